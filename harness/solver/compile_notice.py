"""Whether a compiled integrator must be compiled before it runs, so that a first run says so, once, on the log."""
import logging
import os

LOG = logging.getLogger("harness")
_announced = set()


def announce_compiling(dispatcher, what):
    """Log once per process that `what` is being compiled, when numba has neither compiled nor cached it."""
    if dispatcher.signatures or what in _announced:
        return
    try:
        cached = os.path.exists(dispatcher._cache._cache_file._index_path)
    except AttributeError:                     # another numba's internals: say nothing rather than guess
        return
    if not cached:
        _announced.add(what)
        LOG.info("compiling %s for this machine (first use only; later runs load it from numba's cache)", what)
