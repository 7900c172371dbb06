"""The Python API (`harness.run`, `harness.compare`, ...): every command that makes sense from Python, with the
command line's option names as explicit keywords, each checked for type before anything runs (harness.runs.keywords:
a wrong type is a TypeError naming the keyword, a bad value a ValueError), returning data with a short repr."""
import functools
import os
from collections.abc import Mapping
from inspect import Parameter, Signature, signature

from ..infra.errors import UserError, UserTypeError
from ..runs.keywords import as_flag, as_names, as_path, as_real, as_text, as_whole, as_wholes
from ..runs.request import Request, resolution_from, scene_from

SCENE = tuple(p.replace(kind=Parameter.KEYWORD_ONLY) for p in signature(scene_from).parameters.values())
RESOLUTION = tuple(p.replace(kind=Parameter.KEYWORD_ONLY) for p in signature(resolution_from).parameters.values())
WITH = (Parameter("with_", Parameter.KEYWORD_ONLY, default=None),)
SCENE_DOC = """
    Scene (as the command line's options): en (target e_n, a list), one of angles (deg) | psi (Psi1*) | vt (m/s),
    mu, material (a name of `harness models`), radius (m), E (Pa), nu, rho (kg/m^3), speed | normal_speed (m/s),
    omega0 (rad/s), gravity (m/s^2), wall ("same", "rigid", a material or "E=...,nu=..."), target ("wall" or
    "sphere") with target_radius (m), target_material, target_omega (rad/s), target_fixed; with_ ({sub-model:
    choice}, --with)."""
RESOLUTION_DOC = """
    Resolution: one of steps_per_contact (default 1000) | dt (s) | converged=True."""
SUITES = ("chung-ooi",)


def takes(*groups, doc=""):
    """Give `function(..., **keywords)` an explicit signature: its own parameters, then the keyword-only `groups`
    (SCENE, RESOLUTION, WITH); a keyword it does not take is a UserTypeError naming it."""
    def wrap(function):
        own = [p for p in signature(function).parameters.values() if p.kind != Parameter.VAR_KEYWORD]
        explicit = Signature(own + [p for group in groups for p in group])

        @functools.wraps(function)
        def call(*args, **keywords):
            try:
                explicit.bind(*args, **keywords)
            except TypeError as exc:
                raise UserTypeError(f"{function.__name__}(): {exc}") from None
            return function(*args, **keywords)
        call.__signature__ = explicit
        call.__doc__ = function.__doc__ + doc
        return call
    return wrap


@takes(SCENE, RESOLUTION, WITH, doc=SCENE_DOC + RESOLUTION_DOC)
def run(model, scene="impact", scene_params=None, engines=None, engine_options=None, **keywords):
    """The reference solver's results table (pandas; units: harness.columns) of the law `model` over the impact
    scene, e.g. run("hertz-mindlin", en=[0.5], angles=[10, 30], steps_per_contact=2000); with another scene kind
    (`harness scenes`), its SceneRun: .series and .checks (the closed-form checks; with `engines`, a list of names,
    on those engines too, and each one's agreement with its dialect; .unavailable: the engines that did not run it,
    and why), e.g. run("hertz-mindlin", scene="rest", scene_params={"steps": 1000}, en=[0.5], engines=["lammps"])."""
    as_text("scene", scene)
    if scene != "impact":
        from .scene_requests import run_scene_request
        if scene_params is not None and not isinstance(scene_params, Mapping):
            raise UserTypeError(f"scene_params must be a mapping of parameter names to values, got {scene_params!r}")
        return run_scene_request(model, scene, scene_params, engines=engines, engine_options=engine_options,
                                 **keywords)
    if scene_params:
        raise UserError("scene impact takes its own keywords (target, en, angles, ...), not scene_params")
    if engines is not None or engine_options:
        raise UserError("run computes the impact scene on the reference solver: compare(..., engines=[...]) runs it "
                        "on engines")
    from .requests import run_request
    return run_request(Request.from_keywords(model, **keywords))


@takes(SCENE, RESOLUTION, WITH, doc=SCENE_DOC + RESOLUTION_DOC)
def compare(model, engines=None, engine_options=None, tolerances=None, engine_input=None, **keywords):
    """The paper law, each engine's dialect and each engine on one scene (harness compare): a Comparison with
    .results, .agreement, .deviation, .cross, .attribution, .findings, .sliding, .physics, .reproduces, .ok,
    .report(dir) and .plot(column), e.g. compare("hertz-mindlin", engines=["liggghts"], en=[0.5], angles=[10, 30]).
    engines: a list of names (None: every engine that supports the law); engine_options: {engine: {key: value}};
    tolerances: the physics verdict's, {name: value} (--tolerance); engine_input: {engine: your own input as it
    takes it} (--engine-input)."""
    from .requests import compare_request
    from .notebook_results import Compared
    request = Request.from_keywords(model, engines=engines, engine_options=engine_options, tolerances=tolerances,
                                    engine_input=engine_input, **keywords)
    return Compared.of(compare_request(request))


@takes(SCENE, RESOLUTION, WITH, doc=SCENE_DOC + RESOLUTION_DOC)
def calibrate(model, engine, tolerances=None, timestep_tolerance=1e-2, engine_input=None, **keywords):
    """The engine inputs that make `engine` compute `model` nearest the paper law on a scene, confirmed by running
    the engine, and the time step that buys `timestep_tolerance` (harness calibrate): a Calibration, e.g.
    calibrate("hertz-mindlin", "lammps", en=[0.25, 0.5], angles=[10, 30, 60]). engine_input: {engine: your own
    input as it takes it} (--engine-input), the stage before calibration."""
    from .requests import calibrate_request
    as_text("engine", engine)
    as_real("timestep_tolerance", timestep_tolerance)
    request = Request.from_keywords(model, engines=[engine], tolerances=tolerances, engine_input=engine_input,
                                    **keywords)
    return calibrate_request(request, request.tolerances, timestep_tolerance)


@takes(SCENE, WITH, doc=SCENE_DOC)
def cost(model, engines=None, engine_options=None, ladder=None, **keywords):
    """Accuracy against time (harness cost): a ladder of steps per contact for the paper law, each engine's dialect
    and each engine: a CostStudy with .table (cost.csv), .recommendations, .ok and .report(dir), e.g.
    cost("hertz-mindlin", engines=["reference"], en=[0.5], angles=[30], ladder=[10, 100])."""
    from ..analyses.cost import LADDER
    from ..runs.availability import able_engines
    from ..studies.cost_plan import check_ladder, cost_table
    from .notebook_results import CostStudy
    rungs = LADDER if ladder is None else check_ladder(as_wholes("ladder", ladder))
    request = Request.from_keywords(model, engines=engines, engine_options=engine_options, **keywords)
    able, skipped = able_engines(request)
    table, failures, uncertainty = cost_table(request.law, request.scene, able, rungs)
    return CostStudy(request.law, request.scene, dict(request.overrides), table, uncertainty, skipped, failures,
                     request.engines)


def paper(laws=None, steps_per_contact=2000):
    """The paper's figure set on its scene (harness paper): for each law Psi2*, Omega* and e_t against Psi1*, the
    normal impacts, where each law slides throughout: a PaperFigures with .oblique, .normal, .sliding, .published,
    .plot(column, law) and .report(dir), e.g. paper(laws=["thornton"]). laws: a list of names (None: every law)."""
    from ..studies.paper import checked, figure_set
    from .notebook_results import PaperFigures
    laws = checked(as_names("laws", laws), as_whole("steps_per_contact", steps_per_contact))
    return PaperFigures(*figure_set(laws, steps_per_contact))


def benchmark(suite="chung-ooi", engines=None):
    """A published verification suite (harness benchmark; Chung & Ooi 2011's eight tests) on the reference and the
    engines: a Benchmark with .table, .ok, .passed, .checked and .report(dir), e.g.
    benchmark("chung-ooi", engines=["reference"]). engines: a list of names (None: every engine)."""
    from .notebook_results import Benchmark
    from ..studies.verification.chung_ooi import known_engines, run_suite
    if as_text("suite", suite) not in SUITES:
        raise UserError(f"suite must be one of {', '.join(SUITES)}, got {suite!r}")
    named = as_names("engines", engines)
    chosen = known_engines(named)
    return Benchmark(run_suite(chosen), chosen, named is not None)


def campaign(spec, store, no_cache=False):
    """A matrix of comparisons (harness campaign), run in this process into the Parquet store at `store` (a rerun
    takes what it holds): a CampaignRun with .summary, .table and .report(path). spec: the campaign file's path
    (TOML) or its table as a dict, e.g. campaign({"laws": ["hertz-mindlin"], "en": [0.5], "angles": [10, 30]},
    "store")."""
    from ..studies.campaign.driver import run_campaign
    from ..studies.campaign.executors import InProcess
    from ..studies.campaign.spec import from_dict, load
    from ..studies.campaign.store import Store
    from ..infra.lock import exclusive
    from .notebook_results import CampaignRun
    if isinstance(spec, Mapping):
        matrix = from_dict(dict(spec))
    elif isinstance(spec, (str, os.PathLike)):
        matrix = load(os.fspath(spec))
    else:
        raise UserTypeError(f"keyword spec must be a campaign file's path or its table as a dict, got "
                            f"{type(spec).__name__}")
    path, no_cache = as_path("store", store), as_flag("no_cache", no_cache)
    with exclusive(path):
        summary = run_campaign(matrix, Store(path), InProcess(), no_cache)
    return CampaignRun(matrix.name, summary, path)


def plot(frame, y, x=None, title=None):
    """A matplotlib Figure of a results table (harness.run's, a Comparison's .results): column `y` against Psi1* on
    the paper's axes (psi2_star, omega_star, e_t) or else against the impact angle, one panel per e_n, one curve
    per engine and dialect, e.g. plot(harness.run("thornton", en=[0.5]), "e_t")."""
    from .notebook_results import series
    return series(frame, y, x, title)


def explain(engine, text, run=False, **keywords):
    """What your own input `text` of `engine` computes (harness explain): an Explanation with .e_n, .t_contact,
    .sweep (the input's dialect per impact), .nearest [(paper law, distance)], .translations, .advice and, with
    run=True, .agreement of the engine with its dialect; e.g. explain("lammps", "hooke 1e7 2e5 tangential
    linear_history 2.8e6 0.5 0.4", angles=[10, 30])."""
    from ..studies.explain import explain as explained
    return explained(engine, text, run=run, **keywords)
