"""Which LIGGGHTS binary runs, whether it is there, and its version (harness.engines.executable)."""
import re
from functools import lru_cache

from ..executable import BANNER_TIMEOUT_S as VERSION_TIMEOUT_S, banner, chosen, missing, present

BINARY_VARIABLE = "HARNESS_LIGGGHTS"     # path of another liggghts binary (a custom build, or a test's fake)


def binary():
    return chosen(BINARY_VARIABLE, "liggghts")


def available():
    return present(BINARY_VARIABLE, "liggghts")


def missing_reason():
    return missing(BINARY_VARIABLE, "liggghts", "liggghts")


def version():
    return _version(binary())


@lru_cache(maxsize=None)
def _version(path):
    """'3.8.0' from the banner the binary prints."""
    match = re.search(r"LIGGGHTS-PUBLIC ([0-9.]+)", banner(path, "liggghts"))
    return match.group(1) if match else "unknown"


__all__ = ["BINARY_VARIABLE", "VERSION_TIMEOUT_S", "available", "binary", "missing_reason", "version"]
