"""What accuracy costs in time, from the cost study's results (studies/cost_plan.py runs it): per rung of each curve the
errors of the rebound velocities, contact time and peak force against the converged reference of the same dialect;
timings and the orders of convergence. What a tolerance costs per curve: analyses/cost_answer.py."""
import math

import numpy as np
import pandas as pd

from ..infra.wording import counted

LADDER = (5, 10, 20, 50, 100, 200, 500, 1000, 5000)
VELOCITIES = ("v_n1", "v_t1", "omega1")          # as a fraction of the impact's incident speed V (omega1: R omega1)
SCALED = ("t_contact", "f_n_max")                # as a fraction of their largest value over the impacts
METRICS = VELOCITIES + SCALED
MEASURE = ("error: |x - x*| of the rebound velocities v_n1, v_t1 and R omega1 as a fraction of the impact's incident "
           "speed V (the physics verdict's measure), of contact time and peak force as a fraction of their largest "
           "value; the worst over the five, the impacts and the e_n, against the converged reference of the same "
           "dialect")
TOLERANCES = (1e-2, 1e-3, 1e-4)
RAYLEIGH_FRACTION = 0.2
WITHIN_NOISE = "within noise"    # the timing column of a rung whose net time is not above its spread
PER_STEP = "per impact-step"     # the rung of a curve's timing run: enough impacts to resolve its time per impact-step
RESOLVED, NOT_RESOLVED = "resolved", "not resolved"      # its timing column
RESOLVE_RATIO = 3.0              # a net time is resolved when at least this many times its noise ...
MIN_NET_S = 0.2                  # ... and at least this long
EXTRAPOLATED = "paper, graded Richardson"       # the converged ladder's rungs as a curve of the reference
ADAPTIVE = "paper, adaptive"                    # the adaptive integrator's tolerances as a curve of the reference
ADAPTIVE_RUNGS = (1e-4, 1e-5, 1e-6, 1e-7, 1e-8)  # above the truth's own uncertainty (2^16 steps: ~1e-9)
TRUTH_LEVEL = "truth "           # the rung label's prefix of a level of a dialect's converged reference: "truth 131072"
COLUMNS = ("model", "engine", "dialect", "e_n_target", "rung", "steps_per_contact", "dt", "impacts", "steps",
           "wall_s", "wall_spread_s", "startup_s", "net_wall_s", "timing", "status", "message",
           *(f"err_{m}" for m in METRICS), "err_max", "err_truth", "s_per_impact_step", "s_per_impact")


def rayleigh_time(scene):
    """T_R = pi R sqrt(rho/G)/(0.1631 nu + 0.8766), G = E/(2(1 + nu)) (Li, Xu & Thornton 2005)."""
    shear = scene.E / (2.0 * (1.0 + scene.nu))
    return math.pi * scene.radius * math.sqrt(scene.rho / shear) / (0.1631 * scene.nu + 0.8766)


def impact_errors(values, truth, scales=None):
    """Per impact (rows in the same order) and metric: |x - x*| / V of the rebound velocities (R |omega1 - omega1*| / V,
    V = |(v_n0, v_t0)|), |x - x*| / scale of contact time and peak force, the scale their largest |x*| (or `scales`,
    {metric: scale}, when the truth is a part of the impacts); NaN where the truth is not finite, inf where the
    truth is and the value is not."""
    speed = np.hypot(truth.v_n0.to_numpy(dtype=float), truth.v_t0.to_numpy(dtype=float))
    radius = truth.radius.to_numpy(dtype=float)
    out = {}
    for metric in METRICS:
        exact = truth[metric].to_numpy(dtype=float)
        got = values[metric].to_numpy(dtype=float)
        if metric in VELOCITIES:
            scale = speed / (radius if metric == "omega1" else 1.0)
        else:
            usable = np.isfinite(exact)
            scale = (scales or {}).get(metric, np.max(np.abs(exact[usable])) if usable.any() else np.nan)
        with np.errstate(invalid="ignore", divide="ignore"):
            error = np.abs(got - exact) / scale
        error[np.isfinite(exact) & ~np.isfinite(got)] = np.inf
        error[~np.isfinite(exact)] = np.nan
        out[metric] = error
    return pd.DataFrame(out, index=truth.index)


def rebound_errors(values, truth):
    """Per metric (MEASURE) the largest impact error (impact_errors): inf where an impact is lost, NaN where no
    impact reports the metric (an engine's contact time from a run that does not observe it); err_max the worst."""
    per_impact = impact_errors(values, truth)
    out = {}
    for metric in METRICS:
        error = per_impact[metric].to_numpy()
        reported = np.isfinite(values[metric].to_numpy(dtype=float)).any()
        out[f"err_{metric}"] = float(np.nanmax(error)) if reported and not np.isnan(error).all() else np.nan
    finite = [v for v in out.values() if not np.isnan(v)]
    out["err_max"] = max(finite) if finite else np.nan
    return out


def uncertainty_of(changes, truth):
    """Per metric the largest of the impacts' last changes (impact_errors of a truth against its coarser level),
    err_max the worst, and what the truth is."""
    out = {f"err_{m}": float(np.nanmax(changes[m])) if not changes[m].isna().all() else np.nan for m in METRICS}
    finite = [v for v in out.values() if not np.isnan(v)]
    return {**out, "err_max": max(finite) if finite else np.nan, "truth": truth}


def relative_errors(values, truth):
    """Per metric of e_n, e_t, Omega*, t_c, F_max: max |x - x*| over the impacts / max |x*| (harness calibrate's
    measure; e_t and Omega* pass through 0)."""
    out = {}
    for metric in ("e_n", "e_t", "omega_star", "t_contact", "f_n_max"):
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


def contact_steps(frame):
    """Steps taken in contact, all impacts of one batch: ceil(t_c/dt) (the release step counts whole; an engine's
    observed contact time is a whole number of steps)."""
    return float(np.ceil(frame.t_contact / frame.dt - 1e-9).sum(skipna=False))


def fastest(walls):
    """(fastest, spread) of repeated timings: the minimum is the run least disturbed by the machine's other work; its
    spread the second fastest less it, so that one run slowed by other work does not make a timing unresolved."""
    walls = sorted(w for w in walls if np.isfinite(w))
    if not walls:
        return np.nan, np.nan
    return float(walls[0]), (float(walls[1] - walls[0]) if len(walls) > 1 else np.nan)


def measure(rows, law_name, engine, dialect, rung, frames_by_e, truth, startup=None, steps_per_impact=None,
            timings=None, note=""):
    """Cost rows of one rung: per e_n the errors against the truth (a Truth: its frame and its uncertainty), the
    fastest of its timings and their spread (timings: {e_n: [wall seconds]}, else the frame's), the wall time without
    the engine's start-up (startup: {e_n: (fastest, spread)}), said to be within noise where it is not above the two
    spreads, and contact steps (or `steps_per_impact` times the impacts: a rung made of several runs, {e_n: steps}
    or one number); `note` the message of a rung that ran."""
    for e_n, frame in frames_by_e.items():
        exact = truth.frame[truth.frame.e_n_target == e_n]
        per_impact = steps_per_impact.get(e_n) if isinstance(steps_per_impact, dict) else steps_per_impact
        ok = frame.status == "ok"
        wall, spread = fastest((timings or {}).get(e_n, [float(frame.wall_s.sum())]))
        start, start_spread = (startup or {}).get(e_n, (0.0, 0.0))
        net = wall - start
        noise = np.nansum([spread, start_spread])
        rows.append({"model": law_name, "engine": engine, "dialect": dialect, "e_n_target": e_n, "rung": rung,
                     "steps_per_contact": float(frame.steps_per_contact.mean()), "dt": float(frame.dt.mean()),
                     "impacts": len(frame), "wall_s": wall, "wall_spread_s": spread, "startup_s": start,
                     "steps": contact_steps(frame) if per_impact is None else per_impact * len(frame),
                     "net_wall_s": net if np.isfinite(net) else np.nan,
                     "timing": WITHIN_NOISE if np.isfinite(net) and net <= noise else "",
                     "status": "ok" if ok.all() else str(frame.status[~ok].iloc[0]),
                     "message": note if ok.all() else str(frame.message[~ok].iloc[0]),
                     **rebound_errors(frame, exact), "err_truth": truth.uncertainty[e_n]["err_max"]})


def refused(rows, law_name, engine, dialect, rung, scene, message):
    for e_n in scene.e_n:
        rows.append({"model": law_name, "engine": engine, "dialect": dialect, "e_n_target": e_n, "rung": rung,
                     "status": "refused", "message": message})


def per_e_n(frame):
    """{e_n target: its rows} of a results table, in its order."""
    return {e: g for e, g in frame.groupby("e_n_target", sort=False)}


def converged_rows(rows, law, frame, truth):
    """The paper law in --converged mode (its results table): one point of cost and error per e_n."""
    for e_n, group in per_e_n(frame).items():
        exact = truth.frame[truth.frame.e_n_target == e_n]
        rows.append({"model": law.name, "engine": "reference", "dialect": law.dialect, "e_n_target": e_n,
                     "rung": "converged", "steps_per_contact": float(group.steps_per_contact.max()),
                     "dt": float(group.dt.min()), "impacts": len(group), "steps": np.nan,
                     "wall_s": float(group.wall_s.sum()), "startup_s": 0.0, "net_wall_s": float(group.wall_s.sum()),
                     "timing": "", "status": "ok", "message": "converged mode",
                     **rebound_errors(group, exact), "err_truth": truth.uncertainty[e_n]["err_max"]})


class Rows(list):
    """Cost rows that hand themselves to `keep` as each is added, so an interrupted study keeps what it measured."""

    def __init__(self, keep=None):
        super().__init__()
        self.keep = keep

    def append(self, row):
        super().append(row)
        if self.keep:
            self.keep(pd.DataFrame(self, columns=COLUMNS))


def per_rung(cost):
    """Per curve and rung, over the e_n: worst error per metric, wall times and steps summed, finest dt."""
    agg = {f"err_{m}": "max" for m in (*METRICS, "max", "truth")}
    agg.update({"wall_s": "sum", "net_wall_s": "sum", "s_per_impact": "mean", "steps_per_contact": "min",
                "steps": "sum", "impacts": "sum", "dt": "max",
                "timing": lambda t: WITHIN_NOISE if (t == WITHIN_NOISE).any() else ""})
    ran = cost[cost.status != "refused"].assign(timing=lambda c: c.timing.fillna(""))
    return ran.groupby(["engine", "dialect", "rung"], sort=False).agg(agg).reset_index()


def resolved(net, noise):
    """A net time is a measurement when it is at least RESOLVE_RATIO times its noise and MIN_NET_S long."""
    return bool(np.isfinite(net) and net >= MIN_NET_S and net >= RESOLVE_RATIO * np.nan_to_num(noise))


def step_time_row(law_name, engine, dialect, e_n, rung, copies, impacts, steps, wall, start, rounds):
    """The row of a curve's timing run: `impacts` (`copies` of the scene's impacts of one e_n) at the ladder's `rung`
    (its row: a dict), `steps` impact-steps in all; wall and start-up as (fastest, spread);
    its time per impact-step where the net time is resolved, else NaN and 'not resolved'; `rounds` says how the
    number of impacts was chosen."""
    net = wall[0] - start[0]
    noise = float(np.nansum([wall[1], start[1]]))
    ok = resolved(net, noise)
    why = (f"{counted(impacts, 'impact')} ({counted(copies, 'copy', 'copies')} of the scene's) at rung {rung['rung']}, "
           "fastest of the timings; "
           f"net {net:.3g} s, noise {noise:.2g} s (resolved: >= {RESOLVE_RATIO:g}x noise and >= {MIN_NET_S:g} s); "
           f"impacts tried: {rounds}")
    return {"model": law_name, "engine": engine, "dialect": dialect, "e_n_target": e_n, "rung": PER_STEP,
            "steps_per_contact": rung["steps_per_contact"], "dt": rung["dt"], "impacts": impacts, "steps": steps,
            "wall_s": wall[0], "wall_spread_s": wall[1], "startup_s": start[0],
            "net_wall_s": net if np.isfinite(net) else np.nan, "timing": RESOLVED if ok else NOT_RESOLVED,
            "status": "ok", "message": why, "s_per_impact_step": net / steps if ok and steps > 0 else np.nan}


def priced(cost):
    """Each row's time per impact: its impact-steps per impact times its curve's resolved time per impact-step (the
    converged mode's point: its own measured time per impact); NaN where the curve's time is not resolved."""
    cost = cost.copy()
    timing = cost[cost.rung == PER_STEP].set_index(["engine", "dialect"]).s_per_impact_step
    timing = timing[~timing.index.duplicated()]
    for i, row in cost.iterrows():
        if row.rung == PER_STEP:
            cost.at[i, "s_per_impact"] = np.nan
            continue
        if row.rung == "converged":
            cost.at[i, "s_per_impact"] = row.wall_s / row.impacts
            continue
        step = timing.get((row.engine, row.dialect), np.nan)
        cost.at[i, "s_per_impact_step"] = step
        cost.at[i, "s_per_impact"] = step * row.steps / row.impacts if row.impacts else np.nan
    return cost


def step_times(cost):
    """Per curve its timing run: engine, dialect, seconds per impact-step (NaN: not resolved), impacts, the verdict."""
    rows = cost[cost.rung == PER_STEP]
    return rows[["engine", "dialect", "s_per_impact_step", "impacts", "steps", "net_wall_s", "timing", "message"]]


def ladder_rows(cost, levels=True):
    """Rows of the curves' rungs: steps per contact, the adaptive integrator's tolerances, and (`levels`) the levels
    of a dialect's converged reference beyond the ladder."""
    rung = cost.rung.astype(str)
    return cost[rung.str.fullmatch(r"\d+") | rung.str.startswith("tol ") | (levels & rung.str.startswith(TRUTH_LEVEL))]


def convergence_orders(cost, floor=1e-12):
    """Per curve and metric: slope of -log(error) against log(steps per contact; force evaluations per contact for
    the adaptive curve) over the rungs of 20+ whose error is above `floor` (least squares over every e_n); the levels
    of the converged reference are not rungs here (the finest is the truth, the next its uncertainty)."""
    out = []
    ladder = ladder_rows(cost, levels=False)
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
