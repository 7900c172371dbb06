"""Figures drawn side by side: matplotlib holds one core per figure, so a page's figures are drawn in forked worker
processes, one per core (each gets its data pickled and returns its SVG)."""
import multiprocessing
from concurrent.futures import ProcessPoolExecutor

from ..solver.threads import THREADS


def draw_all(calls):
    """[function(*args) for function, args in calls], drawn in parallel where the machine has cores to spare."""
    if len(calls) < 2 or THREADS < 2 or "fork" not in multiprocessing.get_all_start_methods():
        return [function(*args) for function, args in calls]
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot  # noqa: F401  (loaded once here, inherited by the workers)
    with ProcessPoolExecutor(max_workers=min(THREADS, len(calls)),
                             mp_context=multiprocessing.get_context("fork")) as pool:
        futures = [pool.submit(function, *args) for function, args in calls]
        return [future.result() for future in futures]
