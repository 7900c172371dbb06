"""Executing a plan: each run through its engine, in the plan's order, each frame handed on as it is done (so that a
caller keeps whatever is finished); one tidy results table and the failed runs."""
import pandas as pd

from .engines import ENGINES
from .results import COLUMNS


def execute(runs, on_frame=None):
    """(results table, failed runs) of the runs; on_frame(frame) after each."""
    frames, failures = [], []
    for run in runs:
        frame, failure = ENGINES[run.engine].run([run])[0]
        frames.append(frame)
        if failure is not None:
            failures.append(failure)
        if on_frame is not None:
            on_frame(frame)
    table = pd.concat(frames, ignore_index=True) if frames else pd.DataFrame(columns=list(COLUMNS))
    return table, failures
