"""Which YADE runs: Debian's python3.11 with a flavour's module directory (double, long-double, float128, mpfr150),
never the yade launcher, which opens network servers; and its version."""
import os
import re
from functools import lru_cache

from ...infra.errors import UserError
from ...infra.programs import from_variable, which

PYTHON_VARIABLE = "HARNESS_YADE_PYTHON"    # another interpreter (a test's fake); default Debian's python3.11
FLAVOURS = {"double": "yade-double", "long-double": "yade-longdouble", "float128": "yade-float128",
            "mpfr150": "yade-mpfr150"}
ARITHMETIC = {"double": "double (IEEE 754 binary64)", "long-double": "long double (x87 80-bit extended)",
              "float128": "float128 (IEEE 754 binary128)", "mpfr150": "MPFR, 150 decimal digits"}
LIBRARY = "/usr/lib/x86_64-linux-gnu"


def python():
    return from_variable(PYTHON_VARIABLE, "/usr/bin/python3.11")


def flavour_path(precision):
    if precision not in FLAVOURS:
        raise UserError(f"precision must be one of {', '.join(FLAVOURS)}, got {precision!r}")
    return os.path.join(LIBRARY, FLAVOURS[precision], "py")


def available(precision="double"):
    """Debian's python3.11 and the flavour's module directory are both there."""
    return which(python()) is not None and os.path.isdir(flavour_path(precision))


def version():
    return _version(LIBRARY)


@lru_cache(maxsize=None)
def _version(library):
    """'2023.02a' from the Debian package's changelog path, else 'unknown'."""
    try:
        names = os.listdir("/usr/share/doc/yade")
    except OSError:
        names = []
    for name in ("changelog.Debian.gz",):
        if name in names:
            import gzip
            with gzip.open(os.path.join("/usr/share/doc/yade", name), "rt") as handle:
                match = re.search(r"\(([0-9.a-z]+)-", handle.readline())
                if match:
                    return match.group(1)
    return "unknown"


def environment(precision):
    return {**os.environ, "PYTHONPATH": flavour_path(precision), "OMP_NUM_THREADS": "1"}




def missing_reason(precision="double"):
    """What was looked for, and where, when YADE cannot run."""
    if which(python()) is None:
        where = (f"{PYTHON_VARIABLE}={os.environ[PYTHON_VARIABLE]!r}" if PYTHON_VARIABLE in os.environ else
                 "/usr/bin/python3.11")
        return f"no Python interpreter at {where} (YADE runs as a module of Debian's python3.11)"
    return (f"no YADE {precision} module directory {flavour_path(precision)} "
            "(apt-get install -y yade, or bash tools/setup.sh)")
