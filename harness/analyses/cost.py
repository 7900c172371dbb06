"""What accuracy costs in time, from the cost study's results (harness.cost_plan runs it): errors of e_n, e_t,
Omega*, t_c and F_max against the converged reference of the same dialect, per rung of each curve; timings, the
recommended time steps and the orders of convergence."""
import math

import numpy as np
import pandas as pd

from ..wording import counted

LADDER = (5, 10, 20, 50, 100, 200, 500, 1000, 5000)
METRICS = ("e_n", "e_t", "omega_star", "t_contact", "f_n_max")
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
COLUMNS = ("model", "engine", "dialect", "e_n_target", "rung", "steps_per_contact", "dt", "impacts", "steps",
           "wall_s", "wall_spread_s", "startup_s", "net_wall_s", "timing", "status", "message",
           *(f"err_{m}" for m in METRICS), "err_max", "s_per_impact_step", "s_per_impact")


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


def uncertainties(coarse, fine, truth):
    """Per e_n the errors of the coarser run against the truth, and what the truth is."""
    return {e: {**relative_errors(group, fine[fine.e_n_target == e]), "truth": truth}
            for e, group in coarse.groupby("e_n_target", sort=False)}


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


def per_e_n(frame):
    """{e_n target: its rows} of a results table, in its order."""
    return {e: g for e, g in frame.groupby("e_n_target", sort=False)}


def converged_rows(rows, law, frame, truth):
    """The paper law in --converged mode (its results table): one point of cost and error per e_n."""
    for e_n, group in per_e_n(frame).items():
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


def per_rung(cost):
    """Per curve and rung, over the e_n: worst error per metric, wall times and steps summed, finest dt."""
    agg = {f"err_{m}": "max" for m in (*METRICS, "max")}
    agg.update({"wall_s": "sum", "net_wall_s": "sum", "s_per_impact": "mean", "steps_per_contact": "min", "steps": "sum", "dt": "max",
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
            row[f"time/impact for {key} [s]"] = per_impact(chosen) if chosen is not None else np.nan
        rayleigh = cost[(cost.engine == engine) & (cost.dialect == dialect) & (cost.rung == "rayleigh")]
        row["error at 20% Rayleigh"] = rayleigh.err_max.max() if rayleigh.status.eq("ok").all() else np.nan
        out.append(row)
    return pd.DataFrame(out)


def per_impact(level):
    """Seconds per impact of one rung over its e_n: the impacts' modelled times (s_per_impact) averaged."""
    if "s_per_impact" not in level or not np.isfinite(level.s_per_impact).all():
        return np.nan
    return float((level.s_per_impact * level.impacts).sum() / level.impacts.sum())


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


def verdict(cost):
    """For the paper scheme and each engine: time per impact-step, and per tolerance of 1% and 0.1% the steps per
    contact (worst metric, every e_n and every finer rung too) and the time per impact, and that time as a multiple of
    the paper scheme's."""
    rec = recommendations(cost)
    if rec.empty:
        return pd.DataFrame()
    curves = rec[(rec.engine != "reference") | (rec.dialect == "paper")].set_index(["engine", "dialect"])
    steps = step_times(cost).set_index(["engine", "dialect"])
    out = []
    for (engine, dialect), row in curves.iterrows():
        line = {"engine": engine if engine != "reference" else "paper scheme",
                "s/impact-step": steps.s_per_impact_step.get((engine, dialect), np.nan),
                "timing": steps.timing.get((engine, dialect), NOT_RESOLVED)}
        for key in ("1%", "0.1%"):
            paper = curves.loc[("reference", "paper"), f"time/impact for {key} [s]"] \
                if ("reference", "paper") in curves.index else np.nan
            mine = row[f"time/impact for {key} [s]"]
            line[f"steps/contact for {key}"] = row[f"steps/contact for {key}"]
            line[f"s/impact for {key}"] = mine
            line[f"x paper for {key}"] = mine / paper if np.isfinite(paper) and paper > 0 else np.nan
        line["20% T_R error"] = row["error at 20% Rayleigh"]
        out.append(line)
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
