"""The Python API: `run` and `compare` with the CLI's option names as keywords (docs/user-guide.md)."""
from dataclasses import replace

from .analyses.attribution import attribution
from .analyses.sliding import sliding_thresholds, threshold_table
from .comparison import Comparison
from .engines import ENGINES, EXTERNAL
from .engines.protocol import Status
from .execute import execute
from .plan import CONVERGED, compare_plan, reference_runs
from .request import Request
from .solver.reference import simulate

HISTORY_POINTS = 400


def run(model, **keywords):
    """The reference solver's results table (pandas) of `model` over a scene, e.g.
    run("hertz-mindlin", en=[0.5], angles=[10, 30], steps_per_contact=2000)."""
    request = Request.from_keywords(model, **keywords)
    return run_request(request)


def run_request(request, on_frame=None):
    table, _ = execute(reference_runs(request.law, request.scene, request.resolution), on_frame)
    return table


def compare(model, engines=None, engine_options=None, **keywords):
    """The paper law, each engine's dialect and each engine on one scene: a Comparison with .results, .agreement,
    .deviation, .cross, .attribution, .findings, .sliding and .ok, e.g. compare("hertz-mindlin", engines=["liggghts"],
    en=[0.5], angles=[10, 30])."""
    return compare_request(Request.from_keywords(model, engines=engines, engine_options=engine_options, **keywords))


def statuses(request):
    """The Status of every external engine for the request: asked for (or every one when none was named), able to run
    the law and to express the scene."""
    names = [e for e in (request.engines if request.engines is not None else EXTERNAL) if e != "reference"]
    out = []
    scene = request.scene
    unsupported = ("engine inputs do not model gravity" if scene.gravity else
                   "engine inputs use a wall of the sphere's own material" if scene.wall != "same" else None)
    for name in names:
        engine = ENGINES[name]
        status = engine.status(request.law.name, request.engine_options.get(name))
        if status.available and unsupported:
            status = Status(name, False, unsupported)
        out.append(status)
    return out


def compare_request(request, on_frame=None):
    """Run the comparison of a validated request (on_frame(frame) after each run) and return it."""
    law, scene = request.law, request.scene
    ran = [s for s in statuses(request) if s.available]
    engines = {ENGINES[s.name]: request.engine_options.get(s.name, {}) for s in ran}
    engine_resolution = 1000 if request.resolution == CONVERGED else request.resolution
    plan = compare_plan(law, scene, request.resolution, engines, engine_resolution)
    for run_ in plan:                          # a time step above a stability limit: refused before anything runs
        if run_.resolution != CONVERGED:
            run_.batch()
    results, failures = execute(plan, on_frame)

    def simulate_at(l, s):
        return simulate(l, s, steps_per_contact=engine_resolution)[0]

    attributions, dialects = {}, {}
    for engine, options in engines.items():
        dialects[engine.NAME] = engine.dialect(law.name, options)
        attributions[f"{engine.NAME} dialect -> paper"] = attribution(law, dialects[engine.NAME], scene, simulate_at)
    names = list(dialects)
    for i, a in enumerate(names):                      # every pair of engines: which ingredients make the difference
        for b in names[i + 1:]:
            attributions[f"{a} dialect -> {b} dialect"] = attribution(dialects[b], dialects[a], scene, simulate_at)
    precision = None
    for engine, options in engines.items():
        if hasattr(engine, "precision_gap") and options.get("precision", "double") == "double" and not failures:
            precision = engine.precision_gap(law, scene, engine_resolution)
    sliding = threshold_table(law.name, sliding_thresholds(law, scene)) if scene.mu > 0 else None
    return Comparison(law, scene, results, overrides=dict(request.overrides), engine_options=request.engine_options,
                      requested=request.engines, skipped=[(s.name, s.reason) for s in statuses(request)
                                                          if not s.available],
                      failures=failures, attribution=attributions, sliding=sliding, precision=precision,
                      histories=normal_histories(law, scene, engine_resolution))


def normal_histories(law, scene, steps):
    """Force histories of the paper law's normal impact at the scene speed, one per e_n (for the report)."""
    normal = replace(scene, angles_deg=(0.0,), psi1_star=None, v_t=None)
    return simulate(law, normal, steps_per_contact=steps, history_points=HISTORY_POINTS)[1]
