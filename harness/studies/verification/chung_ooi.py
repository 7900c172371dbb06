"""Chung & Ooi (2011, Granular Matter 13:643)'s eight tests graded on the reference and on each engine that can
express them: every measured quantity beside its closed form at the suite's own values (e, mu, speeds), the error,
the tolerance and, where a check fails, what the measurement says caused it (docs/chung-ooi.md).

The law is Hertz-Mindlin (the suite's); a wall is rigid. A quantity without a closed form (the stick regime of tests
4-8) is reported, unchecked."""
import math
from dataclasses import replace

import pandas as pd
from scipy.integrate import quad

from ...engines import ENGINES
from ...infra.errors import UserError
from ...runs.execute import run_all
from ...laws import compose
from ...solver.resolution import FixedTimeStep
from ...runs.plan import engine_runs, reference_runs
from ...solver.two_spheres import with_bodies
from ...infra.wording import counted
from .chung_ooi_cases import cases, published_e

LAW = "hertz-mindlin"
HERTZ_TOLERANCE = 1e-3       # relative: peak force, peak overlap, duration against Hertz (the suite's 0.1%)
RESTITUTION_TOLERANCE = 1e-3  # absolute: e_out against e_in (test 3), the achieved e_n against the suite's e
SLIDING_TOLERANCE = 1e-3     # relative to the incident speed: the gross-sliding lines (tests 4-8)
KRATOS_TOLERANCE = 0.05     # Kratos' DEM benchmarks: a curve passes when sum|DEM - expected|/sum|expected| < 5%
GROSS_SLIDING_PSI = 7.5      # |Psi1*| above which Hertz-Mindlin slides throughout (rigid body: 7; with a margin)
NO_SLIP = 1e-12              # |V_s0| / V at or below which nothing slides at first touch (test 7)
DAMPING = {   # a dialect's damping label -> what returns its e_n
    "tsuji:appendix-b": "the App. B damping fit of Thornton et al. (2013)",
    "tsuji:polynomial": "LAMMPS' Tsuji polynomial in e",
    "tsuji:tension": "the Tsuji damping calibrated for a contact ending at zero overlap",
    "tsuji:exact": "the exact Tsuji calibration",
}
COLUMNS = ("test", "engine", "case", "quantity", "value", "expected", "error", "tolerance", "passed", "note")


def hertz(case):
    """Hertz (1882) at approach speed V: alpha_max = (15 m* V^2/(16 E* R*^1/2))^2/5, F_max = 4/3 E* R*^1/2
    alpha_max^3/2, t_c = 2 alpha_max/V int_0^1 dx/sqrt(1 - x^5/2) (= 2.94 alpha_max/V)."""
    scene = case.effective_scene
    contact = scene.contact
    alpha = (15.0 * contact.mass * scene.speed ** 2 / (16.0 * contact.E_star * math.sqrt(contact.radius))) ** 0.4
    force = 4.0 / 3.0 * contact.E_star * math.sqrt(contact.radius) * alpha ** 1.5
    duration = 2.0 * alpha / scene.speed * quad(lambda x: 1.0 / math.sqrt(1.0 - x ** 2.5), 0.0, 1.0)[0]
    return {"f_n_max": force, "overlap_max": alpha, "t_contact": duration}


def row(case, engine, quantity, value, expected=math.nan, scale=math.nan, tolerance=math.nan, note="", cause=""):
    """One checked (or, without `expected`, reported) quantity; the error is |value - expected| / scale, and a check
    without a finite value fails; a failed check's note ends with its cause."""
    checked = math.isfinite(expected)
    error = abs(value - expected) / scale if checked else math.nan
    passed = (bool(error <= tolerance) if math.isfinite(error) else False) if checked else None
    if passed is False and cause:
        note = f"{note}; fails: {cause}"
    return {"test": case.test, "engine": engine, "case": case.label, "quantity": quantity, "value": float(value),
            "expected": expected, "error": error, "tolerance": tolerance if checked else math.nan, "passed": passed,
            "note": note}


def damping_of(engine, case):
    """The words for what sets the rebound e_n in `engine`'s dialect of the law (its damping calibration)."""
    label = ENGINES[engine].dialect(LAW, {}, "wall" if case.target is None else "sphere").describe()["damping"]
    return DAMPING.get(label, f"its damping ({label})")


def restitution(case, engine, table, quantity="e_n achieved"):
    """The impact whose rebound e_n is furthest from the suite's e, against it (test 3: e_out = e_in)."""
    e = published_e(case)
    worst = table.iloc[int((table.e_n - e).abs().fillna(math.inf).to_numpy().argmax())]
    note = "e_out = e_in" if case.test == 3 else f"the suite's e, worst of {counted(len(table), 'impact')}"
    cause = (f"{damping_of(engine, case)} returns e_n {worst.e_n:.4g} for {e:g}" if worst.status == "ok" else
             f"the run's status is {worst.status} ({worst.message})")
    return row(case, engine, quantity, worst.e_n, e, 1.0, RESTITUTION_TOLERANCE, note, cause)


def initial_slip(case, impact):
    """V_s0 = v_t0 - R* omega0 of the equivalent impact, 0 where below NO_SLIP of the incident speed."""
    slip0 = impact.v_t0 - case.effective_scene.contact.radius * impact.omega0
    return 0.0 if abs(slip0) <= NO_SLIP * math.hypot(impact.v_n0, impact.v_t0) else slip0


def sliding_lines(case, impact, j_n):
    """Each checked quantity's rigid-body value when the contact slides throughout: J_t = -mu J_n sign(V_s0) (0
    without slip at first touch); a wall's sphere takes v_t1 = v_t0 + J_t/m, omega1 = omega0 - R J_t/I, two spheres
    each take +-J_t with their own lever and inertia."""
    scene = case.effective_scene
    contact = scene.contact
    slip0 = initial_slip(case, impact)
    j_t = 0.0 if slip0 == 0.0 else -scene.mu * j_n * math.copysign(1.0, slip0)
    if case.target is None:
        return {"v_t1 [m/s]": impact.v_t0 + j_t / contact.mass,
                "omega1 R [m/s]": (impact.omega0 - contact.radius * j_t / contact.inertia) * contact.radius}
    projectile, target = scene.spheres
    moving = 0.0 if target.fixed else 1.0
    return {"v1_t [m/s]": impact.v_t0 + target.v_t + j_t / projectile.mass,
            "omega1 R1 [m/s]": (projectile.omega - projectile.radius * j_t / projectile.inertia) * projectile.radius,
            "v2_t [m/s]": target.v_t - moving * j_t / target.mass,
            "omega2 R2 [m/s]": (target.omega - moving * target.radius * j_t / target.inertia) * target.radius}


def measured(case, impact):
    """The same quantities as simulated."""
    if case.target is None:
        return {"v_t1 [m/s]": impact.v_t1, "omega1 R [m/s]": impact.omega1 * impact.radius}
    projectile, target = case.effective_scene.spheres
    return {"v1_t [m/s]": impact.v1_t, "omega1 R1 [m/s]": impact.omega1_after * projectile.radius,
            "v2_t [m/s]": impact.v2_t, "omega2 R2 [m/s]": impact.omega2_after * target.radius}


def sliding_cause(case, impact, quantity, speed):
    """Why a check of sliding_lines fails, from the impact itself: its status; met at its own rebound e_n (the
    normal impulse is off, not the tangential law); else its tangential impulse against mu times its own normal one
    (or against none, without slip), and whether its e_n is off as well."""
    if impact.status != "ok":
        return f"the run's status is {impact.status} ({impact.message})"
    contact = case.effective_scene.contact
    e = published_e(case)
    j_n = contact.mass * (impact.v_n1 + impact.v_n0)
    lines = sliding_lines(case, impact, j_n)
    off = abs(measured(case, impact)[quantity] - lines[quantity]) / speed
    rebound = f"the impact rebounds at e_n {impact.e_n:.4g}, not the suite's {e:g}"
    if off <= SLIDING_TOLERANCE:
        return f"{rebound}; at its own e_n the line is met to {off:.1e}"
    ratio = abs(contact.mass * (impact.v_t1 - impact.v_t0)) / (case.effective_scene.mu * j_n)
    if initial_slip(case, impact) == 0.0:
        tangential = f"a tangential impulse of {ratio:.3g} mu J_n without slip at first touch"
    elif ratio > 1.0 + SLIDING_TOLERANCE:
        tangential = f"|J_t| = {ratio:.4g} mu J_n: the tangential impulse exceeds the Coulomb bound"
    elif ratio < 1.0 - SLIDING_TOLERANCE:
        tangential = f"|J_t| = {ratio:.4g} mu J_n: the contact does not slide throughout"
    else:
        tangential = f"|J_t| = mu J_n to {abs(ratio - 1.0):.1e}, so the spin's change differs by its lever (not R)"
    return (f"{rebound}, and " if abs(impact.e_n - e) > RESTITUTION_TOLERANCE else "") + tangential


def tangential(case, engine, impact):
    """Each body's rebound tangential velocity and surface speed from spin; where the contact slides throughout at
    the suite's e (|Psi1*| = 2 |V_s0|/(mu (1 + e) V_n) >= GROSS_SLIDING_PSI) or does not slip at all, against the
    rigid-body impulses J_n = m* (1 + e) V_n and J_t of sliding_lines; elsewhere reported without a closed form."""
    scene = case.effective_scene
    contact = scene.contact
    e = published_e(case)
    at = case if case.test not in (4, 5) else replace(case, label=f"{case.label}, theta {impact.theta_deg:.4g} deg")
    speed = math.hypot(impact.v_n0, impact.v_t0)
    slip0 = initial_slip(case, impact)
    psi = 2.0 * abs(slip0) / (scene.mu * (1.0 + e) * impact.v_n0)
    lines = sliding_lines(case, impact, contact.mass * (1.0 + e) * impact.v_n0)
    if slip0 == 0.0:
        note = "no slip at first touch: no tangential impulse"
    elif psi >= GROSS_SLIDING_PSI:
        note = "gross sliding"
    else:
        note, lines = "sticks for part of the contact: no closed form", dict.fromkeys(lines, math.nan)
    return [row(at, engine, quantity, value, lines[quantity], speed, SLIDING_TOLERANCE, note,
                cause=sliding_cause(case, impact, quantity, speed) if math.isfinite(lines[quantity]) else "")
            for quantity, value in measured(case, impact).items()]


def checks(case, engine, table):
    """The rows of one case's results table."""
    if case.test in (1, 2):
        expected = hertz(case)
        impact = table.iloc[0]
        cause = (f"the impact rebounds at e_n {impact.e_n:.6g} ({impact.status}), at "
                 f"{impact.steps_per_contact:.0f} steps per contact")
        return [row(case, engine, f"{quantity} [{unit}]", impact[quantity], expected[quantity], expected[quantity],
                    HERTZ_TOLERANCE, "Hertz", cause) for quantity, unit in (("f_n_max", "N"), ("overlap_max", "m"),
                                                                            ("t_contact", "s"))] + \
            [restitution(case, engine, table)]
    if case.test == 3:
        return [restitution(case, engine, table, "e_out")]
    return [r for impact in table.itertuples(index=False) for r in tangential(case, engine, impact)] + \
        [restitution(case, engine, table)]


def applicable(case, engine):
    """Why `engine` cannot run `case`, or '' when it can."""
    status = ENGINES[engine].status(LAW)
    if not status.available:
        return status.reason
    if engine == "reference":
        return ""
    if case.target is not None:
        return ENGINES[engine].target_reason(LAW, case.effective_scene)
    if case.scene.wall not in ENGINES[engine].walls(LAW):
        return f"its {LAW} inputs have no {case.scene.wall} wall"
    return ""


def plan(case, engine):
    """The run of one case on one engine, at the case's own fixed time step."""
    law, scene, dt = compose(LAW), case.effective_scene, FixedTimeStep(case.time_step)
    runs = (reference_runs(law, scene, dt) if engine == "reference" else
            engine_runs(ENGINES[engine], law, scene, dt, observe=case.test in (1, 2)))
    return runs[0]


def outcome(case, frame, failure):
    """(results table, None) of a finished run (of two spheres, with each body's velocities), or (None, failure)."""
    if failure is not None:
        return None, failure
    table = frame.reset_index(drop=True)
    return (with_bodies(table, case.effective_scene) if case.target is not None else table), None


def results(case, engine):
    """(results table, None) of one case on one engine, or (None, the failure) when the engine failed."""
    (frame, failure), = run_all([plan(case, engine)])
    return outcome(case, frame, failure)


def run_suite(engines=("reference",), progress=None):
    """Every test on every engine: the table of COLUMNS, a row per quantity (one per case an engine cannot run). The
    runs are executed together, so that an engine's share its processes."""
    pairs = [(case, engine) for case in cases() for engine in engines]
    reasons = [applicable(case, engine) for case, engine in pairs]
    jobs = [i for i, reason in enumerate(reasons) if not reason]
    runs = [plan(*pairs[i]) for i in jobs]
    names = {id(run): f"{pairs[i][1]}: test {pairs[i][0].test}, {pairs[i][0].label}" for i, run in zip(jobs, runs)}
    if progress:
        progress.expect(len(runs))
    done = dict(zip(jobs, run_all(runs, None if progress is None else
                                  lambda run, frame, failure: progress.advance(names[id(run)]))))
    rows = []
    for i, (case, engine) in enumerate(pairs):
        if reasons[i]:
            rows.append(row(case, engine, "not run", math.nan, note=reasons[i]))
            continue
        table, failure = outcome(case, *done[i])
        rows += (checks(case, engine, table) if failure is None else
                 [{**row(case, engine, "failed", math.nan, note=failure.message), "passed": False}])
    return pd.DataFrame(rows, columns=list(COLUMNS))


def curve_errors(table):
    """Per test, engine and quantity, Kratos' measure of a curve: sum |value - expected| / sum |expected| over its
    checked points (sum |value - expected| itself where every expected value is 0, as Kratos measures test 7's
    v_t), and whether it is below KRATOS_TOLERANCE (its DEM_benchmarks_class.py; it compares with Chung & Ooi's
    published curves, harness with the closed forms)."""
    checked = table[table.passed.notna() & table.expected.notna()]
    rows = []
    for (test, engine, quantity), group in checked.groupby(["test", "engine", "quantity"], sort=False):
        scale = group.expected.abs().sum()
        error = (group.value - group.expected).abs().sum() / (scale if scale > 0 else 1.0)
        rows.append({"test": test, "engine": engine, "quantity": quantity, "points": len(group),
                     "L1 error": error, "within Kratos' 5%": bool(error < KRATOS_TOLERANCE)})
    return pd.DataFrame(rows, columns=["test", "engine", "quantity", "points", "L1 error", "within Kratos' 5%"])


def verdict(table):
    """(every check made passed and at least one was made, checks passed, checks made) of a suite's table."""
    checked = table[table.passed.notna()]
    passed = int((checked.passed == True).sum())     # noqa: E712 (a column of True/False/None)
    return passed == len(checked) and len(checked) > 0, passed, len(checked)


def known_engines(engines, shown=None):
    """The engines to run the suite on (None: every one), each a known name."""
    engines = tuple(ENGINES) if engines is None else tuple(engines)
    unknown = [n for n in engines if n not in ENGINES]
    if unknown or not engines:
        given = ", ".join(unknown) or repr(list(engines) if shown is None else shown)
        raise UserError(f"unknown engine(s) {given}; known: {', '.join(ENGINES)}")
    return engines
