"""Errors a user can cause: reported as one line, exit code 2; from Python, a ValueError (a bad value) or also a
TypeError (a keyword of the wrong type), so that ordinary `except ValueError` / `except TypeError` catch them."""


class UserError(ValueError):
    """Bad input from a user (value, name, file): the CLI prints one line and exits with code 2."""


class UserTypeError(UserError, TypeError):
    """A Python API keyword of the wrong type (e.g. a string where a list of numbers belongs), naming the keyword."""


class EngineMissing(UserError):
    """An engine build asked for by name that is not here (no such version, no binary): one line, exit code 3."""


class NotModelled(UserError):
    """An input that parses but names a model harness has no sub-model for yet: one line, exit code 2."""


def not_modelled(what):
    raise NotModelled(f"not yet modelled: {what}")
