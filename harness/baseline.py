"""Baselines: the expected rebound kinematics of a fixed matrix (every law through the reference and through each
engine that supports it), committed under baselines/ and shipped with the package, and the regression check."""
import os
from importlib.resources import files

import numpy as np
import pandas as pd

from .engines import ENGINES, EXTERNAL
from .errors import UserError
from .execute import execute
from .files import refuse_to_read_unless_regular
from .laws import LAWS, compose
from .plan import engine_plan, reference_runs
from .results import read_csv, write_csv
from .scene import Scene

DEFAULT_BASELINE = str(files("harness") / "baselines")
BASELINE_FILE = "baseline.csv"
MATRIX_EN = (0.9, 0.5, 0.1)
MATRIX_ANGLES = (0.0, 30.0, 60.0)
STEPS_PER_CONTACT = 200
METRICS = ("v_n1", "v_t1", "omega1", "e_n", "e_t", "omega_star", "psi2_star", "t_contact", "f_n_max")
KEYS = ["model", "engine", "dialect", "e_n_target", "theta_deg"]
# relative tolerance (floor 1e-9 of the metric's scale): the reference is deterministic; an engine build may move
TOLERANCE = {"reference": 1e-9, "engine": 1e-6}


def matrix_scene():
    return Scene(e_n=MATRIX_EN, angles_deg=MATRIX_ANGLES)


def compute(progress=None, cache=None):
    """The baseline matrix now: paper law and every engine's dialect on the reference, the engines where installed;
    (frame, skipped)."""
    scene = matrix_scene()
    frames, skipped = [], []
    if progress:
        progress.expect(len(LAWS))
    for name in LAWS:
        law = compose(name)
        plan = reference_runs(law, scene, STEPS_PER_CONTACT)
        for engine_name in EXTERNAL:
            engine = ENGINES[engine_name]
            status = engine.status(name)
            if not engine.supports(name):
                continue
            if status.available:
                plan += engine_plan(engine, law, scene, STEPS_PER_CONTACT)
            else:                           # its dialect needs only the reference solver
                skipped.append(f"{engine_name} {name}: {status.reason}")
                plan += reference_runs(law, scene, STEPS_PER_CONTACT, engine.dialect(name, {}))
        frame, failures = execute(plan, cache=cache)
        frames.append(frame)
        skipped += [f"{f.engine} {name} e_n={f.e_n}: {f.message}" for f in failures]
        if progress:
            progress.advance(name)
    return pd.concat(frames, ignore_index=True), skipped


def update(directory, progress=None):
    """Rewrite DIRECTORY/baseline.csv from a fresh computation."""
    os.makedirs(directory, exist_ok=True)
    frame, skipped = compute(progress)
    write_csv(frame, os.path.join(directory, BASELINE_FILE))
    return frame, skipped


def compare_to_baseline(baseline, now):
    """Rows (model, engine, dialect, e_n, angle, metric, baseline, now, rel_diff, tolerance) outside tolerance."""
    merged = baseline.merge(now, on=KEYS, suffixes=("_base", "_now"), how="left")
    out = []
    for metric in METRICS:
        base, current = merged[f"{metric}_base"].to_numpy(float), merged[f"{metric}_now"].to_numpy(float)
        scale = np.nanmax(np.abs(base)) if np.any(np.isfinite(base)) else 1.0
        tol = np.where(merged.engine == "reference", TOLERANCE["reference"], TOLERANCE["engine"])
        both_nan = np.isnan(base) & np.isnan(current)
        rel = np.abs(current - base) / np.maximum(np.abs(base), 1e-9 * scale)
        bad = ~both_nan & ~(rel <= tol)
        for i in np.flatnonzero(bad):
            out.append({**{k: merged[k].iloc[i] for k in KEYS}, "metric": metric, "baseline": base[i],
                        "now": current[i], "rel_diff": rel[i], "tolerance": tol[i]})
    return pd.DataFrame(out, columns=KEYS + ["metric", "baseline", "now", "rel_diff", "tolerance"])


def check(directory, now=None, progress=None, cache=None):
    """Recompute the matrix (unless given) and list every metric outside tolerance; rows of absent engines are
    reported as skipped, not as failures."""
    path = os.path.join(directory, BASELINE_FILE)
    if not os.path.exists(path):
        raise UserError(f"no baseline at {path}; create it with `harness baseline --update --baseline {directory}`")
    refuse_to_read_unless_regular(path, "the baseline")
    baseline = read_csv(path)
    if baseline.empty:
        raise UserError(f"the baseline {path} holds no rows; recreate it with `harness baseline --update`")
    if not all(pd.api.types.is_numeric_dtype(baseline[m]) for m in METRICS):
        raise UserError(f"the baseline {path} holds a value that is not a number in "
                        f"{', '.join(m for m in METRICS if not pd.api.types.is_numeric_dtype(baseline[m]))}")
    skipped = []
    if now is None:
        now, skipped = compute(progress, cache)
    ran = set(now.engine.unique())
    missing = sorted(set(baseline.engine.unique()) - ran)
    skipped += [f"{engine}: not run here, its baseline rows were not checked" for engine in missing]
    baseline = baseline[baseline.engine.isin(ran)]
    return compare_to_baseline(baseline, now), skipped
