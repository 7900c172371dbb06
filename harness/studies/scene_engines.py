"""A scene case on the engines: each engine's run of the case (Engine.run_scene) in a scratch directory, and its
agreement with the small-system integrator run with that engine's dialect of the law at the same time step."""
import dataclasses
import math

import numpy as np

from ..engines.runner import EngineFailure, scratch
from ..solver.system import E_KIND, E_VN, PART, TOUCH
from ..solver.system_run import simulate_system

REFERENCE = "reference"
AGREEMENT = 1e-6                    # of each quantity's scale, where the scene is deterministic
TIMEOUT_FLOOR_S = 120.0             # an engine scene run's timeout: this, plus 100 times its cost estimate


def engine_run(engine, kind, case, grid, options):
    """(SystemResult, '') of the engine's run of the case, or (None, failure with its log tail)."""
    timeout = TIMEOUT_FLOOR_S + 100.0 * engine.campaign_seconds(len(case.variant.spheres), case.variant.steps)
    with scratch(f"scene-{engine.code}") as workdir:
        try:
            result, _, _ = engine.run_scene(kind, case, grid, timeout, workdir, options)
        except EngineFailure as failure:
            tail = f"\n{failure.log_tail}" if failure.log_tail else ""
            return None, f"{engine.NAME} failed on scene {kind}, {case.name}: {failure}{tail}"
    return result, ""


def dialect_run(engine, law_name, case, grid, options, gain_from, kept):
    """The small-system integrator's run of the case with the engine's dialect of the law in place of the paper's
    (against the wall, and between two spheres where it has one) and its set-up's forces (Engine.START_FRICTION)."""
    dialect = engine.dialect(law_name, options)
    pair = engine.dialect(law_name, options, "sphere") if law_name in engine.PAIR_DIALECTS else None
    variant = dataclasses.replace(case.variant, law=dialect, start_friction=engine.START_FRICTION,
                                  pair_law=pair if len(case.variant.spheres) > 1 else None)
    return simulate_system([variant], grid, gain_from=gain_from, kept_events=kept)


def agreement(kind, case, engine_result, dialect_result):
    """(largest difference over the scale, where it is, the recorded times compared): x and z over the largest of
    the radius' 1e-3, the dialect's largest overlap and its largest displacement; vx, vz over its largest speed; w
    over its largest R |w| / R (its largest speed over R where it never spins); a bounce up to its first parting,
    with the first touch's and parting's V_n over the incident speed."""
    mine, theirs = engine_result.trace[0], dialect_result.trace[0]
    grid = dialect_result.grid
    upto = len(grid)
    events = dialect_result.events[0, :dialect_result.n_events[0]]
    if kind == "bounce":
        parts = [e for e in events if e[E_KIND] == PART]
        if parts:
            upto = int(np.searchsorted(grid, parts[0][0], side="right"))
    radius = case.variant.spheres[0].radius
    start = theirs[0]
    displacement = np.nanmax(np.abs(theirs[:upto, :, :2] - start[None, :, :2]))
    alpha = np.nanmax(np.abs(dialect_result.final[0, :, 0])) if dialect_result.final.size else 0.0
    length = max(1e-3 * radius, displacement, alpha)
    speed = max(np.nanmax(np.abs(theirs[:upto, :, 2:4])), 1e-12)
    spin = max(np.nanmax(np.abs(theirs[:upto, :, 4])), speed / radius)
    scales = np.array([length, length, speed, speed, spin])
    relative = np.abs(mine[:upto] - theirs[:upto]) / scales
    worst = np.unravel_index(int(np.nanargmax(relative)), relative.shape)
    value, where = float(relative[worst]), f"{'x z vx vz w'.split()[worst[2]]} at t = {grid[worst[0]]:.6g} s"
    if kind == "bounce":
        value, where = first_bounce(engine_result, events, value, where)
    return value, where, upto


def first_bounce(engine_result, events, value, where):
    """The larger of the trace's difference and the first touch's and parting's V_n differences over the incident
    speed."""
    theirs = [e for e in events if e[E_KIND] in (TOUCH, PART)][:2]
    mine = engine_result.events[0, :engine_result.n_events[0]][:2]
    if len(theirs) < 2 or len(mine) < 2:
        return math.inf, "the first bounce is missing from the engine's or the dialect's events"
    incident = abs(theirs[0][E_VN])
    for name, a, b in (("touch", mine[0], theirs[0]), ("parting", mine[1], theirs[1])):
        difference = abs(a[E_VN] - b[E_VN]) / incident
        if difference > value:
            value, where = difference, f"V_n at the first {name}"
    return value, where


def scene_engines(kind, law_name, names, engine_options, overrides=()):
    """([(engine, its options)] of the engines named that run the scene for the law with the --with `overrides`
    (Engine.with_options adds the options that make its input follow them), {name: why not} of the others)."""
    from ..engines import get_engine
    from ..infra.errors import UserError
    runners, unavailable = [], {}
    for name in names or ():
        if name == REFERENCE:
            continue
        engine = get_engine(name)
        options = dict(engine_options.get(name, {}))
        status = engine.status(law_name, options)
        reason = status.reason if not status.available else engine.scene_reason(kind, law_name, options)
        if not reason:
            try:
                options = engine.with_options(law_name, dict(overrides), options)
            except UserError as refusal:
                reason = str(refusal)
        if reason:
            unavailable[name] = reason
        else:
            runners.append((engine, options))
    return runners, unavailable


def agreement_row(engine, kind, case, ran, dialect, law_name, options=None):
    """The row of checks.csv of the engine's trace against its dialect's on the small-system integrator; where it
    fails, the note names the dialect's ingredients the integrator leaves out (or says none was found)."""
    value, where, compared = agreement(kind, case, ran, dialect)
    span = "up to the first parting" if kind == "bounce" else "over the run"
    passed = bool(np.isfinite(value) and value <= AGREEMENT)
    note = (f"largest difference over its scale, {where}; {compared} recorded times {span}, "
            f"dt {case.variant.dt:.6g} s on both")
    if not passed:
        left_out = left_out_ingredients(engine.dialect(law_name, options))
        note += ("; the small-system integrator leaves out its dialect's " + ", ".join(left_out) if left_out else
                 "; no ingredient of its dialect that the small-system integrator leaves out was found: the cause is "
                 "not named yet")
    return dict(check="agreement", engine=engine.NAME, case=case.name, quantity="trace against its dialect",
                value=value, expected=0.0, error=value, tolerance=AGREEMENT, passed=passed, note=note)


def left_out_ingredients(dialect):
    """The sub-models of a dialect the small-system integrator does not follow: a slip form other than the lever's
    (YADE's noRatch slip with the wall's reference radius)."""
    return [f"slip {dialect.slip} (it takes the lever's)"] if dialect.slip != "lever" else []


def dialect_ingredients(engine, law, options):
    """The sub-models where the engine's dialect differs from the paper law, as `key choice` texts."""
    paper, dialect = law.describe(), engine.dialect(law.name, options).describe()
    return [f"{key} {choice}" for key, choice in dialect.items() if paper.get(key) != choice]


def explained(rows, dialect_rows, ingredients):
    """The engine's check rows, each that failed noting the value its dialect gives on the small-system integrator
    and the dialect's ingredients that differ from the paper law (where the difference comes from)."""
    theirs = {(row["check"], row["case"]): row["value"] for row in dialect_rows}
    for row in rows:
        if not row["passed"] and (row["check"], row["case"]) in theirs:
            value = theirs[row["check"], row["case"]]
            row["note"] += (f"; its dialect on the small-system integrator gives {value:.9g}, differing from the "
                            f"paper law in {', '.join(ingredients) or 'nothing'}")
    return rows
