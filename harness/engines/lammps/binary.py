"""Which LAMMPS binary runs, whether it is there, and its version (read from its help text in a temporary
directory, never in the user's)."""
import os
import re
import shutil
from functools import lru_cache

from ..runner import EngineFailure, run_engine, scratch

BINARY_VARIABLE = "HARNESS_LAMMPS"      # path of another lmp binary (a custom build, or a test's fake)
VERSION_TIMEOUT_S = 5.0


def binary():
    return os.environ.get(BINARY_VARIABLE, "lmp")


def available():
    return shutil.which(binary()) is not None


def missing_reason():
    """What was looked for, and where, when the binary is not there."""
    if BINARY_VARIABLE in os.environ:
        return f"{BINARY_VARIABLE}={os.environ[BINARY_VARIABLE]!r} is not an executable file"
    return "no `lmp` on PATH (apt-get install -y lammps, or bash tools/setup.sh)"


def version():
    return _version(binary())


@lru_cache(maxsize=None)
def _version(path):
    """'29Sep2021_update2' (the stable release's own spelling) from the banner of `lmp -h`, '29 Sep 2021 - Update 2'."""
    with scratch("lammps-version") as workdir:
        try:
            run_engine([path, "-h"], workdir, VERSION_TIMEOUT_S)
        except EngineFailure:
            pass
        try:
            with open(os.path.join(workdir, "engine.log"), errors="replace") as handle:
                log = handle.read(20000)
        except OSError:
            log = ""
    match = re.search(r"Simulator - ([0-9]+) ([A-Za-z]+) ([0-9]+)(?: - Update ([0-9]+))?\s*$", log, re.MULTILINE)
    if not match:
        return "unknown"
    day, month, year, update = match.groups()
    return f"{day}{month}{year}" + (f"_update{update}" if update else "")
