"""Figures drawn side by side: matplotlib holds one core per figure, so a page's figures are drawn in forked worker
processes, one per core (each gets its data pickled and returns its SVG). The workers die with harness, however it
ends: killed on an interrupt, and by Linux's parent-death signal when harness itself is killed."""
import ctypes
import multiprocessing
import os
import signal
from concurrent.futures import ProcessPoolExecutor

from ..infra.cores import CORES

PR_SET_PDEATHSIG = 1            # prctl(2): the signal this process gets when the thread that forked it ends


def die_with(parent):
    """Worker initializer: SIGKILL when `parent` ends (even by SIGKILL), and an exit at once if it already has."""
    try:
        ctypes.CDLL(None, use_errno=True).prctl(PR_SET_PDEATHSIG, signal.SIGKILL)
    except (OSError, AttributeError):              # not Linux: the workers then end with the pool's pipes
        pass
    if os.getppid() != parent:
        os._exit(1)


def draw_all(calls):
    """[function(*args) for function, args in calls], drawn in parallel where the machine has cores to spare."""
    if len(calls) < 2 or CORES < 2 or "fork" not in multiprocessing.get_all_start_methods():
        return [function(*args) for function, args in calls]
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot  # noqa: F401  (loaded once here, inherited by the workers)
    pool = ProcessPoolExecutor(max_workers=min(CORES, len(calls)), mp_context=multiprocessing.get_context("fork"),
                               initializer=die_with, initargs=(os.getpid(),))
    try:
        futures = [pool.submit(function, *args) for function, args in calls]
        drawn = [future.result() for future in futures]
    except BaseException:                           # interrupted: the figures being drawn are not waited for
        stop(pool)
        raise
    pool.shutdown()
    return drawn


def stop(pool):
    """Kill the pool's workers and shut it down without waiting (the pool has no public way before Python 3.14)."""
    if hasattr(pool, "terminate_workers"):
        pool.terminate_workers()
        return
    for process in list((getattr(pool, "_processes", None) or {}).values()):
        process.kill()
    pool.shutdown(wait=False, cancel_futures=True)
