"""Executing a plan: the reference's runs in this thread, each external engine's runs in a worker thread of their
own (engines are processes, so engines run side by side up to the machine's cores, and an engine may share one
process between its runs); each frame handed on as soon as it is done, so that a caller keeps whatever is finished;
one tidy results table in the plan's order, and the failed runs. What the threads use is imported before they
start (harness.runs.before_threads)."""
from concurrent.futures import ThreadPoolExecutor, as_completed

import pandas as pd

from .before_threads import import_what_threads_use
from ..engines import ENGINES
from ..engines.runner import allow, kill_all
from ..data.results import COLUMNS
from ..data.states import attach, gather
from ..solver.threads import THREADS


def execute(runs, on_frame=None, cache=None):
    """(results table, failed runs) of the runs; on_frame(frame) as each is done; a cache (get(run), put(run,
    frame): harness.runs.partial, a campaign store) serves the runs it holds and keeps the others as they finish."""
    done = run_all(runs, None if on_frame is None else (lambda run, frame, failure: on_frame(frame)), cache)
    frames = [frame for frame, _ in done]
    table = pd.concat(frames, ignore_index=True) if frames else pd.DataFrame(columns=list(COLUMNS))
    return attach(table, gather(frames)), [failure for _, failure in done if failure is not None]


def run_all(runs, on_done=None, cache=None, meanwhile=None):
    """(frame, failure or None) of each run, in the runs' order; on_done(run, frame, failure) as each is done; runs
    the cache holds are taken from it, and each run that succeeds is put there. meanwhile() runs in this thread
    after the reference's runs, while the engines' threads run theirs."""
    allow()
    import_what_threads_use()
    frames, failures = [None] * len(runs), [None] * len(runs)
    held = {i: frame for i, run in enumerate(runs) if cache is not None for frame in [cache.get(run)]
            if frame is not None}
    groups = {}
    for i, run in enumerate(runs):
        if i not in held:
            groups.setdefault(run.engine, []).append(i)

    def done(indices, results, from_cache=False):
        for i, (frame, failure) in zip(indices, results):
            frames[i], failures[i] = frame, failure
            if cache is not None and not from_cache and failure is None:
                cache.put(runs[i], frame)
            if on_done is not None:
                on_done(runs[i], frame, failure)

    done(list(held), [(frame, None) for frame in held.values()], from_cache=True)

    external = {name: indices for name, indices in groups.items() if name != "reference"}
    try:
        with ThreadPoolExecutor(max_workers=max(1, min(THREADS, len(external)))) as pool:
            try:
                pending = {pool.submit(ENGINES[name].run, [runs[i] for i in indices]): indices
                           for name, indices in external.items()}
                for i in groups.get("reference", []):
                    done([i], ENGINES["reference"].run([runs[i]]))
                if meanwhile is not None:
                    meanwhile()
                for future in as_completed(pending):
                    done(pending[future], future.result())
            except BaseException:
                kill_all()              # before the pool waits for its threads: their engine processes end now
                raise
    finally:
        allow()                         # its threads have ended: engines may start again (a caller's next run)
    return list(zip(frames, failures))
