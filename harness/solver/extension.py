"""Normal kernels registered at run time (submodels.registry.register_normal): the integrators carry a table of
their compiled functions and call through it for the codes beyond the generated dispatch, so that nothing compiled
needs compiling again. A slot without a kernel answers NaN: a missing kernel shows as a non-finite result."""
import math
import warnings

from numba import njit, types
from numba.core.errors import NumbaExperimentalFeatureWarning

warnings.filterwarnings("ignore", category=NumbaExperimentalFeatureWarning)

FORCE, BELOW, SLOPE, RESIDUAL, KINK = 0, 1, 2, 3, 4     # what a kernel's `extension` answers, by `point`
SIGNATURE = types.UniTuple(types.float64, 2)(types.int64, types.float64[:], *([types.float64] * 5))


@njit(SIGNATURE, cache=True)
def missing(point, slots, radius, alpha, alpha_max, x, y):
    """An empty slot: NaN, so that a missing kernel ends as a non-finite row, never as another law."""
    return math.nan, math.nan


@njit(cache=True, inline="always")
def call(ext, slot, point, slots, radius, alpha, alpha_max, x, y):
    """ext[slot](point, ...), `slots` the normal family's block of the kernel row (the kernel's SLOTS first):
    (force, contact radius) for FORCE, (dF/dalpha, d ln a/dalpha) for SLOPE with x, y = F, a and alpha_max = 1
    while loading; the first of the pair for BELOW (F at alpha <= 0), RESIDUAL, KINK."""
    if slot < len(ext):
        return ext[slot](point, slots, radius, alpha, alpha_max, x, y)
    return math.nan, math.nan


def table():
    """The extension table of the registered kernels (each module's `extension`, compiled with SIGNATURE), padded
    with `missing` to the registry's slots."""
    import importlib
    from ..submodels.registry import EXTENSION_SLOTS, EXTENSIONS
    functions = [importlib.import_module(k.module).extension for k in EXTENSIONS]
    return tuple(functions + [missing] * (EXTENSION_SLOTS - len(functions)))
