"""Rows of a batch split between threads: the compiled integrators release the GIL, so threads run them in parallel
without numba's parallel compilation (which multiplies the first run's compile time). The threads are daemons and
the caller only waits for them, so Ctrl-C or SIGTERM stops harness at once, not when a compiled loop returns."""
import queue
import threading
from concurrent.futures import Future

import numpy as np

from ..infra.cores import CORES

THREADS = CORES                             # the cores this process may use
CHUNKS_PER_THREAD = 4
_pool = []                                  # one pool for the process, made on first use


class DaemonPool:
    """submit(fn, *args) -> Future, run by daemon threads (an interrupted process does not wait for them)."""

    def __init__(self, workers):
        self.tasks = queue.SimpleQueue()
        for k in range(workers):
            threading.Thread(target=self.work, name=f"harness-rows-{k}", daemon=True).start()

    def work(self):
        while True:
            fulfil(*self.tasks.get())

    def submit(self, fn, *args):
        future = Future()
        self.tasks.put((future, fn, args))
        return future


def fulfil(future, fn, args):
    """Run fn(*args) into `future` (its result, or the exception it raised)."""
    if future.set_running_or_notify_cancel():
        try:
            future.set_result(fn(*args))
        except BaseException as exc:
            future.set_exception(exc)


def pool():
    if not _pool:
        _pool.append(DaemonPool(THREADS))
    return _pool[0]


def in_threads(kernel, n, *args, threads=None):
    """kernel(first, last, *args) over rows 0..n-1 in contiguous chunks on up to `threads` threads. The kernel is
    compiled (or loaded from numba's cache) here first, by a call over no rows: what compiling imports is imported
    by this thread, not by a worker, where an import could wait on another thread's import lock."""
    threads = max(1, min(threads or THREADS, n))
    if n == 0:
        return
    kernel(0, 0, *args)
    if threads == 1:
        pool().submit(kernel, 0, n, *args).result()
        return
    bounds = np.linspace(0, n, min(n, CHUNKS_PER_THREAD * threads) + 1).astype(np.int64)   # small chunks balance
                                                                                    # grazing rows' longer contacts
    chunks = [pool().submit(kernel, int(a), int(b), *args) for a, b in zip(bounds[:-1], bounds[1:]) if b > a]
    for chunk in chunks:
        chunk.result()
