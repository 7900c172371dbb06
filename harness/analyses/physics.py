"""The physics verdict: does an engine reproduce the paper law on this scene? Its rows against the paper law's, impact
by impact, on four checks with stated tolerances (rebound velocities, e_n, the Coulomb impulse bound, energy), each
failed check graded by the size of its miss against the tolerance and the share of impacts that fail it, with its
causes and the share of the miss each explains (causes.py)."""
import math
from dataclasses import asdict, dataclass, fields

import numpy as np

from ..infra.errors import UserError
from .causes import EXPLAINS, MENTION, check_causes, phrase
from .misses import IMPACT  # noqa: F401 (the calibration imports it from here)
from .misses import VELOCITIES, coulomb_miss, e_n_miss, energy_miss, velocity_miss, with_paper
from ..infra.wording import counted, more_or_less

REPRODUCES, MARGINAL, DEVIATES, NOT_CHECKED = "reproduces", "marginal", "deviates", "not checked"
MARGINAL_TIMES = 10.0      # a failed check is marginal when its worst miss is at most this many times its tolerance
MARGINAL_SHARE = 0.1       # and at most this share of the impacts fails it; else it deviates
CHECK_WORDS = {"velocity": "rebound velocity", "e_n": "normal restitution", "coulomb": "Coulomb impulse bound",
               "energy": "energy"}

SMALLEST_TOLERANCE = 1e-12        # a tolerance below what double precision resolves in these quantities


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
            if not (math.isfinite(number) and SMALLEST_TOLERANCE <= number < 1e3):
                raise UserError(f"--tolerance {name} must lie in [{SMALLEST_TOLERANCE:g}, 1000) (below, double "
                                f"precision's round-off decides), got {value!r}")
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
    ours = frame[(frame.engine == engine) & (frame.dialect == engine)]
    return with_paper(ours, paper_rows(frame))


def paper_rows(frame):
    """The paper law's rows (the reference's, dialect paper)."""
    return frame[(frame.engine == "reference") & (frame.dialect == "paper")]


def _where(pairs, i):
    return {"e_n_target": float(pairs.e_n_target.iloc[i]), "theta_deg": float(pairs.theta_deg.iloc[i])}


def _at(where):
    return f"e_n {where['e_n_target']:g}, {where['theta_deg']:g} deg"


def grade(worst, tolerance, failing, impacts):
    """marginal when the worst miss is at most MARGINAL_TIMES the tolerance and at most MARGINAL_SHARE of the
    impacts fail; else deviates (a tolerance of 0 makes every miss deviate)."""
    small = tolerance > 0 and worst <= MARGINAL_TIMES * tolerance
    return MARGINAL if small and failing <= MARGINAL_SHARE * impacts else DEVIATES


def severity(record):
    """'126 of 180 impacts, 587x the tolerance'."""
    times = record["times_tolerance"]
    size = "a tolerance of 0" if math.isinf(times) else f"{times:.0f}x" if times >= 100 else f"{times:.2g}x"
    of = "" if math.isinf(times) else " the tolerance"
    return f"{record['failing']} of {counted(record['impacts'], 'impact')}, {size}{of}"


def _check(name, excess, tolerance, pairs, describe, allowance=0.0, brief=None):
    """One check's record from a per-impact measure (NaN where not applicable), its tolerance and a per-impact
    allowance for round-off; `text` says its worst case in a sentence, `short` in a phrase; a failed check its grade
    and the mask of its failing impacts (`failing_at`, dropped from the record once its causes are found)."""
    measured = np.isfinite(excess)
    failing = measured & (excess > tolerance + allowance)
    record = {"check": name, "tolerance": tolerance, "impacts": int(measured.sum()),
              "failing": int(failing.sum()), "passed": not failing.any()}
    if measured.any():
        worst = int(np.nanargmax(excess))
        record.update(worst=float(excess[worst]), row=worst, **_where(pairs, worst))
        record["times_tolerance"] = record["worst"] / tolerance if tolerance > 0 else math.inf
        record["text"] = describe(worst) + (f"; {severity(record)}" if failing.any() else "")
        none = f"0 of {counted(record['impacts'], 'impact')}"
        record["short"] = (f"{brief(worst)} at {_at(_where(pairs, worst))} ("
                           + (severity(record) if failing.any() else none) + ")")
    if failing.any():
        record["grade"] = grade(record["worst"], tolerance, record["failing"], record["impacts"])
        record["failing_at"] = failing
    return record


def velocity_check(pairs, tolerance):
    """max over v_n1, v_t1 and R omega1 of |engine - paper| / V."""
    excess, metric_of, relative = velocity_miss(pairs)
    scales = {m: s for m, _, s in VELOCITIES}

    def describe(i):
        metric = metric_of[i]
        unit = {m: u for m, u, _ in VELOCITIES}[metric]
        return (f"{metric} {pairs[metric].iloc[i]:.4g} {unit} where the paper law gives "
                f"{pairs[metric + '_paper'].iloc[i]:.4g} ({relative[metric][i]:+.2%} of {scales[metric]}) at "
                f"{_at(_where(pairs, i))}")
    record = _check("velocity", excess, tolerance, pairs, describe,
                    brief=lambda i: f"{metric_of[i]} {relative[metric_of[i]][i]:+.2%} of {scales[metric_of[i]]}")
    if "worst" in record:
        record["metric"] = metric_of[int(np.nanargmax(excess))]
    return record


def e_n_check(pairs, tolerance):
    """|e_n - the paper law's e_n at the same impact|, at every angle of the sweep."""
    def describe(i):
        return (f"rebounds at e_n {pairs.e_n.iloc[i]:.4g} where the paper law gives {pairs.e_n_paper.iloc[i]:.4g} "
                f"(target {pairs.e_n_target.iloc[i]:g}, {pairs.theta_deg.iloc[i]:g} deg)")
    return _check("e_n", e_n_miss(pairs), tolerance, pairs, describe,
                  brief=lambda i: f"e_n {pairs.e_n.iloc[i]:.3g} for the paper law's {pairs.e_n_paper.iloc[i]:.3g}")


def coulomb_check(pairs, tolerance, gravity=0.0):
    """Coulomb's bound both ways: |J_t| / (mu J_n) - 1 where mu > 0, and, where the paper law slides throughout,
    1 - |J_t| / (mu J_n) too (misses.coulomb_miss); the invariants' round-off allowance at tiny mu added."""
    excess, ratio, allowance, slides = coulomb_miss(pairs, tolerance, gravity)

    def describe(i):
        if ratio[i] < 1.0:
            where = " where the paper law slides throughout" if slides[i] else ""
            return (f"tangential impulse {ratio[i]:.4g} x mu J_n{where} ({1.0 - ratio[i]:.3g} below Coulomb's bound) "
                    f"at {_at(_where(pairs, i))}")
        return (f"tangential impulse {ratio[i]:.4g} x mu J_n ({ratio[i] - 1.0:.3g} beyond Coulomb's bound) "
                f"at {_at(_where(pairs, i))}")
    return _check("coulomb", excess, tolerance, pairs, describe, allowance,
                  brief=lambda i: f"|J_t| {ratio[i]:.4g} mu J_n")


def energy_check(pairs, tolerance):
    """max(KE1/KE0, (KE_t1 + KE_r1)/(KE_t0 + KE_r0)) - 1: a contact can only take energy out."""
    excess, total, tangential = energy_miss(pairs)

    def describe(i):
        which = "tangential and rotational" if tangential[i] > total[i] else "total"
        return (f"ends with {more_or_less(100.0 * excess[i], '%')} {which} kinetic energy than it began with at "
                f"{_at(_where(pairs, i))}")
    return _check("energy", excess, tolerance, pairs, describe, brief=lambda i: f"energy gain {excess[i]:.3g}")


def explained(check, pairs, frame, attribution, rows, tolerances, gravity):
    """The check's causes (causes.check_causes at its failing impacts), and `cause` and `ingredient`: them in a
    sentence and in a phrase (neither without an attribution)."""
    found = check_causes(check["check"], pairs[check.pop("failing_at")], attribution, rows, paper_rows(frame),
                         tolerances, gravity)
    check["causes"] = found
    if attribution is None or rows is None:
        return
    over = f"over the {check['failing']} failing impact{'' if check['failing'] == 1 else 's'}"
    if not found:
        check["ingredient"] = ""
        check["cause"] = f"no ingredient alone or in a pair closes {MENTION:.0%} of the miss {over}"
        return
    check["ingredient"] = phrase(found, "brief")
    rest = "" if any(c["explains"] for c in found) else \
        f"; none explains {EXPLAINS:.0%} of it, alone or the strongest with another"
    check["cause"] = f"switched to the paper's, each closes this share of the miss {over}: {phrase(found)}{rest}"


def engine_physics(frame, engine, tolerances=Tolerances(), attribution=None, gravity=0.0, rows=None):
    """{state, impacts, checks, failing, reason}: reproduces when every check passes on every impact compared;
    marginal or deviates (the worst grade of its failed checks) with the failed checks (worst case, grade, causes
    from the attribution `attribution` and its rows of every impact `rows`); not checked when no impact pairs."""
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
        check.pop("row", None)
        if not check["passed"]:
            explained(check, pairs, frame, attribution, rows, tolerances, gravity)
    failing = sorted((c for c in checks if not c["passed"]), key=lambda c: -c["worst"] / max(c["tolerance"], 1e-300))
    state = (REPRODUCES if not failing else DEVIATES if any(c["grade"] == DEVIATES for c in failing) else MARGINAL)
    return {"state": state, "impacts": len(pairs), "checks": checks,
            "failing": [c["check"] for c in failing], "reason": "; ".join(c["text"] for c in failing)}


def overall(states):
    """deviates if any engine deviates, else marginal if any is marginal, reproduces if every engine checked
    reproduces, else not checked."""
    for state in (DEVIATES, MARGINAL):
        if state in states:
            return state
    return REPRODUCES if REPRODUCES in states else NOT_CHECKED
