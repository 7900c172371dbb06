"""Baselines: the expected rebound kinematics of a fixed matrix (every law through the reference and through each
engine that supports it), committed under baselines/ and shipped with the package, and the regression check."""
import os
from dataclasses import replace
from importlib.resources import files

import numpy as np
import pandas as pd

from ..engines import ENGINES, EXTERNAL
from ..infra.errors import UserError
from ..runs.execute import execute
from ..infra.files import refuse_to_read_unless_regular
from ..laws import LAWS, compose
from ..runs.plan import engine_plan, reference_runs
from ..data.results import read_csv, write_csv
from ..scenes.scene import Scene

DEFAULT_BASELINE = str(files("harness") / "data" / "baselines")
BASELINE_FILE = "baseline.csv"
MATRIX_EN = (0.9, 0.5, 0.1)
MATRIX_ANGLES = (0.0, 30.0, 60.0)
STEPS_PER_CONTACT = 200
METRICS = ("v_n1", "v_t1", "omega1", "e_n", "e_t", "omega_star", "psi2_star", "t_contact", "f_n_max")
KEYS = ["model", "engine", "dialect", "engine_input", "e_n_target", "theta_deg"]   # engine by code: lammps@X -> lammps
INPUT_CASES = (     # (law, engine, a user's own input): rows recorded with the input verbatim and its composition
    ("linear-spring-dashpot", "lammps", "hooke 1e7 45 damping velocity tangential linear_history 2.8e6 0.5 0.4"),
    ("hertz-mindlin", "liggghts", "model hertz tangential history youngsModulus 7e10 poissonsRatio 0.3 "
                                  "coefficientRestitution 0.5 coefficientFriction 0.4"),
)
# relative tolerance (floor 1e-9 of the metric's scale): the reference is deterministic; an engine build may move
TOLERANCE = {"reference": 1e-9, "engine": 1e-6}


def matrix_scene():
    return Scene(e_n=MATRIX_EN, angles_deg=MATRIX_ANGLES)


def pinned(engines):
    """{engine: the build that runs it}: each registered engine's default build, or the one `engines` names."""
    chosen = {name: ENGINES[name] for name in EXTERNAL}
    for name in engines or ():
        build = ENGINES[name]
        if build.code not in chosen:
            raise UserError(f"the baseline matrix has no engine {build.code}")
        chosen[build.code] = build
    return chosen


def compute(progress=None, cache=None, engines=None):
    """The baseline matrix now: paper law and every engine's dialect on the reference, the engines where installed
    (each its default build, or the build `engines` pins); (frame, skipped)."""
    scene = matrix_scene()
    builds = pinned(engines)
    frames, skipped = [], []
    if progress:
        progress.expect(len(LAWS))
    for name in LAWS:
        law = compose(name)
        plan = reference_runs(law, scene, STEPS_PER_CONTACT)
        for engine_name, engine in builds.items():
            status = engine.status(name)
            if not engine.supports(name):
                continue
            if status.available:
                plan += engine_plan(engine, law, scene, STEPS_PER_CONTACT)
            else:                           # its dialect needs only the reference solver
                skipped.append(f"{engine_name} {name}: {status.reason}")
                plan += reference_runs(law, scene, STEPS_PER_CONTACT, engine.dialect(name, {}))
        frame, failures = execute(plan, cache=cache)
        frames.append(frame.assign(engine_input="", composition=""))
        skipped += [f"{f.engine} {name} e_n={f.e_n}: {f.message}" for f in failures]
        if progress:
            progress.advance(name)
    for name, code, text in INPUT_CASES:
        frame, missed = input_case(builds[code], name, text, cache)
        frames.append(frame)
        skipped += missed
    return pd.concat(frames, ignore_index=True), skipped


def input_case(engine, law_name, text, cache=None):
    """The rows of a user's own input on the matrix's angles at its own e and mu: its dialect on the reference and
    the engine where installed, each with the input verbatim and the neutral composition it maps to; (frame,
    skipped)."""
    from ..engines.user_inputs import INPUT_OPTION, parse
    options = {INPUT_OPTION: text}
    law, scene = compose(law_name), replace(matrix_scene(), e_n=(0.5,), mu=parse(engine.code, text).mu)
    dialect = engine.dialect(law_name, dict(options))
    composition = "; ".join(f"{k} {v}" for k, v in dialect.describe().items())
    status = engine.status(law_name)
    plan = (engine_plan(engine, law, scene, STEPS_PER_CONTACT, options) if status.available else
            reference_runs(law, scene, STEPS_PER_CONTACT, dialect))
    frame, failures = execute(plan, cache=cache)
    skipped = ([] if status.available else [f"{engine.code} {law_name} (input {text!r}): {status.reason}"])
    skipped += [f"{f.engine} {law_name} (input {text!r}): {f.message}" for f in failures]
    return frame.assign(engine_input=text, composition=composition), skipped


def update(directory, progress=None, engines=None):
    """Rewrite DIRECTORY/baseline.csv from a fresh computation (with the engine builds `engines` pins)."""
    os.makedirs(directory, exist_ok=True)
    frame, skipped = compute(progress, engines=engines)
    write_csv(frame, os.path.join(directory, BASELINE_FILE))
    return frame, skipped


def by_code(frame):
    """The frame with each build's engine and dialect named by the engine's code (lammps@2023.8.2.3 -> lammps), so
    that a baseline from one release is checked against another, and no engine input written as ''."""
    given = frame.engine_input.fillna("").astype(str) if "engine_input" in frame else ""
    return frame.assign(engine=frame.engine.str.partition("@")[0], dialect=frame.dialect.str.partition("@")[0],
                        engine_input=given)


def compare_to_baseline(baseline, now):
    """Rows (model, engine, dialect, e_n, angle, metric, baseline, now, rel_diff, tolerance) outside tolerance."""
    merged = by_code(baseline).merge(by_code(now), on=KEYS, suffixes=("_base", "_now"), how="left")
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


def release_changes(baseline, now):
    """Per engine whose release differs between the baseline and now: {engine, baseline, now, binary, ingredients}
    with the sub-models in which the two releases' dialects differ (per law), so a regression of the physics an
    upgrade brings is told from one harness does not know (docs/user-guide.md#engine-builds-and-releases)."""
    out = []
    base, current = by_code(baseline), by_code(now)
    for code in sorted(set(base.engine) & set(current.engine) - {"reference"}):
        old = str(base[base.engine == code].engine_version.iloc[0])
        rows = current[current.engine == code]
        new = str(rows.engine_version.iloc[0])
        if old == new:
            continue
        engine = ENGINES[code]
        differ = {}
        for law in sorted(set(rows.model)):
            a, b = engine.release_dialect(law, old).describe(), engine.release_dialect(law, new).describe()
            changed = [f"{key}: {a[key]} -> {b[key]}" for key in a if str(a[key]) != str(b[key])]
            if changed:
                differ[law] = changed
        out.append({"engine": code, "baseline": old, "now": new, "binary": str(rows.engine_binary.iloc[0]),
                    "ingredients": differ})
    return out


def check(directory, now=None, progress=None, cache=None, engines=None):
    """Recompute the matrix (unless given; with the engine builds `engines` pins) and list every metric outside
    tolerance; rows of absent engines are reported as skipped, not as failures."""
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
        now, skipped = compute(progress, cache, engines)
    ran = set(by_code(now).engine.unique())
    codes = by_code(baseline).engine
    missing = sorted(set(codes.unique()) - ran)
    skipped += [f"{engine}: not run here, its baseline rows were not checked" for engine in missing]
    baseline = baseline[codes.isin(ran).to_numpy()]
    return compare_to_baseline(baseline, now), skipped, release_changes(baseline, now)
