"""The states at the scene's times as the terminal and the report show them: each engine's first impacts, not every
row of states.csv."""
from ..data.states import STATE

SHOWN_IMPACTS = 1          # per engine, build and dialect: its first impact (the whole table is states.csv)
SHOWN_COLUMNS = ("engine", "dialect", "e_n_target", "theta_deg") + STATE
FORMATS = {name: "{:.6g}" for name in ("e_n_target", "theta_deg") + STATE}


def first_impacts(states, impacts=SHOWN_IMPACTS):
    """The rows of the first `impacts` impacts (e_n, angle) of each engine build and dialect, in the table's order."""
    if states is None or states.empty:
        return None
    keys = ["engine", "engine_version", "dialect"]
    impact = states.groupby(keys, sort=False)[["e_n_target", "theta_deg"]].transform(
        lambda column: column.ne(column.shift()).cumsum())
    first = (impact.e_n_target <= impacts) & (impact.theta_deg <= impacts)
    return states.loc[first, list(SHOWN_COLUMNS)].reset_index(drop=True)

