"""Whether a compiled integrator must be compiled before it runs, so that a first run says so, once, on the log; and
the time compiling takes, counted (harness.infra.compiling) from numba's compile events."""
import logging
import os
import threading
import time

from numba.core import event

from ..infra.compiling import add, first_clock

LOG = logging.getLogger("harness")
_announced = set()
TYPICAL_COMPILE_S = (5, 15)     # one integrator of one law: quiet, and 2 cores shared by 4 jobs (docs/performance.md)


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
        low, high = TYPICAL_COMPILE_S
        LOG.info("compiling %s for this machine (first use only, typically %d to %d s a law; later runs load it "
                 "from numba's cache; `harness compile` compiles every law ahead of time)", what, low, high)


class CompileClock(event.Listener):
    """Adds the wall time of each outermost compile (a compile nests the compiles of the functions it calls) to
    harness.infra.compiling."""

    def __init__(self):
        self.depth, self.start, self.lock = 0, 0.0, threading.Lock()

    def on_start(self, _):
        with self.lock:
            if self.depth == 0:
                self.start = time.perf_counter()
            self.depth += 1

    def on_end(self, _):
        with self.lock:
            self.depth -= 1
            if self.depth == 0:
                add(time.perf_counter() - self.start)


_clock = CompileClock()
if first_clock(_clock):
    event.register("numba:compile", _clock)
