"""The version of harness and the date it was released, in one place (the package, its metadata, CITATION.cff and
every results row read it)."""
__version__ = "0.1.0"
RELEASED = "2026-11-23"
