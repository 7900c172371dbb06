"""How the compiled kernels are compiled: cached on disk, in a cache of their own code, and, for a function that
allocates no array, without reference counting.

numba checks a cached function against its own file only, while a compiled function carries the code of every
function it calls: so the cache is a directory named by a digest of all compiled sources (under NUMBA_CACHE_DIR if
set, else the user's cache directory), and changed code is never served from an older cache. A function decorated
`compiled` borrows every array it is given from its caller, which owns it: counting the references of array arguments
took three quarters of a step's time (an atomic increment and decrement per array per call), and leaving them out
changes no result (docs/performance.md#compiled-kernels). It is called from compiled code only, so it is built
without the wrappers that let Python (or a first-class function pointer) call it, which were an eighth of the first
run's compile time: Python reaches one through `python_twin`, and a Python call of the function itself raises a
TypeError that says so. This module is imported before anything is compiled."""
import os

from numba import config, njit
from numba.core.registry import CPUDispatcher

from .sources import source_digest

COMPILED_SOURCES = ("solver", "submodels")


def cache_base():
    """Where numba's caches of harness live: NUMBA_CACHE_DIR, else $XDG_CACHE_HOME/harness/numba (~/.cache)."""
    if os.environ.get("NUMBA_CACHE_DIR"):
        return os.environ["NUMBA_CACHE_DIR"]
    return os.path.join(os.environ.get("XDG_CACHE_HOME") or os.path.expanduser("~/.cache"), "harness", "numba")


config.CACHE_DIR = os.path.join(cache_base(), source_digest(*COMPILED_SOURCES, "infra/jit.py"))

COMPILED_OPTIONS = {"nopython": True, "boundscheck": None, "_nrt": False, "no_cfunc_wrapper": True,
                    "no_cpython_wrapper": True}


class CompiledOnly(CPUDispatcher):
    """A compiled function that only compiled code calls: called from Python, it raises (it has no wrapper to be
    called through)."""

    def __call__(self, *args, **kwargs):
        name = self.py_func.__name__
        raise TypeError(f"{name} is compiled for compiled callers only (no Python wrapper); from Python call "
                        f"harness.infra.jit.python_twin({name})")


def compiled(function):
    """`function` compiled without reference counting nor Python wrapper, cached on disk (CompiledOnly)."""
    dispatcher = CompiledOnly(py_func=function, locals={}, targetoptions=dict(COMPILED_OPTIONS))
    dispatcher.enable_caching()
    return dispatcher


def python_twin(function):
    """A `compiled` function compiled apart, uncached, with the wrapper Python calls it through (the original has
    none: calling it from Python would jump to a null address)."""
    return njit(_nrt=False)(function.py_func)
