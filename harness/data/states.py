"""The states table (states.csv): each impact's state at the times the scene names, one row per impact and time,
with the results table's key columns (docs/results.md#states)."""
import numpy as np
import pandas as pd

KEY = ("engine", "engine_version", "dialect", "e_n_target", "theta_deg", "v_n0", "v_t0", "omega0")
STATE = ("t", "overlap", "f_n", "f_t", "v_n", "v_t", "omega")
COLUMNS = KEY + STATE
NUMBERS = KEY[3:] + STATE


def states_frame(results, states):
    """Rows of one run's states, an array (impacts, times, 7) in STATE's columns, beside its results rows (one per
    impact, in the same order), whose key columns they take."""
    states = np.asarray(states, dtype=float)
    impacts, times = states.shape[:2]
    if impacts != len(results):
        raise ValueError(f"{impacts} impacts of states for {len(results)} result rows")
    keys = {name: np.repeat(results[name].to_numpy(), times) for name in KEY}
    values = {name: states[:, :, j].reshape(-1) for j, name in enumerate(STATE)}
    return pd.DataFrame({**keys, **values}, columns=list(COLUMNS))


class Carried:
    """A states table in a results frame's attrs['states'], compared by identity (pandas compares the attrs of the
    frames it joins, and a table has no truth value)."""

    def __init__(self, table):
        self.table = table


def attach(frame, table):
    """`frame` carrying its run's states table (None: none)."""
    if table is not None:
        frame.attrs["states"] = Carried(table)
    return frame


def carried(frame):
    """The states table a results frame carries, or None."""
    held = frame.attrs.get("states") if frame is not None else None
    return held.table if held is not None else None


def gather(frames):
    """The states tables the results frames carry, as one table, or None if none carries one."""
    parts = [table for table in map(carried, frames) if table is not None]
    return pd.concat(parts, ignore_index=True) if parts else None
