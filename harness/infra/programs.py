"""Where harness finds the programs it runs (engines, their interpreters, sbatch, setpriv): never in the working
directory. PATH is searched in its absolute entries alone (an empty entry means the working directory, a relative
one a folder in it), and a path harness is told in an environment variable must be absolute."""
import os
import shutil
from contextlib import contextmanager

from .errors import UserError


def search_path(path=None):
    """PATH (or `path`) without its empty and relative entries."""
    entries = (os.environ.get("PATH", os.defpath) if path is None else path).split(os.pathsep)
    return os.pathsep.join(entry for entry in entries if os.path.isabs(entry))


@contextmanager
def absolute_path():
    """PATH without its empty and relative entries while the block runs, for the programs the libraries harness
    calls run by name (matplotlib's fc-list, dask-jobqueue's); PATH as it was afterwards."""
    before = os.environ.get("PATH")
    os.environ["PATH"] = search_path()
    try:
        yield
    finally:
        if before is None:
            os.environ.pop("PATH", None)
        else:
            os.environ["PATH"] = before


def which(program):
    """The absolute path of the executable file `program` names: an absolute path as it is, a bare name on PATH's
    absolute entries; None for anything else (a relative path is never run)."""
    if not program:
        return None
    if os.sep in program:
        here = os.path.isabs(program) and os.path.isfile(program) and os.access(program, os.X_OK)
        return program if here else None
    found = shutil.which(program, path=search_path())
    return os.path.abspath(found) if found else None


def from_variable(variable, default):
    """The program an environment variable names (`default` when it is unset): an absolute path or a bare name to
    look up on PATH; an empty value or a relative path is refused (UserError), since it would name a file in
    whatever directory harness is started from."""
    value = os.environ.get(variable)
    if value is None:
        return default
    if not value or (os.sep in value and not os.path.isabs(value)):
        raise UserError(f"{variable}={value!r} must be an absolute path or a program name on PATH (harness runs "
                        "nothing found relative to the working directory)")
    return value


def directory_from(variable, default):
    """The directory an environment variable names (`default` when it is unset): absolute, or refused (UserError)
    when empty or relative."""
    value = os.environ.get(variable)
    if value is None:
        return default
    if not os.path.isabs(value):
        raise UserError(f"{variable}={value!r} must be an absolute directory (harness searches nothing relative to "
                        "the working directory)")
    return value
