"""Executing a plan: the reference's runs in this thread, each external engine's runs in a worker thread of their
own (engines are processes, so engines run side by side up to the machine's cores, and an engine may share one
process between its runs); each frame handed on as soon as it is done, so that a caller keeps whatever is finished;
one tidy results table in the plan's order, and the failed runs."""
from concurrent.futures import ThreadPoolExecutor, as_completed

import pandas as pd

from .engines import ENGINES
from .engines.runner import allow, kill_all
from .results import COLUMNS
from .solver.threads import THREADS


def execute(runs, on_frame=None):
    """(results table, failed runs) of the runs; on_frame(frame) as each is done."""
    done = run_all(runs, None if on_frame is None else (lambda run, frame, failure: on_frame(frame)))
    frames = [frame for frame, _ in done]
    table = pd.concat(frames, ignore_index=True) if frames else pd.DataFrame(columns=list(COLUMNS))
    return table, [failure for _, failure in done if failure is not None]


def run_all(runs, on_done=None):
    """(frame, failure or None) of each run, in the runs' order; on_done(run, frame, failure) as each is done."""
    allow()
    frames, failures = [None] * len(runs), [None] * len(runs)
    groups = {}
    for i, run in enumerate(runs):
        groups.setdefault(run.engine, []).append(i)

    def done(indices, results):
        for i, (frame, failure) in zip(indices, results):
            frames[i], failures[i] = frame, failure
            if on_done is not None:
                on_done(runs[i], frame, failure)

    external = {name: indices for name, indices in groups.items() if name != "reference"}
    with ThreadPoolExecutor(max_workers=max(1, min(THREADS, len(external)))) as pool:
        try:
            pending = {pool.submit(ENGINES[name].run, [runs[i] for i in indices]): indices
                       for name, indices in external.items()}
            for i in groups.get("reference", []):
                done([i], ENGINES["reference"].run([runs[i]]))
            for future in as_completed(pending):
                done(pending[future], future.result())
        except BaseException:
            kill_all()                  # before the pool waits for its threads: their engine processes end now
            raise
    return list(zip(frames, failures))
