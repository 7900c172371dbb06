"""A results directory as data first: results.csv plus the other tables a comparison produced, saved as files; the
HTML report is always rebuilt from those files, so `harness report DIR` simulates nothing."""
import json
import os
from dataclasses import asdict

import numpy as np
import pandas as pd

from .comparison import agreement, deviation, findings
from .engines.sweep import FailedRun
from .errors import UserError
from .report import records
from .results import read_csv

RUN, ATTRIBUTION, HISTORIES, FAILURES, PRECISION = ("run.json", "attribution.csv", "histories.csv", "failures.csv",
                                                    "precision.csv")
SLIDING = "sliding.csv"
COST, COST_RUN, COST_TRUTH = "cost.csv", "cost.json", "cost-truth.csv"


def save_extras(out_dir, law_name, overrides, scene, skipped, attributions, failures, precision, histories,
                engine_options=None, sliding=None):
    """Write everything beyond results.csv that the report shows."""
    scene_fields = {k: v for k, v in asdict(scene).items() if k != "extra"}
    with open(os.path.join(out_dir, RUN), "w") as handle:
        json.dump({"model": law_name, "overrides": overrides, "scene": scene_fields, "skipped": skipped,
                   "engine_options": engine_options or {}}, handle, indent=1)
    tables = [table.assign(comparison=name) for name, table in attributions.items()]
    pd.concat(tables, ignore_index=True).to_csv(os.path.join(out_dir, ATTRIBUTION), index=False) if tables else \
        _remove(out_dir, ATTRIBUTION)
    rows = [pd.DataFrame(h[0][~np.isnan(h[0][:, 0])], columns=["t", "overlap", "f_n", "f_t"]).assign(e_n_target=e)
            for e, h in (histories or {}).items()]
    pd.concat(rows, ignore_index=True).to_csv(os.path.join(out_dir, HISTORIES), index=False) if rows else \
        _remove(out_dir, HISTORIES)
    pd.DataFrame([vars(f) for f in failures], columns=["engine", "e_n", "message", "log_tail"]).to_csv(
        os.path.join(out_dir, FAILURES), index=False)
    pd.DataFrame([precision] if precision else []).to_csv(os.path.join(out_dir, PRECISION), index=False)
    (sliding if sliding is not None else pd.DataFrame()).to_csv(os.path.join(out_dir, SLIDING), index=False)


def _remove(out_dir, name):
    path = os.path.join(out_dir, name)
    if os.path.exists(path):
        os.remove(path)


def _read(out_dir, name):
    path = os.path.join(out_dir, name)
    if not os.path.exists(path) or os.path.getsize(path) <= 1:
        return pd.DataFrame()
    try:
        return pd.read_csv(path)
    except pd.errors.EmptyDataError:
        return pd.DataFrame()


def rebuild(out_dir):
    """Write DIR/report.html from the files in DIR alone (a compare run, a cost run or both); returns its path."""
    from .report import write_report
    has_compare = os.path.exists(os.path.join(out_dir, RUN))
    has_cost = os.path.exists(os.path.join(out_dir, COST_RUN))
    if not os.path.isdir(out_dir) or not (has_compare or has_cost):
        raise UserError(f"{out_dir} is not a results directory of `harness compare` or `harness cost` "
                        f"(no {RUN} or {COST_RUN})")
    return write_report(out_dir, compare=compare_part(out_dir) if has_compare else None,
                        cost=cost_part(out_dir) if has_cost else None)


def compare_part(out_dir):
    """Everything the compare sections of the report show, read from DIR."""
    from .laws import compose
    from .scene import Scene
    frame = read_csv(os.path.join(out_dir, "results.csv"))
    with open(os.path.join(out_dir, RUN)) as handle:
        run = json.load(handle)
    scene = Scene(**{k: tuple(v) if isinstance(v, list) else v for k, v in run["scene"].items()})
    law = compose(run["model"], run["overrides"])
    ran = [e for e in frame.engine.unique() if e != "reference"]
    agree = pd.concat([agreement(frame, e) for e in ran], ignore_index=True) if ran else None
    devs = pd.concat([deviation(frame, e, e) for e in ran], ignore_index=True) if ran else None
    cross = deviation(frame, ran[1], ran[1], against=(ran[0], ran[0])) if len(ran) == 2 else None
    attribution_table = _read(out_dir, ATTRIBUTION)
    attributions = {name: table.drop(columns="comparison").dropna(axis=1, how="all")
                    for name, table in attribution_table.groupby("comparison", sort=False)} \
        if not attribution_table.empty else {}
    history_table = _read(out_dir, HISTORIES)
    histories = {e: group[["t", "overlap", "f_n", "f_t"]].to_numpy()[None, :, :]
                 for e, group in history_table.groupby("e_n_target", sort=False)} if not history_table.empty else None
    failure_table = _read(out_dir, FAILURES)
    failures = [FailedRun(r.engine, r.e_n, r.message, "" if pd.isna(r.log_tail) else r.log_tail)
                for r in failure_table.itertuples()] if not failure_table.empty else []
    precision = _read(out_dir, PRECISION)
    sliding = _read(out_dir, SLIDING)
    return dict(frame=frame, law=law, scene=scene, skipped=[tuple(s) for s in run["skipped"]], sliding=sliding,
                agreement=agree, deviation=devs, cross=cross, attributions=attributions,
                findings=findings(frame), failures=failures,
                precision=precision if not precision.empty else None, histories=histories,
                arithmetic=arithmetic(run.get("engine_options", {})))


def cost_part(out_dir):
    """The cost section: cost.csv, the truth uncertainties and cost.json."""
    from .cost_report import cost_section
    with open(os.path.join(out_dir, COST_RUN)) as handle:
        run = json.load(handle)
    cost = pd.read_csv(os.path.join(out_dir, COST), dtype={"rung": str, "message": str})
    section = cost_section(cost, run["model"])
    uncertainty = _read(out_dir, COST_TRUTH)
    section.update(model=run["model"], skipped=[tuple(s) for s in run["skipped"]], failures=run.get("failures", []),
                   scene=run["scene"],
                   uncertainty=records(uncertainty) if not uncertainty.empty else None)
    return section


def arithmetic(engine_options):
    """The floating-point arithmetic of each engine's run, from the options it ran with."""
    from .engines.yade import ARITHMETIC
    yade = engine_options.get("yade", {}).get("precision", "double")
    return {"reference": ARITHMETIC["double"], "liggghts": ARITHMETIC["double"], "yade": ARITHMETIC[yade]}
