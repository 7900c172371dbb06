"""Errors a user can cause: reported as one line, exit code 2."""


class UserError(Exception):
    """Bad input from a user (value, name, file): the CLI prints one line and exits with code 2."""
