"""Which LAMMPS binary runs, whether it is there, and its version (harness.engines.executable)."""
import re
from functools import lru_cache

from ..executable import banner, chosen, missing, present

BINARY_VARIABLE = "HARNESS_LAMMPS"      # path of another lmp binary (a custom build, or a test's fake)


def binary():
    return chosen(BINARY_VARIABLE, "lmp")


def available():
    return present(BINARY_VARIABLE, "lmp")


def missing_reason():
    return missing(BINARY_VARIABLE, "lmp", "lammps")


def version():
    return _version(binary())


@lru_cache(maxsize=None)
def _version(path):
    """'29Sep2021_update2' (the stable release's own spelling) from the banner of `lmp -h`, '29 Sep 2021 - Update 2'."""
    match = re.search(r"Simulator - ([0-9]+) ([A-Za-z]+) ([0-9]+)(?: - Update ([0-9]+))?\s*$", banner(path, "lammps"),
                      re.MULTILINE)
    if not match:
        return "unknown"
    day, month, year, update = match.groups()
    return f"{day}{month}{year}" + (f"_update{update}" if update else "")
