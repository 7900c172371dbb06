"""What a tolerance costs per curve of the cost study: the coarsest rung from which on every rung meets it (measured),
else the rung its measured order of convergence gives (extrapolated), else why there is no number; for an engine
beyond its ladder, its formulas' rungs when it computes them (its errors equal theirs on every rung it ran)."""
import math
from dataclasses import dataclass, replace

import numpy as np
import pandas as pd

from .agreement import AGREEMENT_TOLERANCE
from .cost import NOT_RESOLVED, TOLERANCES, TRUTH_LEVEL, VELOCITIES, step_times

BRACKET = 5.0            # met at n, missed at the next coarser rung m: n is the answer when n/m <= this (the ladder's
MIN_ORDER = 0.5          # widest step); an order is resolved when the last two local orders are above this (the
ORDER_SPREAD = 0.25      # schemes are first order or better) and differ by at most this fraction of the larger
RESOLVED_ABOVE = 10.0    # its rungs' errors at least this many times their truth's uncertainty


@dataclass(frozen=True)
class Answer:
    """Steps per contact for a tolerance (NaN: none), the time step, impact-steps per impact there, and how it was
    found: '' measured on the curve's rungs, 'formulas' on its formulas' rungs beyond its ladder, 'extrapolated',
    'at most' (met there, missed at a rung more than BRACKET coarser, the order between unresolved), or 'none'; `note`
    the sentence that says so."""
    steps: float
    dt: float = np.nan
    steps_per_impact: float = np.nan
    how: str = "none"
    note: str = ""


def key(tol):
    """1% / 0.1% / 0.01%: a tolerance as the tables name it."""
    return f"{tol:.0%}" if tol >= 0.01 else f"{tol * 100:g}%"


def levels(cost, engine, dialect):
    """(levels, agreement) of a curve: its rungs that answer a tolerance, ascending in steps per contact, one row each
    over its e_n (worst error, its truth's uncertainty, every e_n ok, smallest dt, impact-steps per impact), from its
    ladder and the levels of its converged reference; for an engine, its own, then (`borrowed`) its formulas' levels
    beyond its ladder when its velocity errors equal its formulas' within AGREEMENT_TOLERANCE of V on every rung
    both ran. `agreement`: that largest difference (NaN: none measured)."""
    own = _per_level(cost[(cost.engine == engine) & (cost.dialect == dialect)]).assign(borrowed=False)
    if engine == "reference" or own.empty:
        return own, np.nan
    formulas = cost[(cost.engine == "reference") & (cost.dialect == dialect)]
    gap = _gap(cost[(cost.engine == engine) & (cost.dialect == dialect)], formulas)
    if not gap <= AGREEMENT_TOLERANCE:
        return own, gap
    beyond = _per_level(formulas)
    beyond = beyond[beyond.n > own.n.max()].assign(borrowed=True)
    return pd.concat([own, beyond], ignore_index=True), gap


def _per_level(curve):
    rung = curve.rung.astype(str)
    curve = curve[rung.str.fullmatch(r"\d+") | rung.str.startswith(TRUTH_LEVEL)]
    rows = []
    for label, level in curve.groupby("rung", sort=False):
        ok = level.status.eq("ok").all()
        rows.append({"rung": label, "n": float(label.removeprefix(TRUTH_LEVEL)), "ok": ok,
                     "ladder": not label.startswith(TRUTH_LEVEL),
                     "err": float(level.err_max.max()) if ok else np.nan,
                     "truth": float(level.err_truth.fillna(0.0).max()), "dt": float(level.dt.min()),
                     "per_impact": float(level.steps.sum() / level.impacts.sum()) if ok else np.nan})
    return pd.DataFrame(rows, columns=["rung", "n", "ok", "ladder", "err", "truth", "dt", "per_impact"]).sort_values(
        "n", ignore_index=True)


def _gap(engine_rows, formulas):
    """The largest difference of the engine's velocity errors from its formulas' on the ladder rungs both ran (NaN:
    none)."""
    columns = [f"err_{m}" for m in VELOCITIES]
    both = engine_rows.merge(formulas, on=["rung", "e_n_target"], suffixes=("", "_formulas"))
    both = both[both.rung.astype(str).str.fullmatch(r"\d+") & both.status.eq("ok") & both.status_formulas.eq("ok")]
    if both.empty:
        return np.nan
    return max(float(np.nanmax(np.abs(both[c] - both[f"{c}_formulas"]))) for c in columns)


def answer(curve, tol, agreement=np.nan):
    """The Answer for `tol` from a curve's levels (levels()): the coarsest level from which on every level meets it
    with its truth's uncertainty added; else the order of the ladder's finest rungs, extrapolated; else the reason.
    `agreement`: the engine's velocity errors' largest difference from its formulas' (levels())."""
    ran = curve[curve.ok]
    if ran.empty:
        return Answer(np.nan, note="no rung ran")
    uncertain = float(ran.truth.max())
    if uncertain >= tol:
        return Answer(np.nan, note=f"not priced: its converged reference is uncertain by {uncertain:.1e}")
    meets = (curve.ok & (curve.err + curve.truth <= tol)).to_numpy()
    first = next((i for i in range(len(meets)) if meets[i:].all()), None)
    order, orders_said = _order(curve)
    if first == len(curve) - 1 and not curve.ladder.iloc[first]:        # the truth itself: no error by definition
        return Answer(np.nan, note=f"not priced: met only by its converged reference itself, "
                                   f"{curve.n.iloc[first]:.0f} steps/contact, uncertain by {uncertain:.1e}")
    if first is not None:
        chosen = curve.iloc[first]
        missed = curve.n.iloc[first - 1] if first > 0 else None
        how = "formulas" if chosen.borrowed else ""
        said = (f"measured on its formulas in the reference beyond its ladder (it computes them: its velocity errors "
                f"equal theirs to {agreement:.0e} of V on every rung it ran)" if chosen.borrowed else "")
        if missed is None or chosen.n / missed <= BRACKET:
            return Answer(chosen.n, chosen["dt"], chosen.per_impact, how, said)
        projected = _extrapolated(curve, tol, order)
        if projected is not None and missed < projected.steps <= chosen.n:
            return replace(projected, note=f"{projected.note}, between {missed:.0f} (missed) and {chosen.n:.0f} (met)")
        return Answer(chosen.n, chosen["dt"], chosen.per_impact, "at most",
                      f"met there and missed at {missed:.0f}, not measured between; {orders_said}")
    projected = _extrapolated(curve, tol, order)
    if projected is not None:
        return replace(projected, note=f"{projected.note}, beyond its finest rung")
    unused = (f"; its formulas' rungs beyond its ladder not used: its velocity errors differ from theirs by "
              f"{agreement:.1e} of V" if agreement > AGREEMENT_TOLERANCE else "")
    return Answer(np.nan, note=f"not within {curve.n.iloc[-1]:.0f} steps/contact, and not extrapolated: "
                               f"{orders_said}{unused}")


def _order(curve):
    """(order, what was found) from the last three ladder rungs of the curve itself whose errors stand
    RESOLVED_ABOVE their truth's uncertainty: the least-squares slope, when both local orders exceed MIN_ORDER and
    agree within ORDER_SPREAD; else (NaN, why)."""
    own = curve[curve.ok & curve.ladder & ~curve.borrowed & (curve.err > RESOLVED_ABOVE * curve.truth)
                & (curve.err > 0)]
    if len(own) < 3:
        return np.nan, f"its order is not resolved: fewer than 3 rungs above {RESOLVED_ABOVE:g}x its truth's " \
                       f"uncertainty"
    last = own.iloc[-3:]
    n, err = np.log(last.n.to_numpy()), np.log(last.err.to_numpy())
    local = -np.diff(err) / np.diff(n)
    said = (f"local orders {local[0]:.2f} and {local[1]:.2f} over {last.n.iloc[0]:.0f}..{last.n.iloc[-1]:.0f} "
            f"steps/contact")
    if local.min() < MIN_ORDER or abs(local[0] - local[1]) > ORDER_SPREAD * local.max():
        return np.nan, f"its order is not resolved: {said} (resolved: both above {MIN_ORDER:g}, within " \
                       f"{ORDER_SPREAD:.0%})"
    return float(-np.polyfit(n, err, 1)[0]), said


def _extrapolated(curve, tol, order):
    """The Answer where the error of the curve's finest own ladder rung, falling at `order`, meets tol less the
    truth's uncertainty; None without an order."""
    if not np.isfinite(order):
        return None
    own = curve[curve.ok & curve.ladder & ~curve.borrowed]
    finest = own.iloc[-1]
    room = tol - float(curve.truth.max())
    steps = math.ceil(finest.n * (finest.err / room) ** (1.0 / order))
    return Answer(steps, finest["dt"] * finest.n / steps, finest.per_impact * steps / finest.n, "extrapolated",
                         f"extrapolated from {finest.n:.0f} steps/contact ({finest.err:.1e}) at its measured order "
                         f"{order:.2f}")


def answers(cost):
    """{(engine, dialect): {tol: Answer}} for every curve with rungs of steps per contact."""
    out = {}
    rung = cost.rung.astype(str)
    for (engine, dialect), _ in cost[rung.str.fullmatch(r"\d+")].groupby(["engine", "dialect"], sort=False):
        curve, agreement = levels(cost, engine, dialect)
        out[(engine, dialect)] = {tol: answer(curve, tol, agreement) for tol in TOLERANCES}
    return out


def notes(answered, tolerances=TOLERANCES, verdict_only=False):
    """The sentences of the answers not plainly measured on a curve's own rungs, one per curve and sentence with
    the tolerances it answers: 'lammps 1% and 0.1%: 524288 steps/contact measured ...'; `verdict_only`: the curves
    of the verdict (the paper scheme and the engines)."""
    out = []
    for (engine, dialect), per_tol in answered.items():
        if verdict_only and engine == "reference" and dialect != "paper":
            continue
        name = engine if engine != "reference" else ("the paper scheme" if dialect == "paper"
                                                      else f"{dialect} in the reference")
        said = {}
        for tol in tolerances:
            a = per_tol[tol]
            if a.note:
                steps = ("" if a.steps != a.steps else f"at most {a.steps:.0f} steps/contact, " if a.how == "at most"
                         else f"{a.steps:.0f} steps/contact ")
                said.setdefault(steps + a.note, []).append(key(tol))
        out += [f"{name} {' and '.join(keys)}: {note}" for note, keys in said.items()]
    return out


MARKS = {"formulas": "f", "extrapolated": "~", "at most": "<="}


def steps_text(steps, how):
    """An Answer's steps per contact as the tables show them: 'f' after a number measured on an engine's formulas
    beyond its ladder, '~' before an extrapolated one, '<=' before a bound, '-' for none."""
    if how == "none" or steps != steps:
        return "-"
    mark = MARKS.get(how, "")
    return f"{steps:.0f}{mark}" if how == "formulas" else f"{mark}{steps:.0f}"


def recommendations(cost, answered=None):
    """Per curve (engine, dialect) and tolerance: the time step and steps per contact of its Answer, how it was
    found, and the time per impact there (impact-steps per impact x the curve's time per impact-step); the error a
    time step of 20% of the Rayleigh time gives."""
    answered = answers(cost) if answered is None else answered
    times = step_times(cost).set_index(["engine", "dialect"]).s_per_impact_step
    times = times[~times.index.duplicated()]
    out = []
    for (engine, dialect), per_tol in answered.items():
        row = {"engine": engine, "dialect": dialect}
        step_s = times.get((engine, dialect), np.nan)
        for tol, a in per_tol.items():
            row[f"dt for {key(tol)} [s]"] = a.dt
            row[f"steps/contact for {key(tol)}"] = a.steps
            row[f"how for {key(tol)}"] = a.how
            row[f"time/impact for {key(tol)} [s]"] = step_s * a.steps_per_impact
        rayleigh = cost[(cost.engine == engine) & (cost.dialect == dialect) & (cost.rung == "rayleigh")]
        row["error at 20% Rayleigh"] = rayleigh.err_max.max() if rayleigh.status.eq("ok").all() else np.nan
        out.append(row)
    return pd.DataFrame(out)


def verdict(cost, found=None):
    """For the paper scheme and each engine: time per impact-step, its truth's uncertainty, and per tolerance of 1%
    and 0.1% the steps per contact (Answer), how they were found, the time per impact there and that time as a
    multiple of the paper scheme's; the error of 20% of the Rayleigh time."""
    rec = recommendations(cost, found)
    if rec.empty:
        return pd.DataFrame()
    curves = rec[(rec.engine != "reference") | (rec.dialect == "paper")].set_index(["engine", "dialect"])
    steps = step_times(cost).set_index(["engine", "dialect"])
    truth = cost.groupby(["engine", "dialect"]).err_truth.max()
    out = []
    for (engine, dialect), row in curves.iterrows():
        line = {"engine": engine if engine != "reference" else "paper scheme",
                "s/impact-step": steps.s_per_impact_step.get((engine, dialect), np.nan),
                "timing": steps.timing.get((engine, dialect), NOT_RESOLVED),
                "truth uncertainty": truth.get((engine, dialect), np.nan)}
        for tol in TOLERANCES[:2]:
            paper = curves.loc[("reference", "paper"), f"time/impact for {key(tol)} [s]"] \
                if ("reference", "paper") in curves.index else np.nan
            mine = row[f"time/impact for {key(tol)} [s]"]
            line[f"steps/contact for {key(tol)}"] = row[f"steps/contact for {key(tol)}"]
            line[f"how for {key(tol)}"] = row[f"how for {key(tol)}"]
            line[f"s/impact for {key(tol)}"] = mine
            line[f"x paper for {key(tol)}"] = mine / paper if np.isfinite(paper) and paper > 0 else np.nan
        line["20% T_R error"] = row["error at 20% Rayleigh"]
        out.append(line)
    return pd.DataFrame(out)
