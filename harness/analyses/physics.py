"""The physics verdict: does an engine reproduce the paper law on this scene? Its rows against the paper law's, impact
by impact, on four checks with stated tolerances: rebound velocities, e_n, the Coulomb impulse bound, energy."""
import math
from dataclasses import asdict, dataclass, fields

import numpy as np

from ..errors import UserError
from ..wording import counted, more_or_less
from .findings import tangential_energy_ratio
from .invariants import FRICTIONLESS_TOLERANCE, coulomb_impulses

REPRODUCES, DEVIATES, NOT_CHECKED = "reproduces", "deviates", "not checked"
IMPACT = ["model", "e_n_target", "theta_deg", "v_n0", "v_t0", "omega0", "mu", "radius", "E", "nu", "rho"]
VELOCITIES = (("v_n1", "m/s", "V"), ("v_t1", "m/s", "V"), ("omega1", "rad/s", "V/R"))
CHECK_WORDS = {"velocity": "rebound velocity", "e_n": "normal restitution", "coulomb": "Coulomb impulse bound",
               "energy": "energy"}
ATTRIBUTED = {"v_n1": "v_n1", "v_t1": "v_t1", "omega1": "omega1", "e_n": "e_n", "coulomb": "coulomb_ratio",
              "energy": "ke_ratio"}     # what a check's worst case is, as an attribution metric


@dataclass(frozen=True)
class Tolerances:
    """How close an engine must come to the paper law to reproduce it."""
    velocity: float = 0.01      # |engine - paper| of v_n1, v_t1 and R omega1, as a fraction of the incident speed V
    e_n: float = 0.01           # |e_n - the paper law's e_n at the same impact|, absolute
    coulomb: float = 1e-3       # |J_t| <= mu J_n (1 + this): Coulomb's |F_t| <= mu F_n integrated over the contact
    energy: float = 1e-6        # KE1 <= KE0 (1 + this), in all and in the tangential + rotational motion

    @classmethod
    def of(cls, given=None):
        """From {name: value} or ["name=value", ...] (the CLI's --tolerance); unknown names or values: UserError."""
        if isinstance(given, cls):
            return given
        pairs = given.items() if isinstance(given, dict) else [_split(text) for text in (given or ())]
        names = [f.name for f in fields(cls)]
        values = {}
        for name, value in pairs:
            if name not in names:
                raise UserError(f"--tolerance takes {', '.join(names)}, got {name!r}")
            if name in values:
                raise UserError(f"--tolerance {name}=... given twice")
            try:
                number = float(value)
            except (TypeError, ValueError):
                raise UserError(f"--tolerance {name} must be a number, got {value!r}") from None
            if not (math.isfinite(number) and 0.0 <= number < 1e3):
                raise UserError(f"--tolerance {name} must lie in [0, 1000), got {value!r}")
            values[name] = number
        return cls(**values)

    def describe(self):
        """The tolerances in words, as every view prints them."""
        return (f"rebound velocities within {100 * self.velocity:.3g}% of V, e_n within {self.e_n:.3g}, "
                f"|J_t| <= mu J_n (= where the paper law slides) within {100 * self.coulomb:.3g}%, energy gain at "
                f"most {self.energy:.3g} KE0")

    def as_dict(self):
        return asdict(self)


def _split(text):
    name, sep, value = str(text).partition("=")
    if not sep:
        raise UserError(f"--tolerance takes NAME=VALUE, got {text!r}")
    return name.strip(), value.strip()


def paired(frame, engine):
    """The engine's ok rows (its own dialect) beside the paper law's rows of the same impacts (suffix _paper)."""
    ours = frame[(frame.engine == engine) & (frame.dialect == engine) & (frame.status == "ok")]
    paper = frame[(frame.engine == "reference") & (frame.dialect == "paper") & (frame.status == "ok")]
    paper = paper[IMPACT + ["v_n1", "v_t1", "omega1", "e_n"]]
    return ours.merge(paper, on=IMPACT, suffixes=("", "_paper")).reset_index(drop=True)


def _where(pairs, i):
    return {"e_n_target": float(pairs.e_n_target.iloc[i]), "theta_deg": float(pairs.theta_deg.iloc[i])}


def _at(where):
    return f"e_n {where['e_n_target']:g}, {where['theta_deg']:g} deg"


def _check(name, excess, tolerance, pairs, describe, allowance=0.0, brief=None):
    """One check's record from a per-impact measure (NaN where not applicable), its tolerance and a per-impact
    allowance for round-off; `text` says its worst case in a sentence, `short` in a phrase."""
    measured = np.isfinite(excess)
    failing = measured & (excess > tolerance + allowance)
    record = {"check": name, "tolerance": tolerance, "impacts": int(measured.sum()),
              "failing": int(failing.sum()), "passed": not failing.any()}
    if measured.any():
        worst = int(np.nanargmax(excess))
        record.update(worst=float(excess[worst]), row=worst, **_where(pairs, worst))
        of_all = f"{record['failing']} of {counted(record['impacts'], 'impact')}"
        record["text"] = describe(worst) + (f"; {of_all} beyond the tolerance" if failing.any() else "")
        record["short"] = f"{brief(worst)} at {_at(_where(pairs, worst))} ({of_all})"
    return record


def velocity_check(pairs, tolerance):
    """max over v_n1, v_t1 and R omega1 of |engine - paper| / V."""
    speed = np.hypot(pairs.v_n0, pairs.v_t0).to_numpy(dtype=float)
    radius = pairs.radius.to_numpy(dtype=float)
    relative = {metric: (pairs[metric] - pairs[metric + "_paper"]).to_numpy(dtype=float)
                * (radius if metric == "omega1" else 1.0) / speed for metric, _, _ in VELOCITIES}
    stacked = np.abs(np.vstack(list(relative.values())))
    excess = np.fmax.reduce(stacked, axis=0)
    metric_of = [VELOCITIES[j][0] for j in np.argmax(np.nan_to_num(stacked, nan=-1.0), axis=0)]

    def describe(i):
        metric = metric_of[i]
        unit, scale = {m: (u, s) for m, u, s in VELOCITIES}[metric]
        return (f"{metric} {pairs[metric].iloc[i]:.4g} {unit} where the paper law gives "
                f"{pairs[metric + '_paper'].iloc[i]:.4g} ({relative[metric][i]:+.2%} of {scale}) at "
                f"{_at(_where(pairs, i))}")
    record = _check("velocity", excess, tolerance, pairs, describe,
                    brief=lambda i: f"{metric_of[i]} {relative[metric_of[i]][i]:+.2%} of "
                                    f"{dict((m, s) for m, _, s in VELOCITIES)[metric_of[i]]}")
    if "worst" in record:
        record["metric"] = metric_of[int(np.nanargmax(excess))]
    return record


def e_n_check(pairs, tolerance):
    """|e_n - the paper law's e_n at the same impact|, at every angle of the sweep."""
    excess = np.abs(pairs.e_n - pairs.e_n_paper).to_numpy(dtype=float)

    def describe(i):
        return (f"rebounds at e_n {pairs.e_n.iloc[i]:.4g} where the paper law gives {pairs.e_n_paper.iloc[i]:.4g} "
                f"(target {pairs.e_n_target.iloc[i]:g}, {pairs.theta_deg.iloc[i]:g} deg)")
    return _check("e_n", excess, tolerance, pairs, describe,
                  brief=lambda i: f"e_n {pairs.e_n.iloc[i]:.3g} for the paper law's {pairs.e_n_paper.iloc[i]:.3g}")


def coulomb_check(pairs, tolerance, gravity=0.0):
    """Coulomb's bound both ways: |J_t| / (mu J_n) - 1 where mu > 0, and, where the paper law slides throughout
    (its |J_t| = mu J_n within the tolerance, without gravity), 1 - |J_t| / (mu J_n) too; the invariants' round-off
    allowance at tiny mu (1e-6 V) added."""
    j_t, mu_j_n = coulomb_impulses(pairs, gravity)
    speed = np.hypot(pairs.v_n0, pairs.v_t0).to_numpy(dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        ratio = np.where(mu_j_n > 0, j_t / mu_j_n, np.nan)
        paper = (np.abs(pairs.v_t1_paper - pairs.v_t0) / (pairs.mu * (pairs.v_n0 + pairs.v_n1_paper))).to_numpy()
        slides = (np.abs(paper - 1.0) <= tolerance) & (gravity == 0.0)
        excess = np.where(slides, np.abs(ratio - 1.0), ratio - 1.0)
        allowance = np.where(mu_j_n > 0, FRICTIONLESS_TOLERANCE * speed / mu_j_n, 0.0)

    def describe(i):
        if ratio[i] < 1.0:
            where = " where the paper law slides throughout" if slides[i] else ""
            return (f"tangential impulse {ratio[i]:.4g} x mu J_n{where} ({1.0 - ratio[i]:.3g} below Coulomb's bound) "
                    f"at {_at(_where(pairs, i))}")
        return (f"tangential impulse {ratio[i]:.4g} x mu J_n ({ratio[i] - 1.0:.3g} beyond Coulomb's bound) "
                f"at {_at(_where(pairs, i))}")
    record = _check("coulomb", excess, tolerance, pairs, describe, allowance,
                    brief=lambda i: f"|J_t| {ratio[i]:.4g} mu J_n")
    if "row" in record:
        record["towards"] = 1.0 if ratio[record["row"]] < 1.0 else -1.0     # the ratio's way to the paper law
    return record


def energy_check(pairs, tolerance):
    """max(KE1/KE0, (KE_t1 + KE_r1)/(KE_t0 + KE_r0)) - 1: a contact can only take energy out."""
    total = pairs.ke_ratio.to_numpy(dtype=float)
    tangential = tangential_energy_ratio(pairs).to_numpy(dtype=float)
    excess = np.fmax(total, tangential) - 1.0

    def describe(i):
        which = "tangential and rotational" if tangential[i] > total[i] else "total"
        return (f"ends with {more_or_less(100.0 * excess[i], '%')} {which} kinetic energy than it began with at "
                f"{_at(_where(pairs, i))}")
    return _check("energy", excess, tolerance, pairs, describe, brief=lambda i: f"energy gain {excess[i]:.3g}")


def ingredient(attribution, metric, towards):
    """(sentence, phrase): the sub-model whose switch to the paper's alone moves `metric` furthest towards the paper
    law (attribution table; `towards` the sign of paper - engine); empty without an attribution."""
    name = ATTRIBUTED.get(metric, metric)
    column = f"d_{name}"
    if attribution is None or attribution.empty or column not in attribution.columns:
        return "", ""
    closing = attribution[column] * towards
    if not (closing > 0).any():
        return f"no single ingredient moves {name} towards the paper law alone (their effects combine)", ""
    row = attribution.loc[closing.idxmax()]
    return (f"{row.ingredient} ({row.dialect} in the engine, {row.target} in the paper law) alone moves {name} "
            f"towards the paper law by up to {abs(row[column]):.3g}{UNITS.get(name, '')}",
            f"{row.ingredient} ({row.dialect} -> {row.target})")


UNITS = {"v_n1": " m/s", "v_t1": " m/s", "omega1": " rad/s", "coulomb_ratio": " mu J_n", "ke_ratio": " KE0"}


def engine_physics(frame, engine, tolerances=Tolerances(), attribution=None, gravity=0.0):
    """{state, impacts, checks, failing, reason}: reproduces when every check passes on every impact compared;
    deviates with the failed checks (worst case, where, attributed ingredient); not checked when no impact pairs."""
    pairs = paired(frame, engine)
    if pairs.empty:
        ran = ((frame.engine == engine) & (frame.status == "ok")).any()
        has_paper = ((frame.engine == "reference") & (frame.dialect == "paper")).any()
        reason = ("no impact of the engine ran" if not ran else "the paper law was not run" if not has_paper
                  else "no impact of the engine matches one of the paper law")
        return {"state": NOT_CHECKED, "impacts": 0, "checks": [], "failing": [], "reason": reason}
    checks = [velocity_check(pairs, tolerances.velocity), e_n_check(pairs, tolerances.e_n),
              coulomb_check(pairs, tolerances.coulomb, gravity), energy_check(pairs, tolerances.energy)]
    for check in checks:
        if not check["passed"]:
            metric = check.get("metric", check["check"])
            towards = check.pop("towards", -1.0) if metric in ("coulomb", "energy") else float(np.sign(
                pairs.loc[check["row"], metric + "_paper"] - pairs.loc[check["row"], metric]))
            check["cause"], check["ingredient"] = ingredient(attribution, metric, towards)
    for check in checks:
        check.pop("row", None)
        check.pop("towards", None)
    failing = sorted((c for c in checks if not c["passed"]), key=lambda c: -c["worst"] / max(c["tolerance"], 1e-300))
    return {"state": DEVIATES if failing else REPRODUCES, "impacts": len(pairs), "checks": checks,
            "failing": [c["check"] for c in failing], "reason": "; ".join(c["text"] for c in failing)}


def overall(states):
    """deviates if any engine deviates, reproduces if every engine checked reproduces, else not checked."""
    if DEVIATES in states:
        return DEVIATES
    return REPRODUCES if REPRODUCES in states else NOT_CHECKED
