"""An engine's executable: which one runs (an absolute path or a name in its environment variable, else its name on
PATH, never a file relative to the working directory), whether it is there, what was looked for when it is not, and
the head of what it prints for `-h` (read in a temporary directory, where the binary's own log files land, never in
the user's)."""
import os

from ..infra.programs import from_variable, which
from .runner import EngineFailure, run_engine, scratch

BANNER_TIMEOUT_S = 5.0          # the banner comes in well under a second; a hung binary costs no more


def chosen(variable, name):
    return from_variable(variable, name) if variable else name


def present(variable, name):
    return which(chosen(variable, name)) is not None


def missing(variable, name, package):
    """What was looked for, and where, when the binary is not there."""
    if variable in os.environ:
        return f"{variable}={os.environ[variable]!r} is not an executable file"
    return f"no `{name}` on PATH (apt-get install -y {package}, or bash tools/setup.sh)"


def banner(path, engine):
    """The first 20000 characters `path -h` prints ('' if it prints nothing or cannot run)."""
    with scratch(f"{engine}-version") as workdir:
        try:
            run_engine([path, "-h"], workdir, BANNER_TIMEOUT_S)
        except EngineFailure:
            pass
        try:
            with open(os.path.join(workdir, "engine.log"), errors="replace") as handle:
                return handle.read(20000)
        except OSError:
            return ""
