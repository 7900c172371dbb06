"""The largest stable time step, measured: for a case (a hard case of the catalogue at one e_n, or a scene kind with
its parameters) and a runner (the reference running a law or an engine's dialect, or an engine itself), bisection
between a step known stable and one known unstable, bracketed by doubling or halving from the law's own stability
estimate (harness/solver/stability.py); beside it the step that 1e-3 accuracy needs and 20% of the Rayleigh time.
What "stable" means is analyses/stability.py's."""
import math
from dataclasses import dataclass, field, fields, replace

import numpy as np
import pandas as pd

from ..analyses.cost import RAYLEIGH_FRACTION, rayleigh_time, rebound_errors
from ..analyses.stability import Probe, impact_probe, overlap_drift, scene_probe, verdict
from ..engines.run import Run
from ..infra.errors import UserError
from ..runs.plan import engine_runs
from ..solver.resolution import FixedTimeStep, run_spec
from ..solver.simulate import results_frame, run_kernel, simulate
from ..solver.batch import batch_of
from ..solver.stability import stability_limit
from ..solver.system import M_GAIN, M_STATUS, STATUS_OK
from ..solver.system_run import simulate_system
from .hard_cases import ALL_LAWS, CATALOGUE, get_case
from .scenes import SCENES, kept_events, run_scene, settle_time, static_overlap

PRECISION = 0.02            # the bisection stops when the unstable step is within 2% above the stable one
ACCURACY = 1e-3             # the accuracy a step must reach against the converged reference
SEARCH = 12                 # doublings or halvings that bracket the stable step at most (a factor 4096)
ACCURACY_HALVINGS = 16      # halvings below the stable step that look for the accurate one at most (65536x)
INSIDE = (2, 4, 8)          # dt_stable / these are probed for the verdict, beside the bisection's own probes
DEFAULT_CASES = ("grazing 89.5 deg", "mu = 2", "E = 1e12 Pa", "R = 10 um")
SCENE_EN = (0.05, 0.5)      # a scene kind's e_n unless given (a resting sphere settles only below 1)
HELD_TIMES = 101            # recorded heights of a resting sphere while it is held
COLUMNS = ("case", "e_n", "engine", "dialect", "law", "dt_estimate", "dt_stable", "dt_unstable", "stable_how",
           "dt_accurate_1e-3", "accurate_how", "dt_rayleigh_20", "rayleigh_20_stable", "stable_over_rayleigh_20",
           "accurate_over_rayleigh_20", "stable_over_accurate", "verdict", "verdict_note", "probes", "log_tail")


@dataclass(frozen=True)
class StabilityCase:
    """A case: its name, the Scene (the sphere's material and friction, the impacts) at one target e_n, and the
    scene kind with its parameter values (kind None: the impacts of the Scene)."""
    name: str
    scene: object
    kind: object = None
    values: dict = field(default_factory=dict)

    @property
    def e_n(self):
        return self.scene.e_n[0]


@dataclass(frozen=True)
class Runner:
    """Who runs a case: the reference solver (engine None) running `law`, or an engine (harness.engines.Engine) with
    its options running its dialect `law` of the law named `law.name`."""
    name: str
    law: object
    engine: object = None
    options: tuple = ()


@dataclass(frozen=True)
class Bracket:
    """The bisection's end: `stable` the largest step that passed, `unstable` the smallest that did not (either None
    where the search found none), every probe in the order run."""
    stable: Probe | None
    unstable: Probe | None
    probes: tuple


class UncheckedRun(Run):
    """A Run whose spec is not refused above the law's stability limit: the bisection runs beyond it on purpose."""

    @property
    def scene_specs(self):
        return tuple(run_spec(self.dialect, s, self.e_n, self.resolution, self.step_cap, check_stability=False)
                     for s in (self.scene,) + self.together)


def run_case(case, runner, dt):
    """The Probe of `case` run by `runner` at time step dt: the one place a runner runs a case (an engine's scene
    run plugs in here)."""
    if case.kind is None:
        if runner.engine is None:
            return impact_probe(reference_impacts(runner.law, case.scene, dt), dt)
        frame, failure, log_tail = engine_impacts(runner, case.scene, dt)
        return impact_probe(frame, dt, failure, log_tail)
    if runner.engine is not None:
        raise UserError(f"stability does not run scenes on engines yet: scene {case.kind.NAME} runs on the "
                        "reference solver alone")
    return reference_scene_probe(case, runner.law, dt)


def reference_impacts(law, scene, dt):
    """The reference's results table of `law` on the scene's impacts (one e_n) at dt, above its stability limit too."""
    spec = run_spec(law, scene, scene.e_n[0], FixedTimeStep(dt), check_stability=False, bounded=False)
    batch = batch_of(law, scene, spec)
    out, _, wall = run_kernel(batch)
    return results_frame(law, scene, batch, out, wall, batch.steps_per_contact, batch.dt, [""] * len(out))


def engine_impacts(runner, scene, dt):
    """(results table, failure message or '', its log tail) of the engine running its dialect on the scene's impacts
    at dt."""
    run = engine_runs(runner.engine, runner.law, scene, FixedTimeStep(dt), dict(runner.options))[0]
    unchecked = UncheckedRun(**{f.name: getattr(run, f.name) for f in fields(run)})
    frame, failure = runner.engine.run([unchecked])[0]
    if failure is None:
        return frame, "", ""
    return frame, (failure.message.strip().splitlines() or ["no message"])[0], failure.log_tail


def scene_case(case, law, dt):
    """The scene kind's case (studies/scenes.py builds it) for `law` at dt."""
    build = SCENES[case.kind.NAME][0]
    return build(law, case.values, case.scene, case.e_n, FixedTimeStep(dt))


def reference_scene_probe(case, law, dt):
    """The Probe of a scene on the reference's system integrator at dt: finite, its largest energy gain (counted
    from the end of the settling for a resting sphere) against its initial mechanical energy, and the resting
    overlap's drift while held."""
    built = scene_case(case, law, dt)
    variant = built.variant
    resting = case.kind.NAME == "rest"
    start = settle_time(law, built, case.values) if resting else 0.0
    end = variant.steps * variant.dt
    grid = np.linspace(start, end, HELD_TIMES) if resting else np.array([0.0, end])
    result = simulate_system([variant], grid, gain_from=start, kept_events=kept_events(case.values))
    finite = result.metrics[0, M_STATUS] == STATUS_OK
    drift = math.nan
    if resting and finite:
        delta = static_overlap(law, built.contact, case.e_n, variant.speed, variant.gravity)
        drift = overlap_drift(result.trace[0, :, 0, 1], delta)
    return scene_probe(dt, finite, float(result.metrics[0, M_GAIN]), initial_energy(variant), drift)


def initial_energy(variant):
    """sum of m (g z + v^2/2) + I w^2/2 over the variant's spheres at the start (m = 4/3 pi R^3 rho, I = 2/5 m R^2)."""
    total = 0.0
    for s in variant.spheres:
        m = 4.0 / 3.0 * math.pi * s.radius ** 3 * variant.rho
        total += m * (variant.gravity * s.z + 0.5 * (s.vx ** 2 + s.vz ** 2)) + 0.2 * m * s.radius ** 2 * s.w ** 2
    return total


def bisect(test, start, precision=PRECISION, upward=True, search=SEARCH, ceiling=math.inf):
    """The Bracket of `test` (dt -> Probe): from `start`, doubling while it passes (upward, up to `ceiling`) or
    halving while it does not, at most `search` times, then bisecting (geometric means) until the failing step is
    within `precision` above the passing one."""
    probes = []

    def run(dt):
        probes.append(test(dt))
        return probes[-1]

    first = run(start)
    passed, failed = (first, None) if first.passed else (None, first)
    for _ in range(search):
        if passed is not None and failed is not None:
            break
        if passed is not None:
            if not upward or passed.dt >= ceiling:
                break
            probe = run(min(2.0 * passed.dt, ceiling))
        else:
            probe = run(0.5 * failed.dt)
        passed, failed = (probe, failed) if probe.passed else (passed, probe)
    while passed is not None and failed is not None and failed.dt > passed.dt * (1.0 + precision):
        probe = run(math.sqrt(passed.dt * failed.dt))
        passed, failed = (probe, failed) if probe.passed else (passed, probe)
    return Bracket(passed, failed, tuple(probes))


def contact_time_of(case, law):
    """The search's ceiling, one step per contact (a longer step resolves no contact): the law's contact-time
    estimate on the case's material at its slowest normal speed (a scene kind: at the Scene's speed, or the period
    of a resting sphere's oscillation where the kind has gravity and that is longer)."""
    speed = case.scene.speed
    if case.kind is None:
        normal = case.scene.impacts(case.e_n)[0]
        speed = float(np.min(normal[normal > 0.0])) if (normal > 0.0).any() else speed
    contact_time = law.normal.parameters(case.scene.contact, case.e_n, speed).contact_time
    if case.kind is None or "g" not in case.values or law.normal.name not in ("hertz", "linear"):
        return contact_time
    return max(contact_time, resting_period(case, law))


def resting_period(case, law):
    """2 pi sqrt(m/k) of a sphere resting on the wall, k linearised at its static overlap (1.5 m g/delta Hertz,
    m g/delta linear): a scene with a resting contact may step up to one step per resting oscillation."""
    contact, g = case.scene.contact, case.values["g"]
    delta = static_overlap(law, contact, case.e_n, case.scene.speed, g)
    stiffness = (1.5 if law.normal.name == "hertz" else 1.0) * contact.mass * g / delta
    return 2.0 * math.pi * math.sqrt(contact.mass / stiffness)


def estimate_of(case, law):
    """The law's own stability estimate on the case's material (harness.solver.stability.stability_limit)."""
    return stability_limit(law, case.scene, case.e_n).dt


def truth_of(case, law):
    """The converged reference of `law` on an impact case (the reference's converged mode)."""
    return simulate(law, case.scene, converged=True)[0]


def accuracy_test(case, law):
    """dt -> Probe passed where the result is within ACCURACY of the converged reference: the cost study's measure
    (analyses.cost.rebound_errors) for impacts, the kind's closed-form checks (their error) for scenes."""
    if case.kind is None:
        truth = truth_of(case, law)

        def impact_test(dt):
            error = rebound_errors(reference_impacts(law, case.scene, dt), truth)["err_max"]
            return Probe(dt, bool(error <= ACCURACY), f"error {error:.3g} against the converged reference")
        return impact_test

    def scene_test(dt):
        checks = run_scene(law, case.kind, case.values, case.scene, FixedTimeStep(dt)).checks
        if checks.empty:
            return Probe(dt, False, "no closed-form check of the scene applies to the law")
        error = float(checks.error.max())
        return Probe(dt, bool(error <= ACCURACY), f"largest closed-form check error {error:.3g}")
    return scene_test


def accurate_step(case, law, dt_stable):
    """(dt_accurate, how): the largest step within ACCURACY, searched below the stable step (which caps it)."""
    test = accuracy_test(case, law)
    bracket = bisect(test, dt_stable, upward=False, search=ACCURACY_HALVINGS)
    if bracket.stable is None:
        last = bracket.probes[-1]
        return math.nan, f"not reached down to dt {last.dt:.4g} s: {last.why}"
    if bracket.unstable is None:
        return bracket.stable.dt, f"accurate at the stable step ({bracket.stable.why})"
    return bracket.stable.dt, f"bisection to {PRECISION:.0%}: {bracket.stable.why}; above, {bracket.unstable.why}"


def measure(case, runner, accurate=None):
    """One row of COLUMNS for `case` and `runner`; `accurate` (dt, how) given for an engine (its dialect's on the
    reference, which agrees with it at equal dt) instead of searched."""
    law = runner.law
    start, ceiling = estimate_of(case, law), contact_time_of(case, law)
    bracket = bisect(lambda dt: run_case(case, runner, dt), min(start, ceiling), ceiling=ceiling)
    dt_r = RAYLEIGH_FRACTION * rayleigh_time(case.scene)
    rayleigh = run_case(case, runner, dt_r)
    row = dict(case=case.name, e_n=case.e_n, engine=runner.name, dialect=law.dialect, law=law.name, dt_estimate=start,
               dt_rayleigh_20=dt_r, rayleigh_20_stable=rayleigh.passed, probes=len(bracket.probes) + 1)
    if bracket.stable is None:
        last = bracket.probes[-1]
        return {**row, "dt_stable": math.nan, "dt_unstable": last.dt,
                "stable_how": f"no stable step found down to dt {last.dt:.4g} s: {last.why}",
                "dt_accurate_1e-3": math.nan, "accurate_how": "no stable step", "verdict": "fail",
                "verdict_note": f"unstable down to dt {last.dt:.4g} s: {last.why}", "log_tail": last.log_tail}
    dt_s = bracket.stable.dt
    if bracket.unstable is None:
        per = "contact" if case.kind is None else "contact or resting oscillation"
        how_s = f"no unstable step up to the ceiling, one step per {per} ({ceiling:.4g} s): {bracket.stable.why}"
    else:
        how_s = f"bisection to {PRECISION:.0%}; unstable at {bracket.unstable.dt:.4g} s: {bracket.unstable.why}"
    inside = [run_case(case, runner, dt_s / k) for k in INSIDE]
    dt_a, how_a = accurate if accurate is not None else accurate_step(case, law, dt_s)
    passed, note = verdict([p for p in bracket.probes if p.dt <= dt_s] + inside, rayleigh)
    return {**row, "dt_stable": dt_s, "dt_unstable": math.nan if bracket.unstable is None else bracket.unstable.dt,
            "log_tail": "", "stable_how": how_s, "dt_accurate_1e-3": dt_a, "accurate_how": how_a, "verdict": passed,
            "verdict_note": note, "probes": len(bracket.probes) + 1 + len(inside)}


def ratios(row):
    """The row with its ratios: dt_stable and dt_accurate over 20% of the Rayleigh time, dt_stable over
    dt_accurate."""
    return {**row, "stable_over_rayleigh_20": row["dt_stable"] / row["dt_rayleigh_20"],
            "accurate_over_rayleigh_20": row["dt_accurate_1e-3"] / row["dt_rayleigh_20"],
            "stable_over_accurate": row["dt_stable"] / row["dt_accurate_1e-3"]}


def stability_study(cases, runners, progress=None):
    """The table (COLUMNS) of every case and runner: for each engine its dialect on the reference first, then the
    engine, which takes the dialect's accurate step; `progress` (views.progress.Progress) told of each row."""
    rows = []
    if progress is not None:
        progress.expect(len(cases) * len(runners))
    for case in cases:
        accurate = {}
        for runner in runners:
            given = accurate.get(runner.law.dialect) if runner.engine is not None else None
            row = ratios(measure(case, runner, given))
            if runner.engine is None:
                accurate[runner.law.dialect] = (row["dt_accurate_1e-3"], f"its dialect on the reference: "
                                                                         f"{row['accurate_how']}")
            rows.append(row)
            if progress is not None:
                progress.advance(f"{case.name}, e_n {case.e_n:g}, {runner.name} ({runner.law.dialect})")
    return pd.DataFrame(rows, columns=list(COLUMNS))


def runners_of(law, engines):
    """The reference running the law, then per engine (available, harness.engines.Engine) its dialect on the
    reference and the engine itself."""
    runners = [Runner("reference", law)]
    for engine in engines:
        dialect = engine.dialect(law.name, {}, "wall")
        runners += [Runner("reference", dialect), Runner(engine.NAME, dialect, engine)]
    return runners


def default_cases(law):
    """The hard cases of issue 43's stability item that apply to the law: grazing incidence, mu >= 0.5, stiff and
    small spheres, and the catalogue's cases of this law alone (Thornton's deep plastic flow at e_n 0.05, the
    400x stiffer unloading)."""
    named = [get_case(name) for name in DEFAULT_CASES]
    own = [case for case in CATALOGUE if case.laws != ALL_LAWS and law.name in case.laws]
    return named + own


def impact_cases(hard_cases, law, e_n=None):
    """A StabilityCase per hard case applying to `law` and per e_n (the case's own unless given)."""
    cases = []
    for hard in hard_cases:
        if law.name not in hard.laws:
            continue
        for value in e_n or hard.make_scene().e_n:
            cases.append(StabilityCase(hard.name, hard.make_scene(e_n=(value,))))
    return cases


def scene_cases(kind, values, scene, e_n):
    """A StabilityCase of the scene kind with its values on the material of `scene`, per e_n."""
    return [StabilityCase(kind.NAME, replace(scene, e_n=(value,)), kind, dict(values)) for value in e_n]
