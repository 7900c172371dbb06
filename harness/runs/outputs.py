"""A results directory as data first: results.csv plus the other tables a comparison produced, saved as files; the
HTML report is always rebuilt from those files, so `harness report DIR` simulates nothing."""
import json
import os
from dataclasses import asdict

import numpy as np
import pandas as pd

from ..analyses.attribution import KEPT as ATTRIBUTION_KEPT, METRICS as ATTRIBUTED
from ..analyses.cost import COLUMNS as COST_COLUMNS, METRICS as COST_METRICS
from ..analyses.physics import Tolerances
from .comparison import Comparison
from ..engines import ENGINES
from ..engines.batches import FailedRun
from ..infra.errors import UserError
from ..infra.files import write_text
from ..laws import compose
from ..infra.reading import read_table
from ..data.records import COST_FIELDS, RUN_FIELDS, load_record
from ..data.results import read_csv, write_csv
from ..data.states import COLUMNS as STATE_COLUMNS, NUMBERS as STATE_NUMBERS
from ..scenes.scene import scene_of_record
from ..infra import strict_json

RUN, ATTRIBUTION, HISTORIES, FAILURES, PRECISION = ("run.json", "attribution.csv", "histories.csv", "failures.csv",
                                                    "precision.csv")
SLIDING, ATTRIBUTION_ROWS, STATES = "sliding.csv", "attribution-rows.csv", "states.csv"
COST, COST_RUN, COST_TRUTH = "cost.csv", "cost.json", "cost-truth.csv"
COST_TEXT = ("model", "engine", "dialect", "rung", "timing", "status", "message")
REPORT, RESULTS = "report.html", "results.csv"
DIRECTORY_FILES = (RESULTS, RUN, ATTRIBUTION, ATTRIBUTION_ROWS, HISTORIES, FAILURES, PRECISION, SLIDING, STATES, COST,
                   COST_RUN, COST_TRUTH, REPORT)


def start_comparison(out_dir, comparison):
    """Before the runs: DIR/run.json describes the compare now running, marked partial, and the tables of an earlier
    compare are removed, so DIR never mixes two runs; an interrupted compare leaves a partial run `report` can show."""
    for name in (ATTRIBUTION, ATTRIBUTION_ROWS, HISTORIES, FAILURES, PRECISION, SLIDING, STATES, RESULTS):
        _remove(out_dir, name)
    _write_run(out_dir, comparison, partial=True)


def _write_run(out_dir, comparison, partial):
    scene_fields = {k: v for k, v in asdict(comparison.scene).items() if k != "extra"}
    write_text(os.path.join(out_dir, RUN), json.dumps(
        {"model": comparison.law.name, "overrides": comparison.overrides, "scene": scene_fields,
         "skipped": comparison.skipped, "engine_options": comparison.engine_options,
         "arithmetic": comparison.arithmetic, "builds": comparison.builds, "engine_inputs": comparison.engine_inputs,
         "requested": comparison.requested, "command": comparison.command, "date": comparison.date,
         "tolerances": comparison.tolerances.as_dict(), "partial": partial,
         "attributions": list(comparison.attribution)}, indent=1))


def save_comparison(out_dir, comparison):
    """Write everything beyond results.csv that the report shows (results.csv is written as the runs finish)."""
    _write_run(out_dir, comparison, partial=False)
    tables = [table.assign(comparison=name) for name, table in comparison.attribution.items()]
    _table(out_dir, ATTRIBUTION, pd.concat(tables, ignore_index=True) if tables else None)
    rows = [table.assign(engine=name) for name, table in comparison.attribution_rows.items()]
    _table(out_dir, ATTRIBUTION_ROWS, pd.concat(rows, ignore_index=True) if rows else None)
    rows = [pd.DataFrame(h[0][~np.isnan(h[0][:, 0])], columns=["t", "overlap", "f_n", "f_t"]).assign(e_n_target=e)
            for e, h in (comparison.histories or {}).items()]
    _table(out_dir, HISTORIES, pd.concat(rows, ignore_index=True) if rows else None)
    _table(out_dir, FAILURES, pd.DataFrame([vars(f) for f in comparison.failures],
                                           columns=["engine", "e_n", "message", "log_tail"]))
    _table(out_dir, PRECISION, pd.DataFrame([comparison.precision] if comparison.precision else []))
    _table(out_dir, SLIDING, comparison.sliding if comparison.sliding is not None else pd.DataFrame())
    _table(out_dir, STATES, comparison.states)


def _table(out_dir, name, frame):
    """DIR/name from `frame`, written whole; None removes a stale one."""
    if frame is None:
        _remove(out_dir, name)
    else:
        write_text(os.path.join(out_dir, name), frame.to_csv(index=False))


def _remove(out_dir, name):
    path = os.path.join(out_dir, name)
    if os.path.exists(path):
        os.remove(path)


TABLES = {   # a saved table -> (columns it must hold, its number columns, its text columns)
    ATTRIBUTION: (("ingredient", "dialect", "target", "comparison"), tuple(f"d_{m}" for m in ATTRIBUTED),
                  ("ingredient", "dialect", "target", "switched", "note", "comparison")),
    ATTRIBUTION_ROWS: (("engine", "switched", *ATTRIBUTION_KEPT),
                       [c for c in ATTRIBUTION_KEPT if c not in ("model", "status")],
                       ("engine", "switched", "model", "status")),
    HISTORIES: (("t", "overlap", "f_n", "f_t", "e_n_target"), ("t", "overlap", "f_n", "f_t", "e_n_target"), ()),
    FAILURES: (("engine", "e_n", "message", "log_tail"), ("e_n",), ("engine", "message", "log_tail")),
    PRECISION: (("engine", "against"), ("e_n_target", "dt", "v_n1", "v_t1", "omega1"),
                ("engine", "against", "theta_deg", "failed")),
    SLIDING: (("e_n_target", "simulated"), ("e_n_target", "simulated", "resolution", "derived", "difference"),
              ("model", "formula", "method")),
    STATES: (STATE_COLUMNS, STATE_NUMBERS, ("engine", "engine_version", "dialect")),
    COST: (COST_COLUMNS, [c for c in COST_COLUMNS if c not in COST_TEXT], COST_TEXT),
    COST_TRUTH: (("curve", "e_n_target", "err_max"), ("e_n_target", *(f"err_{m}" for m in COST_METRICS), "err_max"),
                 ("curve", "truth")),
}


def _read(out_dir, name):
    """DIR/name, a table of TABLES, checked; absent: an empty table."""
    try:
        return read_table(os.path.join(out_dir, name), *TABLES[name][:2], "table", TABLES[name][2])
    except FileNotFoundError:
        return pd.DataFrame()


def kinds(out_dir):
    """(has a comparison, has a cost study) in DIR; a user error when it holds neither."""
    has_compare = os.path.lexists(os.path.join(out_dir, RUN))
    has_cost = os.path.lexists(os.path.join(out_dir, COST_RUN))
    if not os.path.isdir(out_dir) or not (has_compare or has_cost):
        raise UserError(f"{out_dir} is not a results directory of `harness compare` or `harness cost` "
                        f"(no {RUN} or {COST_RUN})")
    return has_compare, has_cost


def _scene(out_dir, name, record):
    """The Scene of a run record, or one line saying the record is damaged."""
    try:
        return scene_of_record(record["scene"])
    except (TypeError, ValueError) as exc:
        raise UserError(f"{out_dir}/{name} is damaged or foreign: in its scene, {exc}") from None


def _law(out_dir, record):
    """The law of a run record (its model and replacements), or one line saying the record is damaged."""
    try:
        return compose(record["model"], record.get("overrides") or {})
    except UserError as exc:
        raise UserError(f"{out_dir}/{RUN} is damaged or foreign: {exc}") from None


def load_comparison(out_dir):
    """The Comparison saved in DIR (its analyses follow from the table again)."""
    frame = read_csv(os.path.join(out_dir, RESULTS))
    if frame.empty:
        raise UserError(f"{out_dir}/results.csv holds no results")
    run = load_record(os.path.join(out_dir, RUN), RUN_FIELDS)
    scene = _scene(out_dir, RUN, run)
    law = _law(out_dir, run)
    attribution_table = _read(out_dir, ATTRIBUTION)
    attributions = {name: table.drop(columns="comparison").dropna(axis=1, how="all")
                    for name, table in attribution_table.groupby("comparison", sort=False)} \
        if not attribution_table.empty else {}
    for name in run.get("attributions") or ():      # measured, and no ingredient differs: no row in the table
        attributions.setdefault(name, pd.DataFrame(columns=["ingredient", "dialect", "target"]))
    row_table = _read(out_dir, ATTRIBUTION_ROWS)
    attribution_rows = {name: table.drop(columns="engine") for name, table in row_table.groupby("engine", sort=False)} \
        if not row_table.empty else {}
    history_table = _read(out_dir, HISTORIES)
    histories = {e: group[["t", "overlap", "f_n", "f_t"]].to_numpy()[None, :, :]
                 for e, group in history_table.groupby("e_n_target", sort=False)} if not history_table.empty else None
    failure_table = _read(out_dir, FAILURES)
    failures = [FailedRun(r.engine, r.e_n, r.message, "" if pd.isna(r.log_tail) else r.log_tail)
                for r in failure_table.itertuples()] if not failure_table.empty else []
    precision = _read(out_dir, PRECISION)
    sliding = _read(out_dir, SLIDING)
    states = _read(out_dir, STATES)
    requested = run.get("requested")
    try:
        tolerances = Tolerances.of(run.get("tolerances") or {})
    except UserError as exc:
        raise UserError(f"{out_dir}/{RUN} is damaged or foreign: {exc}") from None
    engine_options = run.get("engine_options", {})
    return Comparison(law, scene, frame, overrides=run.get("overrides") or {}, engine_options=engine_options,
                      arithmetic=run.get("arithmetic") or arithmetic_of(engine_options),
                      builds=run.get("builds") or {}, engine_inputs=run.get("engine_inputs") or {},
                      requested=tuple(requested) if requested else None,
                      skipped=[tuple(s) for s in run.get("skipped", [])], failures=failures, attribution=attributions,
                      attribution_rows=attribution_rows,
                      sliding=sliding if not sliding.empty else None,
                      precision=precision.iloc[0].to_dict() if not precision.empty else None, histories=histories,
                      states=states if not states.empty else None,
                      command=run.get("command", ""), date=run.get("date", ""), partial=bool(run.get("partial")),
                      tolerances=tolerances)


DOUBLE = "double (IEEE 754 binary64)"


def arithmetic_of(engine_options):
    """The floating-point arithmetic each engine runs in with these options (an engine that can change it says so:
    `arithmetic`); a comparison records it, and one read from a record that lacks it gets it from here."""
    return {name: engine.arithmetic(engine_options.get(name, {})) if hasattr(engine, "arithmetic") else DOUBLE
            for name, engine in ENGINES.items()}


def load_cost(out_dir):
    """(cost table, the truth's uncertainty table, cost.json) saved in DIR."""
    run = load_record(os.path.join(out_dir, COST_RUN), COST_FIELDS)
    _scene(out_dir, COST_RUN, run)
    try:
        cost = read_table(os.path.join(out_dir, COST), *TABLES[COST][:2], "cost table", TABLES[COST][2])
    except FileNotFoundError:
        raise UserError(f"cannot read {out_dir}/{COST}: no such file") from None
    if cost.empty and not len(cost.columns):
        raise UserError(f"{out_dir}/{COST} is empty, not a harness cost table")
    return cost, _read(out_dir, COST_TRUTH), run


def save_cost(out_dir, cost, uncertainty, law, scene, overrides, skipped, failures):
    """DIR/cost.csv (per curve, rung and e_n), the truth uncertainties and cost.json (scene, skipped engines); also
    written before the study starts, so `harness report DIR` works on an interrupted one."""
    write_csv(cost, os.path.join(out_dir, COST))
    rows = [{"curve": curve, "e_n_target": e_n, **errs} for curve, per_e in uncertainty.items()
            for e_n, errs in per_e.items()]
    _table(out_dir, COST_TRUTH, pd.DataFrame(rows))
    scene_fields = {k: v for k, v in asdict(scene).items() if k != "extra"}
    write_text(os.path.join(out_dir, COST_RUN), strict_json.dumps(
        {"model": law.name, "overrides": overrides, "scene": scene_fields, "skipped": skipped,
         "failures": [vars(f) for f in failures]}, indent=1))
