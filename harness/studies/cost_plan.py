"""The cost study's runs (`harness cost`): each dialect's converged truth (cost_truth.py) and its levels, then
per curve a ladder of runs at each resolution, timed; the engines' start-up runs; the converged mode's own rungs.
Each rung's results go to analyses/cost.py as soon as they are run, which turns them into cost rows."""
import math
from dataclasses import replace

import numpy as np
import pandas as pd

from ..analyses.cost import (ADAPTIVE, ADAPTIVE_RUNGS, COLUMNS, EXTRAPOLATED, LADDER, MIN_NET_S, RAYLEIGH_FRACTION,
                            RESOLVE_RATIO, TRUTH_LEVEL, Rows, contact_steps, converged_rows, fastest, measure, per_e_n,
                            priced, rayleigh_time, refused, resolved, step_time_row)
from .cost_truth import covered, reference, truth_of
from ..runs.execute import execute
from ..solver.resolution import MAX_STEPS_PER_CONTACT, FixedTimeStep
from ..runs.plan import engine_runs
from ..infra.errors import UserError
from ..solver.simulate import CONVERGED_START, simulate, simulate_adaptive, simulate_extrapolated
from ..solver.stability import UnstableTimeStep

TIMING_REPEATS = 3               # each timed run and each start-up is timed this often: the fastest, and the spread
LONG_RUN_S = 5.0                 # a run this long is timed once (the machine's noise is small beside it)
STARTUP_STEPS = 1                # a start-up run's step cap: stopped after its first separation check
STARTUP_RESOLUTION = 1000        # steps per contact of the start-up runs (their first check: a tenth of a contact)
TIMING_STEPS = 200               # a curve's time per impact-step is timed at its rung nearest this many steps/contact,
FIRST_IMPACTS = 256              # on copies of the scene's impacts of its first e_n: at least this many at first,
GROWTH = 16                      # this many times more while the net time is not resolved (or as many as it needs):
MAX_TIMING_STEPS = 2 ** 16       # steps per contact up to this many (an engine's start-up does not grow with them),
MAX_TIMING_IMPACTS = 4096        # then impacts up to this many (an engine's start-up grows with them),
MAX_TIMING_ROUNDS = 6            # in at most this many rounds


def truth_rows(rows, law_name, dialect, truth):
    """The levels of a dialect's converged reference as rungs of its curve beyond the ladder ('truth N'), each
    against the truth: at a refined level the impacts run there, the others at their truth."""
    for steps, run, frame in truth.levels:
        level = truth.frame.copy()
        for column in frame.columns:
            level.loc[level.index[run], column] = frame[column].to_numpy()
        ran = per_e_n(frame)
        for e_n, group in ran.items():                      # the level's resolution on every row of its e_n
            resolution = group[["steps_per_contact", "dt"]].iloc[0].to_numpy()
            level.loc[level.e_n_target == e_n, ["steps_per_contact", "dt"]] = resolution
        measure(rows, law_name, "reference", dialect, f"{TRUTH_LEVEL}{steps}",
                {e_n: group for e_n, group in per_e_n(level).items() if e_n in ran}, truth,
                steps_per_impact={e_n: contact_steps(group) / len(group) for e_n, group in ran.items()},
                timings={e_n: [float(group.wall_s.sum())] for e_n, group in ran.items()},
                note=f"a level of the converged reference ({len(run)} impacts run at {steps} steps/contact)")


def ladder_rungs(ladder, scene):
    """(label, resolution) pairs: the ladder's steps per contact, then 20% of the Rayleigh time."""
    return [(str(n), n) for n in ladder] + [("rayleigh", FixedTimeStep(RAYLEIGH_FRACTION * rayleigh_time(scene)))]


def reference_curve(rows, law, scene, ladder, truth, engine_label="reference", progress=None):
    """The reference engine running `law` at every rung, each timed TIMING_REPEATS times."""
    for label, resolution in ladder_rungs(ladder, scene):
        try:
            frames = [reference(law, scene, resolution) for _ in range(TIMING_REPEATS)]
        except UnstableTimeStep as exc:
            refused(rows, law.name, engine_label, law.dialect, label, scene, str(exc))
            step(progress, f"{law.dialect} formulas, {label}: refused")
            continue
        timings = {e: [float(f[f.e_n_target == e].wall_s.sum()) for f in frames] for e in scene.e_n}
        measure(rows, law.name, engine_label, law.dialect, label, per_e_n(frames[0]), truth, timings=timings)
        step(progress, f"{law.dialect} formulas in the reference, {label}")


def step(progress, what):
    if progress:
        progress.advance(what)


def startup_seconds(engine, law, scene, options):
    """Per e_n: (fastest, spread) of TIMING_REPEATS timings of the same batched run stopped after its first check (a
    few steps): process start-up, reading the input and building the scene, which a long simulation pays once."""
    runs = [replace(run, step_cap=STARTUP_STEPS) for run in engine_runs(engine, law, scene, STARTUP_RESOLUTION,
                                                                          options)]
    return {run.e_n: fastest([float(execute([run])[0].wall_s.sum(min_count=1)) for _ in range(TIMING_REPEATS)])
            for run in runs}


def engine_curve(rows, engine, law, dialect, scene, ladder, truth, options, failures, progress=None):
    """The engine itself at every rung (one batched run per e_n, timed TIMING_REPEATS times unless it is long);
    contact time and peak force come from a further, observed run (its per-step output would distort the timing);
    refused and failed runs keep their message."""
    startup = startup_seconds(engine, law, scene, options)
    step(progress, f"{engine.NAME} start-up")
    for label, resolution in ladder_rungs(ladder, scene):
        try:
            frames, failed = sweep(engine, law, scene, resolution, options)
        except UnstableTimeStep as exc:
            refused(rows, law.name, engine.NAME, dialect.dialect, label, scene, str(exc))
            step(progress, f"{engine.NAME}, {label}: refused")
            continue
        failures += failed
        timings = {f.e_n_target.iloc[0]: [float(f.wall_s.sum())] for f in frames}
        for _ in range(TIMING_REPEATS - 1):
            if failed or max(w[0] for w in timings.values()) > LONG_RUN_S:
                break
            for frame in sweep(engine, law, scene, resolution, options)[0]:
                timings[frame.e_n_target.iloc[0]].append(float(frame.wall_s.sum()))
        if not failed:                  # contact time and peak force from an observed, untimed run
            observed, failed = sweep(engine, law, scene, resolution, options, observe=True)
            failures += failed
            for frame, seen in zip(frames, observed):
                for column in ("t_contact", "f_n_max", "overlap_max"):
                    frame[column] = seen[column].to_numpy()
        measure(rows, law.name, engine.NAME, dialect.dialect, label, {f.e_n_target.iloc[0]: f for f in frames}, truth,
                startup, timings=timings)
        step(progress, f"{engine.NAME}, {label}")


def sweep(engine, law, scene, resolution, options, observe=False):
    """The engine's runs at every e_n (one frame each) and its failed runs."""
    runs = engine_runs(engine, law, scene, resolution, options, observe)
    for run in runs:
        run.spec                           # a time step above the stability limit: refused before any run
    frames, failures = [], []
    for run in runs:
        table, failed = execute([run])
        frames.append(table)
        failures += failed
    return frames, failures


def copies(scene, e_n, count):
    """The scene at one e_n with its impacts repeated `count` times (the same impacts, independent of each other)."""
    field = next(f for f in ("angles_deg", "psi1_star", "v_t") if getattr(scene, f) is not None)
    return replace(scene, e_n=(e_n,), **{field: tuple(getattr(scene, field)) * count})


def timing_rung(rows, engine, dialect, e_n):
    """The curve's rung (a row) nearest TIMING_STEPS steps (or evaluations) per contact that ran, at `e_n` (a rung of
    its ladder or tolerances, not 20% of the Rayleigh time nor a level of its converged reference)."""
    ran = [r for r in rows if r["engine"] == engine and r["dialect"] == dialect and r["e_n_target"] == e_n
           and r.get("status") == "ok" and r["rung"] != "rayleigh" and not r["rung"].startswith(TRUTH_LEVEL)
           and r.get("steps", 0) > 0]
    return min(ran, key=lambda r: abs(math.log(r["steps_per_contact"] / TIMING_STEPS)), default=None)


def step_time(rows, law_name, engine, dialect, scene, timed, progress=None, finer=True):
    """A curve's time per impact-step: its rung nearest TIMING_STEPS on copies of the scene's impacts of one e_n,
    FIRST_IMPACTS at first; while the net time (wall less start-up, each the fastest of at least two timings) is not
    resolved, GROWTH times more (or what the last net time says is needed) steps per contact up to MAX_TIMING_STEPS
    (if `finer`: the rung has a finer one), then impacts up to MAX_TIMING_IMPACTS, in at most MAX_TIMING_ROUNDS;
    a row saying 'not resolved' where it never is. timed(scene, rung label) -> (wall timings, start-up timings)."""
    e_n = scene.e_n[0]
    rung = timing_rung(rows, engine, dialect, e_n)
    if rung is None:
        return
    per_copy = len(scene.impacts(e_n)[0])
    count, scale, tried = max(1, math.ceil(FIRST_IMPACTS / per_copy)), 1, []
    most = max(count, MAX_TIMING_IMPACTS // per_copy)
    while True:
        label = rung["rung"] if scale == 1 else str(int(rung["rung"]) * scale)
        walls, starts = timed(copies(scene, e_n, count), label)
        wall, start = fastest(walls), (fastest(starts) if starts else (0.0, 0.0))
        net, noise = wall[0] - start[0], float(np.nansum([wall[1], start[1]]))
        tried.append(f"{count * per_copy} at {label}")
        if resolved(net, noise) or len(tried) >= MAX_TIMING_ROUNDS or not np.isfinite(net):
            break
        need = growth(net, noise)
        finest = MAX_TIMING_STEPS // (int(rung["rung"]) * scale) if finer else 1
        if finest >= 2:
            scale *= min(need, finest)
        elif count < most:
            count = min(count * need, most)
        else:
            break
    timed_rung = {"rung": label, "steps_per_contact": rung["steps_per_contact"] * scale, "dt": rung["dt"] / scale}
    rows.append(step_time_row(law_name, engine, dialect, e_n, timed_rung, count, count * per_copy,
                              count * rung["steps"] * scale, wall, start, "; ".join(tried)))
    step(progress, f"{engine} ({dialect}): time per impact-step")


def growth(net, noise):
    """How many times more work the next timing round needs: what makes the net time 1.5x the least it must be
    (MIN_NET_S and RESOLVE_RATIO x its noise) where the net time stands above its noise, else GROWTH; 2 to GROWTH."""
    if net <= noise:
        return GROWTH
    return min(max(math.ceil(max(MIN_NET_S, RESOLVE_RATIO * noise) * 1.5 / net), 2), GROWTH)


def repeated(once, least=2):
    """TIMING_REPEATS timings of `once()` (seconds), no fewer than `least`, fewer when one takes LONG_RUN_S."""
    walls = []
    for _ in range(TIMING_REPEATS):
        walls.append(once())
        if not np.isfinite(walls[-1]) or (walls[-1] > LONG_RUN_S and len(walls) >= least):
            break
    return walls


def reference_timer(law):
    """timed(scene, rung) of the reference solver running `law` at a rung of steps per contact (no start-up)."""
    return lambda scene, rung: (repeated(lambda: float(reference(law, scene, int(rung)).wall_s.sum())), [])


def converged_timer(law, adaptive):
    """timed(scene, rung) of the converged mode's rungs: the adaptive integrator at 'tol X' or the graded ladder."""
    def once(scene, rung):
        frame = simulate_adaptive(law, scene, float(rung[4:])) if adaptive else simulate_extrapolated(law, scene,
                                                                                                      int(rung))
        return float(frame.wall_s.sum())
    return lambda scene, rung: (repeated(lambda: once(scene, rung)), [])


def engine_timer(engine, law, options):
    """timed(scene, rung) of an engine: its batched run at the rung and the same run stopped after its first check."""
    def timed(scene, rung):
        run = engine_runs(engine, law, scene, int(rung), options)[0]
        def once(run):
            table, failed = execute([run])
            return np.nan if failed else float(table.wall_s.sum(min_count=1))
        return repeated(lambda: once(run)), repeated(lambda: once(replace(run, step_cap=STARTUP_STEPS)))
    return timed


def converged_curve(rows, law, scene, ladder, truth):
    """The converged mode's own rungs as a curve: the adaptive integrator's tolerances where it covers the law,
    else the graded Richardson ladder; True for the adaptive integrator."""
    if law.integrator == "paper" and covered(law, scene):
        adaptive_curve(rows, law, scene, truth)
        return True
    extrapolated_curve(rows, law, scene, ladder, truth)
    return False


def adaptive_curve(rows, law, scene, truth):
    """The adaptive integrator at each tolerance of ADAPTIVE_RUNGS; its steps per contact are force evaluations."""
    for tol in ADAPTIVE_RUNGS:
        frame = simulate_adaptive(law, scene, tol)
        measure(rows, law.name, "reference", ADAPTIVE, f"tol {tol:.0e}", per_e_n(frame), truth,
                steps_per_impact=float(frame.steps_per_contact.mean()))


def extrapolated_curve(rows, law, scene, ladder, truth):
    """The paper law's converged ladder at each rung n >= 20 of the ladder: R_n from n/2 and n graded steps per
    contact, its cost that of both runs and of the two uniform runs that place the release."""
    for n in (n for n in ladder if n >= 20):
        try:
            frame = simulate_extrapolated(law, scene, n)
        except UnstableTimeStep as exc:
            refused(rows, law.name, "reference", EXTRAPOLATED, str(n), scene, str(exc))
            continue
        measure(rows, law.name, "reference", EXTRAPOLATED, str(n), per_e_n(frame), truth,
                steps_per_impact=n // 2 + n + CONVERGED_START // 2 + CONVERGED_START)


def cost_table(law, scene, engines, ladder=LADDER, keep=None, progress=None, cache=None):
    """Every curve of the study as one table (COLUMNS); engines: {name: (engine module, options)}; `keep(table)` is
    called with the table so far after every row; progress told of every rung; the truths' runs through `cache` (a
    campaign store) when given (timed runs never are: a stored run has no time to give)."""
    rungs = len(ladder_rungs(ladder, scene))
    if progress:
        progress.expect(5 + rungs + len(engines) * (4 + 2 * rungs))
    warm = scene.__class__(e_n=(0.5,), angles_deg=(10.0,))
    simulate(law, warm, steps_per_contact=10)                 # compile outside timing: the kernel,
    simulate(law, warm, converged=True)                       # and the adaptive integrator or graded ladder
    rows, failures, uncertainty = Rows(keep), [], {}
    truth = truth_of(law, scene, cache)
    uncertainty["paper"] = truth.uncertainty
    step(progress, "converged reference of the paper law")
    reference_curve(rows, law, scene, ladder, truth, progress=progress)
    truth_rows(rows, law.name, law.dialect, truth)
    step_time(rows, law.name, "reference", law.dialect, scene, reference_timer(law), progress)
    adaptive = converged_curve(rows, law, scene, ladder, truth)
    step(progress, "the converged mode's own rungs")
    step_time(rows, law.name, "reference", ADAPTIVE if adaptive else EXTRAPOLATED, scene,
              converged_timer(law, adaptive), progress, finer=not adaptive)
    converged_rows(rows, law, simulate(law, scene, converged=True)[0], truth)
    step(progress, "the converged mode")
    for name, (engine, options) in engines.items():
        dialect = engine.dialect(law.name, options)
        dialect_truth = truth_of(dialect, scene, cache)
        uncertainty[name] = dialect_truth.uncertainty
        step(progress, f"converged reference of {name}'s formulas")
        reference_curve(rows, dialect, scene, ladder, dialect_truth, progress=progress)
        truth_rows(rows, law.name, dialect.dialect, dialect_truth)
        step_time(rows, law.name, "reference", dialect.dialect, scene, reference_timer(dialect), progress)
        engine_curve(rows, engine, law, dialect, scene, ladder, dialect_truth, options, failures, progress)
        step_time(rows, law.name, engine.NAME, dialect.dialect, scene, engine_timer(engine, law, options), progress)
    return priced(pd.DataFrame(rows, columns=COLUMNS)), failures, uncertainty


MAX_RUNGS = 30                              # each rung runs every curve at every e_n, timed up to 3 times
MAX_LADDER_STEPS = 2 * MAX_STEPS_PER_CONTACT    # the rungs together: two runs at the finest resolution allowed


def check_ladder(rungs, shown=None):
    """The ladder's rungs (whole steps per contact) if >= 1, ascending, no repeats; at most MAX_RUNGS rungs, each at
    most MAX_STEPS_PER_CONTACT (every resolution's bound) and MAX_LADDER_STEPS together, so that the study ends."""
    shown = shown if shown is not None else ",".join(map(str, rungs))
    if not rungs or min(rungs) < 1 or list(rungs) != sorted(set(rungs)):
        raise UserError(f"--ladder needs ascending whole numbers >= 1 without repeats, got {shown!r}")
    if len(rungs) > MAX_RUNGS:
        raise UserError(f"--ladder may have at most {MAX_RUNGS} rungs (each runs every curve at every e_n, timed up "
                        f"to {TIMING_REPEATS} times), got {len(rungs)}")
    if rungs[-1] > MAX_STEPS_PER_CONTACT:
        raise UserError(f"--ladder rungs must be at most {MAX_STEPS_PER_CONTACT:.0e} steps per contact (the bound of "
                        f"every resolution), got {rungs[-1]}")
    if sum(rungs) > MAX_LADDER_STEPS:
        raise UserError(f"--ladder rungs may add up to at most {MAX_LADDER_STEPS:.0e} steps per contact (the work of "
                        f"two runs at the finest resolution allowed), got {sum(rungs):.3g}")
    return tuple(rungs)
