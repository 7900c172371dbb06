"""What accuracy costs in time: a ladder of steps per contact for the paper law, each engine's dialect and each
engine, errors of e_n, e_t, Omega*, t_c and F_max against the converged reference of the same dialect."""
import math

import numpy as np
import pandas as pd

from ..engines.runner import EngineFailure, scratch
from ..engines.batches import TIMEOUT_FLOOR_S
from ..solver.plan import FixedTimeStep, plan_batch
from ..solver.reference import CONVERGED_START, adaptive_batch, simulate, simulate_adaptive, simulate_extrapolated
from ..solver.stability import UnstableTimeStep

LADDER = (5, 10, 20, 50, 100, 200, 500, 1000, 5000)
METRICS = ("e_n", "e_t", "omega_star", "t_contact", "f_n_max")
TOLERANCES = (1e-2, 1e-3, 1e-4)
TRUTH_STEPS = {"paper": 2 ** 16, "engine": 2 ** 18}   # the engines' schemes are first order: a finer truth
TRUTH_SHARPEN = 1e-7             # a paper truth less certain than this is taken from the adaptive integrator ...
TRUTH_TOLERANCE = 1e-11          # ... at this tolerance
RAYLEIGH_FRACTION = 0.2
TIMING_REPEATS = 3               # each timed run and each start-up is timed this often: the fastest, and the spread
LONG_RUN_S = 5.0                 # a run this long is timed once (the machine's noise is small beside it)
WITHIN_NOISE = "within noise"    # the timing column of a rung whose net time is not above its spread
COLUMNS = ("model", "engine", "dialect", "e_n_target", "rung", "steps_per_contact", "dt", "impacts", "steps",
           "wall_s", "wall_spread_s", "startup_s", "net_wall_s", "timing", "status", "message",
           *(f"err_{m}" for m in METRICS), "err_max")


def rayleigh_time(scene):
    """T_R = pi R sqrt(rho/G)/(0.1631 nu + 0.8766), G = E/(2(1 + nu)) (Li, Xu & Thornton 2005)."""
    shear = scene.E / (2.0 * (1.0 + scene.nu))
    return math.pi * scene.radius * math.sqrt(scene.rho / shear) / (0.1631 * scene.nu + 0.8766)


def relative_errors(values, truth):
    """Per metric: max |x - x*| over the impacts / max |x*| (the sweep's scale; e_t and Omega* pass through 0)."""
    out = {}
    for metric in METRICS:
        exact = truth[metric].to_numpy(dtype=float)
        got = values[metric].to_numpy(dtype=float)
        usable = np.isfinite(exact)
        scale = np.max(np.abs(exact[usable])) if usable.any() else 0.0
        if scale == 0.0 or not np.isfinite(got[usable]).any():
            out[f"err_{metric}"] = np.nan
            continue
        diff = np.abs(got[usable] - exact[usable])
        out[f"err_{metric}"] = np.inf if not np.all(np.isfinite(diff)) else float(diff.max() / scale)
    finite = [v for v in out.values() if not np.isnan(v)]
    out["err_max"] = max(finite) if finite else np.nan
    return out


def truth_of(law, scene, cache=None):
    """Converged reference of one dialect: the finest run and its uncertainty (change from half the steps, an
    upper bound for first- and second-order schemes alike), per e_n, each naming its truth. Where that leaves the
    paper scheme uncertain beyond TRUTH_SHARPEN (Walton-Braun's spring at grazing incidence: ~1e-5, order 1.5) and
    the adaptive integrator covers the law, its run at TRUTH_TOLERANCE instead (uncertainty: the change from 10x
    that tolerance; tests/test_adaptive_walton_braun.py checks it against the deep graded ladder). With a cache (a
    campaign store), the two fine runs are taken from it when it holds them, and added to it when not."""
    steps = TRUTH_STEPS["paper" if law.integrator == "paper" else "engine"]
    fine, half = (reference(law, scene, n, cache) for n in (steps, steps // 2))
    uncertainty = uncertainties(half, fine, f"{steps} steps/contact")
    worst = max(errs["err_max"] for errs in uncertainty.values())
    if law.integrator == "paper" and worst > TRUTH_SHARPEN and covered(law, scene):
        fine = simulate_adaptive(law, scene, TRUTH_TOLERANCE)
        coarse = simulate_adaptive(law, scene, 10 * TRUTH_TOLERANCE)
        uncertainty = uncertainties(coarse, fine, f"adaptive at tol {TRUTH_TOLERANCE:.0e} ({steps} steps/contact: "
                                                  f"{worst:.1e})")
    return fine, uncertainty


def reference(law, scene, steps, cache=None):
    """The reference solver's results of `law` at `steps` per contact (through the plan and the cache, if given)."""
    if cache is None:
        return simulate(law, scene, steps_per_contact=steps)[0]
    from ..execute import execute
    from ..plan import reference_runs
    return execute(reference_runs(law, scene, steps, law), cache=cache)[0]


def uncertainties(coarse, fine, truth):
    """Per e_n the errors of the coarser run against the truth, and what the truth is."""
    return {e: {**relative_errors(group, fine[fine.e_n_target == e]), "truth": truth}
            for e, group in coarse.groupby("e_n_target", sort=False)}


def covered(law, scene):
    """The adaptive integrator covers every impact of the scene."""
    return all(adaptive_batch(law, scene, e_n)[1].all() for e_n in scene.e_n)


def contact_steps(frame):
    """Steps taken in contact, all impacts of one batch: ceil(t_c/dt) (the release step counts whole; an engine's
    observed contact time is a whole number of steps)."""
    return float(np.ceil(frame.t_contact / frame.dt - 1e-9).sum(skipna=False))


def fastest(walls):
    """(fastest, spread) of repeated timings: the minimum is the run least disturbed by the machine's other work."""
    walls = [w for w in walls if np.isfinite(w)]
    if not walls:
        return np.nan, np.nan
    return float(min(walls)), (float(max(walls) - min(walls)) if len(walls) > 1 else np.nan)


def measure(rows, law_name, engine, dialect, rung, frames_by_e, truth, startup=None, steps_per_impact=None,
            timings=None):
    """Cost rows of one rung: per e_n the errors against the truth, the fastest of its timings and their spread
    (timings: {e_n: [wall seconds]}, else the frame's), the wall time without the engine's start-up (startup:
    {e_n: (fastest, spread)}), said to be within noise where it is not above the two spreads, and contact steps (or
    `steps_per_impact` times the impacts, for a rung made of several runs)."""
    for e_n, frame in frames_by_e.items():
        exact = truth[truth.e_n_target == e_n]
        ok = frame.status == "ok"
        wall, spread = fastest((timings or {}).get(e_n, [float(frame.wall_s.sum())]))
        start, start_spread = (startup or {}).get(e_n, (0.0, 0.0))
        net = wall - start
        noise = np.nansum([spread, start_spread])
        rows.append({"model": law_name, "engine": engine, "dialect": dialect, "e_n_target": e_n, "rung": rung,
                     "steps_per_contact": float(frame.steps_per_contact.mean()), "dt": float(frame.dt.mean()),
                     "impacts": len(frame), "wall_s": wall, "wall_spread_s": spread, "startup_s": start,
                     "steps": contact_steps(frame) if steps_per_impact is None else steps_per_impact * len(frame),
                     "net_wall_s": net if np.isfinite(net) else np.nan,
                     "timing": WITHIN_NOISE if np.isfinite(net) and net <= noise else "",
                     "status": "ok" if ok.all() else str(frame.status[~ok].iloc[0]),
                     "message": "" if ok.all() else str(frame.message[~ok].iloc[0]),
                     **relative_errors(frame, exact)})


def refused(rows, law_name, engine, dialect, rung, scene, message):
    for e_n in scene.e_n:
        rows.append({"model": law_name, "engine": engine, "dialect": dialect, "e_n_target": e_n, "rung": rung,
                     "status": "refused", "message": message})


def ladder_rungs(ladder, scene):
    """(label, resolution) pairs: the ladder's steps per contact, then 20% of the Rayleigh time."""
    return [(str(n), n) for n in ladder] + [("rayleigh", FixedTimeStep(RAYLEIGH_FRACTION * rayleigh_time(scene)))]


def reference_curve(rows, law, scene, ladder, truth, engine_label="reference", progress=None):
    """The reference engine running `law` at every rung, each timed TIMING_REPEATS times."""
    for label, resolution in ladder_rungs(ladder, scene):
        try:
            frames = [simulate(law, scene, steps_per_contact=resolution)[0] for _ in range(TIMING_REPEATS)]
        except UnstableTimeStep as exc:
            refused(rows, law.name, engine_label, law.dialect, label, scene, str(exc))
            step(progress, f"{law.dialect} formulas, {label}: refused")
            continue
        timings = {e: [float(f[f.e_n_target == e].wall_s.sum()) for f in frames] for e in scene.e_n}
        measure(rows, law.name, engine_label, law.dialect, label,
                {e: g for e, g in frames[0].groupby("e_n_target", sort=False)}, truth, timings=timings)
        step(progress, f"{law.dialect} formulas in the reference, {label}")


def step(progress, what):
    if progress:
        progress.advance(what)


def startup_seconds(adapter, paper_law, dialect, scene, options):
    """Per e_n: (fastest, spread) of TIMING_REPEATS timings of the same batched run stopped after its first check (a
    few steps): process start-up, reading the input and building the scene, which a long simulation pays once."""
    starts = {}
    for e_n in scene.e_n:
        batch = plan_batch(dialect, scene, e_n, 1000)
        walls = []
        for _ in range(TIMING_REPEATS):
            try:
                with scratch(f"{adapter.NAME}-startup") as workdir:
                    walls.append(adapter.run_batch(paper_law, scene, batch, 1, TIMEOUT_FLOOR_S, workdir, options)[1])
            except EngineFailure:
                walls.append(np.nan)
        starts[e_n] = fastest(walls)
    return starts


def engine_curve(rows, adapter, paper_law, dialect, scene, ladder, truth, options, failures, progress=None):
    """The engine itself at every rung (one batched run per e_n, timed TIMING_REPEATS times unless it is long);
    contact time and peak force come from a further, observed run (its per-step output would distort the timing);
    refused and failed runs keep their message."""
    startup = startup_seconds(adapter, paper_law, dialect, scene, options)
    step(progress, f"{adapter.NAME} start-up")
    for label, resolution in ladder_rungs(ladder, scene):
        try:
            frames, failed = sweep(adapter, paper_law, scene, resolution, options)
        except UnstableTimeStep as exc:
            refused(rows, paper_law.name, adapter.NAME, dialect.dialect, label, scene, str(exc))
            step(progress, f"{adapter.NAME}, {label}: refused")
            continue
        failures += failed
        timings = {f.e_n_target.iloc[0]: [float(f.wall_s.sum())] for f in frames}
        for _ in range(TIMING_REPEATS - 1):
            if failed or max(w[0] for w in timings.values()) > LONG_RUN_S:
                break
            for frame in sweep(adapter, paper_law, scene, resolution, options)[0]:
                timings[frame.e_n_target.iloc[0]].append(float(frame.wall_s.sum()))
        if not failed:                  # contact time and peak force from an observed, untimed run
            observed, failed = sweep(adapter, paper_law, scene, resolution, options, observe=True)
            failures += failed
            for frame, seen in zip(frames, observed):
                for column in ("t_contact", "f_n_max", "overlap_max"):
                    frame[column] = seen[column].to_numpy()
        measure(rows, paper_law.name, adapter.NAME, dialect.dialect, label,
                {f.e_n_target.iloc[0]: f for f in frames}, truth, startup, timings=timings)
        step(progress, f"{adapter.NAME}, {label}")


def sweep(engine, law, scene, resolution, options, observe=False):
    """The engine's batches at every e_n (one frame each) and its failed runs, through the plan."""
    from ..execute import execute
    from ..plan import engine_runs
    runs = engine_runs(engine, law, scene, resolution, options, observe)
    for run in runs:
        run.batch()                        # a time step above the stability limit: refused before any run
    frames, failures = [], []
    for run in runs:
        table, failed = execute([run])
        frames.append(table)
        failures += failed
    return frames, failures


EXTRAPOLATED = "paper, graded Richardson"       # the converged ladder's rungs as a curve of the reference
ADAPTIVE = "paper, adaptive"                    # the adaptive integrator's tolerances as a curve of the reference
ADAPTIVE_RUNGS = (1e-4, 1e-5, 1e-6, 1e-7, 1e-8)  # above the truth's own uncertainty (2^16 steps: ~1e-9)


def converged_curve(rows, law, scene, ladder, truth):
    """The converged mode's own rungs as a curve: the adaptive integrator's tolerances where it covers the law,
    else the graded Richardson ladder."""
    if law.integrator == "paper" and covered(law, scene):
        adaptive_curve(rows, law, scene, truth)
    else:
        extrapolated_curve(rows, law, scene, ladder, truth)


def adaptive_curve(rows, law, scene, truth):
    """The adaptive integrator at each tolerance of ADAPTIVE_RUNGS; its steps per contact are force evaluations."""
    for tol in ADAPTIVE_RUNGS:
        frame = simulate_adaptive(law, scene, tol)
        measure(rows, law.name, "reference", ADAPTIVE, f"tol {tol:.0e}",
                {e: g for e, g in frame.groupby("e_n_target", sort=False)}, truth,
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
        measure(rows, law.name, "reference", EXTRAPOLATED, str(n),
                {e: g for e, g in frame.groupby("e_n_target", sort=False)}, truth,
                steps_per_impact=n // 2 + n + CONVERGED_START // 2 + CONVERGED_START)


def converged_point(rows, law, scene, truth):
    """The paper law in --converged mode: one point of cost and error per e_n."""
    frame, _ = simulate(law, scene, converged=True)
    for e_n, group in frame.groupby("e_n_target", sort=False):
        exact = truth[truth.e_n_target == e_n]
        rows.append({"model": law.name, "engine": "reference", "dialect": law.dialect, "e_n_target": e_n,
                     "rung": "converged", "steps_per_contact": float(group.steps_per_contact.max()),
                     "dt": float(group.dt.min()), "impacts": len(group), "steps": np.nan,
                     "wall_s": float(group.wall_s.sum()), "startup_s": 0.0, "net_wall_s": float(group.wall_s.sum()),
                     "timing": "", "status": "ok", "message": "converged mode",
                     **relative_errors(group, exact)})


class Rows(list):
    """Cost rows that hand themselves to `keep` as each is added, so an interrupted study keeps what it measured."""

    def __init__(self, keep=None):
        super().__init__()
        self.keep = keep

    def append(self, row):
        super().append(row)
        if self.keep:
            self.keep(pd.DataFrame(self, columns=COLUMNS))


def cost_table(law, scene, adapters, ladder=LADDER, keep=None, progress=None, cache=None):
    """Every curve of the study as one table (COLUMNS); adapters: {name: (adapter, options)} of the engines;
    `keep(table)` is called with the table so far after every row; progress told of every rung; the truths' runs
    through `cache` (a campaign store) when given (timed runs never are: a stored run has no time to give)."""
    rungs = len(ladder_rungs(ladder, scene))
    if progress:
        progress.expect(3 + rungs + len(adapters) * (2 + 2 * rungs))
    warm = scene.__class__(e_n=(0.5,), angles_deg=(10.0,))
    simulate(law, warm, steps_per_contact=10)                 # compile outside timing: the kernel,
    simulate(law, warm, converged=True)                       # and the adaptive integrator or graded ladder
    rows, failures, uncertainty = Rows(keep), [], {}
    truth, uncertainty["paper"] = truth_of(law, scene, cache)
    step(progress, "converged reference of the paper law")
    reference_curve(rows, law, scene, ladder, truth, progress=progress)
    converged_curve(rows, law, scene, ladder, truth)
    step(progress, "the converged mode's own rungs")
    converged_point(rows, law, scene, truth)
    step(progress, "the converged mode")
    for name, (adapter, options) in adapters.items():
        dialect = adapter.dialect(law.name, options)
        dialect_truth, uncertainty[name] = truth_of(dialect, scene, cache)
        step(progress, f"converged reference of {name}'s formulas")
        reference_curve(rows, dialect, scene, ladder, dialect_truth, progress=progress)
        engine_curve(rows, adapter, law, dialect, scene, ladder, dialect_truth, options, failures, progress)
    return pd.DataFrame(rows, columns=COLUMNS), failures, uncertainty


def per_rung(cost):
    """Per curve and rung, over the e_n: worst error per metric, wall times and steps summed, finest dt."""
    agg = {f"err_{m}": "max" for m in (*METRICS, "max")}
    agg.update({"wall_s": "sum", "net_wall_s": "sum", "steps_per_contact": "min", "steps": "sum", "dt": "max",
                "timing": lambda t: WITHIN_NOISE if (t == WITHIN_NOISE).any() else ""})
    ran = cost[cost.status != "refused"].assign(timing=lambda c: c.timing.fillna(""))
    return ran.groupby(["engine", "dialect", "rung"], sort=False).agg(agg).reset_index()


def recommendations(cost):
    """Per curve (engine, dialect): the largest ladder dt whose error, and that of every finer rung, is within each
    tolerance at every e_n (worst metric); with its steps per contact and wall time."""
    out = []
    ladder = cost[cost.rung.str.fullmatch(r"\d+")]
    for (engine, dialect), curve in ladder.groupby(["engine", "dialect"], sort=False):
        row = {"engine": engine, "dialect": dialect}
        for tol in TOLERANCES:
            chosen = None
            for rung in sorted(curve.rung.unique(), key=int, reverse=True):
                level = curve[curve.rung == rung]
                if level.status.eq("ok").all() and (level.err_max <= tol).all():
                    chosen = level
                else:
                    break
            key = f"{tol:.0%}" if tol >= 0.01 else f"{tol * 100:g}%"
            row[f"dt for {key} [s]"] = chosen.dt.min() if chosen is not None else np.nan
            row[f"steps/contact for {key}"] = int(chosen.rung.iloc[0]) if chosen is not None else np.nan
            row[f"wall for {key} [s]"] = chosen.wall_s.sum() if chosen is not None else np.nan
        rayleigh = cost[(cost.engine == engine) & (cost.dialect == dialect) & (cost.rung == "rayleigh")]
        row["error at 20% Rayleigh"] = rayleigh.err_max.max() if rayleigh.status.eq("ok").all() else np.nan
        out.append(row)
    return pd.DataFrame(out)


def ladder_rows(cost):
    """Rows of the curves' rungs: steps per contact, or the adaptive integrator's tolerances."""
    return cost[cost.rung.str.fullmatch(r"\d+") | cost.rung.str.startswith("tol ")]


def convergence_orders(cost, floor=1e-12):
    """Per curve and metric: slope of -log(error) against log(steps per contact; force evaluations per contact for
    the adaptive curve) over the rungs of 20+ whose error is above `floor` (least squares over every e_n)."""
    out = []
    ladder = ladder_rows(cost)
    ladder = ladder[ladder.status == "ok"]
    for (engine, dialect), curve in ladder.groupby(["engine", "dialect"], sort=False):
        row = {"engine": engine, "dialect": dialect}
        for metric in METRICS:
            pts = curve[(curve.steps_per_contact >= 20) & (curve[f"err_{metric}"] > floor)]
            pts = pts[np.isfinite(pts[f"err_{metric}"])]
            if len(pts.rung.unique()) < 3:
                row[metric] = np.nan
                continue
            slope = np.polyfit(np.log(pts.steps_per_contact), np.log(pts[f"err_{metric}"]), 1)[0]
            row[metric] = -slope
        out.append(row)
    return pd.DataFrame(out)
