"""Rows of a batch split between threads: the compiled integrators release the GIL, so threads run them in parallel
without numba's parallel compilation (which multiplies the first run's compile time)."""
import os
from concurrent.futures import ThreadPoolExecutor

import numpy as np

THREADS = len(os.sched_getaffinity(0))     # the cores this process may use
CHUNKS_PER_THREAD = 4
_pool = []                                  # one pool for the process, made on first use


def pool():
    if not _pool:
        _pool.append(ThreadPoolExecutor(max_workers=THREADS, thread_name_prefix="harness-rows"))
    return _pool[0]


def in_threads(kernel, n, *args, threads=None):
    """kernel(first, last, *args) over rows 0..n-1 in contiguous chunks on up to `threads` threads."""
    threads = max(1, min(threads or THREADS, n))
    if n == 0:
        return
    if threads == 1:
        kernel(0, n, *args)
        return
    bounds = np.linspace(0, n, min(n, CHUNKS_PER_THREAD * threads) + 1).astype(np.int64)   # small chunks balance
                                                                                    # grazing rows' longer contacts
    chunks = [pool().submit(kernel, int(a), int(b), *args) for a, b in zip(bounds[:-1], bounds[1:]) if b > a]
    for chunk in chunks:
        chunk.result()
