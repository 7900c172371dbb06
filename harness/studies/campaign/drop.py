"""The option that drops a store's damaged fragments, named alike by a damaged store's refusal and each command's
help."""
DROP = "--drop-damaged"
DROP_HELP = "remove the store's damaged fragments (named when found) so that their tasks rerun"
