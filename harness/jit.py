"""How the compiled kernels are compiled: cached on disk, in a cache of their own code, and, for a function that
allocates no array, without reference counting.

numba checks a cached function against its own file only, while a compiled function carries the code of every
function it calls: so the cache is a directory named by a digest of all compiled sources (under NUMBA_CACHE_DIR if
set, else the user's cache directory), and changed code is never served from an older cache. A function decorated
`compiled` borrows every array it is given from its caller, which owns it: counting the references of array arguments
took three quarters of a step's time (an atomic increment and decrement per array per call), and leaving them out
changes no result (docs/performance.md#compiled-kernels). It is called from compiled code only, so it is built
without the wrappers that let Python (or a first-class function pointer) call it, which were an eighth of the first
run's compile time: Python reaches one through `python_twin`. This module is imported before anything is compiled."""
import os

from numba import config, njit

from .sources import source_digest

COMPILED_SOURCES = ("solver", "submodels")


def cache_base():
    """Where numba's caches of harness live: NUMBA_CACHE_DIR, else $XDG_CACHE_HOME/harness/numba (~/.cache)."""
    if os.environ.get("NUMBA_CACHE_DIR"):
        return os.environ["NUMBA_CACHE_DIR"]
    return os.path.join(os.environ.get("XDG_CACHE_HOME") or os.path.expanduser("~/.cache"), "harness", "numba")


config.CACHE_DIR = os.path.join(cache_base(), source_digest(*COMPILED_SOURCES, "jit.py"))

compiled = njit(cache=True, _nrt=False, no_cfunc_wrapper=True, no_cpython_wrapper=True)


def python_twin(function):
    """A `compiled` function compiled apart, uncached, with the wrapper Python calls it through (the original has
    none: calling it from Python would jump to a null address)."""
    return njit(_nrt=False)(function.py_func)
