"""Seconds this process has spent compiling kernels (counted by harness.solver.compile_notice from numba's compile
events), so that a progress estimate leaves them out of its rate: a first run compiles in its first steps."""
import threading

_SPENT, _LOCK, _CLOCKS = [0.0], threading.Lock(), []


def spent():
    """Wall seconds spent compiling so far."""
    return _SPENT[0]


def add(seconds):
    """Count `seconds` more of compiling."""
    with _LOCK:
        _SPENT[0] += seconds


def first_clock(clock):
    """Keep `clock` as the process' one compile clock if it has none yet; whether it was kept (every specialised copy
    of the solver imports the module that makes one)."""
    with _LOCK:
        if not _CLOCKS:
            _CLOCKS.append(clock)
        return _CLOCKS[0] is clock
