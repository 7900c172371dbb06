"""What a campaign swept and each metric against it: the scene parameters whose values differ across the store,
and per parameter the SQL over `harness query`'s views (each metric's mean and range; each engine's deviation from
the paper law) with its result, so that every number the campaign page shows is one query away."""
from dataclasses import dataclass

import pandas as pd

from .query import DEVIATIONS, VIEW

PARAMETERS = {"mu": "friction coefficient mu", "speed": "impact speed [m/s]", "radius": "radius [m]",
              "E": "Young's modulus E [Pa]", "nu": "Poisson's ratio nu", "rho": "density rho [kg/m^3]",
              "omega0": "initial spin [rad/s]", "material": "material", "wall": "wall", "target": "target",
              "steps_per_contact": "steps per contact"}
METRICS = {"e_n": "e_n", "e_t": "e_t", "omega_star": "Omega*"}
DEVIATION_METRICS = {f"d_{m}": f"|{label}(engine) - {label}(paper law)|" for m, label in METRICS.items()}


@dataclass
class Sweep:
    """One swept parameter: its SQL and result per metric (mean, min, max over the other dimensions, per law,
    engine, dialect and e_n) and per deviation (worst over the other dimensions, per law, engine and e_n)."""
    parameter: str
    label: str
    sql: str
    table: pd.DataFrame
    deviation_sql: str
    deviation: pd.DataFrame


def swept(table):
    """The parameters of PARAMETERS that take more than one value in the store's table."""
    return [p for p in PARAMETERS if p in table.columns and table[p].dropna().nunique() > 1]


def metric_sql(parameter):
    """Each metric's mean, min and max per law, engine, dialect, value of `parameter` and e_n."""
    stats = ", ".join(f"avg({m}) AS mean_{m}, min({m}) AS min_{m}, max({m}) AS max_{m}" for m in METRICS)
    return (f"SELECT model, engine, dialect, {parameter}, e_n_target, {stats}, count(*) AS impacts FROM {VIEW} "
            "WHERE status = 'ok' GROUP BY ALL ORDER BY ALL")


def deviation_sql(parameter):
    """Each engine's worst deviation from the paper law per law, value of `parameter` and e_n."""
    worst = ", ".join(f"max({d}) AS worst_{d}" for d in DEVIATION_METRICS)
    return (f"SELECT model, engine, {parameter}, e_n_target, {worst}, count(*) AS impacts FROM {DEVIATIONS} "
            "GROUP BY ALL ORDER BY ALL")


def sweeps(db, table):
    """[Sweep] of every parameter the store's table sweeps, each computed by its SQL over the connection `db`
    (query.connection)."""
    return [Sweep(p, PARAMETERS[p], metric_sql(p), db.sql(metric_sql(p)).df(), deviation_sql(p),
                  db.sql(deviation_sql(p)).df()) for p in swept(table)]
