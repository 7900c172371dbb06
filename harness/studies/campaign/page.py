"""Everything the campaign page shows, data first: each table as the SQL over `harness query`'s views that prints
it and its result (the sweeps, the agreement with the formulas, the e_n x angle maps of the deviation from the
paper law), read from the store in one connection."""
from dataclasses import dataclass, field

import pandas as pd

from . import page_views
from .query import connection
from .sweeps import sweeps


@dataclass
class Shown:
    """One table of the page: its title, the SQL that prints it, and its result."""
    title: str
    sql: str
    frame: pd.DataFrame


@dataclass
class PageData:
    """The sweeps (campaign.sweeps), the agreement table, one deviation map per engine and law, the failed tasks."""
    sweeps: list = field(default_factory=list)
    agreement: Shown = None
    maps: list = field(default_factory=list)
    failures: Shown = None


def page_data(store, table):
    """The PageData of a store and its table (Store.table())."""
    if table.empty:
        return PageData()
    db = connection(store)
    try:
        agreement = Shown("agreement", page_views.agreement_sql(), db.sql(page_views.agreement_sql()).df())
        maps = []
        for engine, law, angles in db.sql(page_views.maps_sql()).fetchall():
            sql = page_views.map_sql(engine, law, angles)
            maps.append(Shown(f"{engine}, {law}", sql, db.sql(sql).df()))
        failures = Shown("failed tasks", page_views.failures_sql(), db.sql(page_views.failures_sql()).df())
        return PageData(sweeps(db, table), agreement, maps, failures)
    finally:
        db.close()
