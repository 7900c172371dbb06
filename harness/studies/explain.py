"""`harness explain ENGINE TEXT` and `harness.explain`: what a user's own engine input computes on a scene (default:
the paper's sweep of impact angles, at the input's own stiffness and damping), from its dialect on the reference
solver: achieved e_n, e_t, Omega* and contact time; the paper law it is nearest and how far; the inputs of that engine
and of the others that compute the same law, or each other engine's nearest input, how far, and the ingredient that
makes most of the difference; and calibrate's advice, the engine's input for the nearest paper law at the e_n the
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
    nearest_inputs: list = field(default_factory=list)   # [NearestInput] of each other engine without the same law
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
    same, nearest_inputs = across_engines(given, dialect, scene, target, sweep)
    translations += same
    advice = advice_lines(build, nearest[0][0], paper_scene(nearest[0][0], scene, dialect), paper_e) if nearest else []
    explanation = Explanation(build.NAME, given.text, {k: str(v) for k, v in dialect.describe().items()},
                              [f.why for f in given.flags(version)], e_n, float(normal.t_contact), sweep, nearest,
                              translations, advice, nearest_inputs=nearest_inputs, notes=notes)
    if run:
        explanation.engine_rows, explanation.agreement = engine_check(build, given, scene, dialect)
    return explanation


STEPPING = ("integrator", "coulomb", "geometry", "lever", "slip", "torque", "touch")
SAME_LAW = 1e-6              # worst difference relative to V under one stepping: the same law


@dataclass
class NearestInput:
    """Another engine's input nearest to the input's law where none of its inputs computes it: its distance (worst
    |difference|/V over the scene, each stepped as its engine steps it) and the ingredient whose swap into the input's
    composition removes most of it, with the share it removes."""
    engine: str                       # 'lammps 2024.8.29.3'
    text: str
    distance: float
    ingredient: str | None
    labels: tuple | None              # (the input's label, the candidate's) of that ingredient
    share: float | None


def across_engines(given, dialect, scene, target, mine):
    """([(engine, text)], [NearestInput]): other engines' inputs that compute the input's law, and for each engine
    with none, its nearest. A candidate computes the same law where its composition, given the input's stepping
    sub-models (integrator, Coulomb rule, levers, touch), rebounds on the reference over the scene as the input does
    within SAME_LAW of V (what differs then is each engine's stepping alone); the nearest is the candidate whose
    composition as its own engine steps it rebounds nearest to the input's, as the two engines would differ.
    """
    from ..solver.simulate import simulate
    same, nearest = [], {}
    for engine, text, release in given.other_engines(scene.contact):
        try:
            other = parse(engine, text, release).composition(target, release)
        except UserError:
            continue
        where = f"{engine} {release}" if release else engine
        if distance(mine, simulate(stepped_as(other, dialect), scene, STEPS)[0], scene.speed, scene.radius) < SAME_LAW:
            same.append((where, text))
            continue
        own = replace(other, name=dialect.name)
        theirs = simulate(own, scene, STEPS)[0]
        gap = distance(mine, theirs, scene.speed, scene.radius)
        if math.isfinite(gap) and (engine not in nearest or gap < nearest[engine][0]):
            nearest[engine] = (gap, where, text, own, theirs)
    found = {where.split()[0] for where, _ in same}
    out = [nearest_input(dialect, scene, *nearest[engine]) for engine in nearest if engine not in found]
    return same, out


def stepped_as(law, dialect):
    """`law` with the stepping sub-models of `dialect`, under its name."""
    from ..laws.law import replace_submodels
    stepping = {k: v for k, v in dialect.describe().items() if k in STEPPING}
    stepping["lever"] = {"R": "0", "R - d/4": "0.25", "R - d/2": "0.5", "R - d": "1"}[stepping["lever"]]
    return replace(replace_submodels(law, stepping), name=dialect.name)


def nearest_input(dialect, scene, gap, where, text, law, theirs):
    """The NearestInput of a candidate: attribution's swaps of its sub-models into the input's composition, one at a
    time (analyses/attribution.py), each measured by what remains of the distance."""
    from ..analyses.attribution import attribute, differing_ingredients
    from ..analyses.causes import BASE
    from ..solver.simulate import simulate
    table, impacts = attribute(law, dialect, scene, lambda each, on: simulate(each, on, STEPS)[0])
    labels = {key: (mine, yours) for key, mine, yours in differing_ingredients(law, dialect)}
    singles = [(row["switched"], impacts[impacts.switched == row["switched"]])
               for row in (table.to_dict("records") if not table.empty else []) if row["switched"] != BASE]
    best = most_removed(singles, gap, theirs, scene)
    named = None if best is None else tuple(" + ".join(str(labels[k][i]) for k in best[0].split("+") if k in labels)
                                            for i in (0, 1))
    return NearestInput(where, text, gap, *(((best[0], named, best[1] / gap)) if best else (None,) * 3))


def most_removed(swaps, gap, theirs, scene):
    """(name, distance removed) of the swap that removes most of `gap`, or None."""
    removed = [(name, gap - distance(rows, theirs, scene.speed, scene.radius)) for name, rows in swaps if len(rows)]
    return max(removed, key=lambda pair: pair[1]) if removed else None


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
