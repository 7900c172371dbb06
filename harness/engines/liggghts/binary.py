"""Which LIGGGHTS binary runs, whether it is there, and its version (read in a temporary directory, where the
binary's log.liggghts lands, never in the user's)."""
import os
import re
import shutil
from functools import lru_cache

from ..runner import EngineFailure, run_engine, scratch

BINARY_VARIABLE = "HARNESS_LIGGGHTS"     # path of another liggghts binary (a custom build, or a test's fake)
VERSION_TIMEOUT_S = 5.0                 # the banner comes in well under a second; a hung binary costs no more


def binary():
    return os.environ.get(BINARY_VARIABLE, "liggghts")


def available():
    return shutil.which(binary()) is not None


def missing_reason():
    """What was looked for, and where, when the binary is not there."""
    if BINARY_VARIABLE in os.environ:
        return f"{BINARY_VARIABLE}={os.environ[BINARY_VARIABLE]!r} is not an executable file"
    return "no `liggghts` on PATH (apt-get install -y liggghts, or bash tools/setup.sh)"


def version():
    return _version(binary())


@lru_cache(maxsize=None)
def _version(path):
    """'3.8.0' from the banner the binary prints."""
    with scratch("liggghts-version") as workdir:
        try:
            run_engine([path, "-h"], workdir, VERSION_TIMEOUT_S)
        except EngineFailure:
            pass
        try:
            with open(os.path.join(workdir, "engine.log"), errors="replace") as handle:
                log = handle.read(20000)               # the banner is at the top of the help text
        except OSError:
            log = ""
    match = re.search(r"LIGGGHTS-PUBLIC ([0-9.]+)", log)
    return match.group(1) if match else "unknown"
