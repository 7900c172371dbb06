"""What the commands and the Python API (harness.api.notebook) share: run, compare and calibrate a validated request
(which engines can take it: runs/availability.py)."""
from dataclasses import replace

import pandas as pd

from ..analyses.attribution import attribute, attribution, law_key
from ..analyses.precision import precision_gap
from ..analyses.sliding import threshold_table
from ..runs.comparison import Comparison
from ..studies.calibration.calibrate import calibrate as run_calibration
from ..data.states import attach, carried, gather
from ..engines import ENGINES, EXTERNAL
from ..infra.errors import UserError
from ..runs.availability import options_for, statuses
from ..runs.execute import execute, run_all
from ..runs.outputs import arithmetic_of
from ..solver.resolution import CONVERGED
from ..runs.plan import compare_plan, reference_runs, specs_of, target_of
from ..studies.sliding_search import sliding_thresholds
from ..solver.simulate import simulate
from ..solver.two_spheres import with_bodies

HISTORY_POINTS = 400


def run_request(request, on_frame=None, progress=None):
    """The reference solver's results table of a validated request (the dialect of its one engine input, if it has
    one: --engine-input); progress.advance after each e_n."""
    from ..engines.user_inputs import INPUT_OPTION
    given = [name for name, options in request.engine_options.items() if INPUT_OPTION in options]
    if len(given) > 1:
        raise UserError(f"run takes one engine input, got {len(given)} ({', '.join(given)})")
    dialect = ENGINES[given[0]].dialect(request.law.name, request.engine_options[given[0]],
                                        target_of(request.scene)) if given else None
    runs = reference_runs(request.law, request.scene, request.resolution, dialect)
    if progress:
        progress.expect(len(runs))

    def done(frame):
        if on_frame:
            on_frame(frame)
        if progress:
            progress.advance(f"e_n {frame.e_n_target.iloc[0]:g}")
    table, _ = execute(runs, done)
    return attach(with_bodies(table, request.scene), carried(table)) if request.scene.spheres else table


def calibrate_request(request, tolerances=None, timestep_tolerance=1e-2):
    """calibrate() of a validated request naming one engine build: one line for what a calibration cannot take, before
    anything runs (a --with its inputs cannot follow is refused by compare's own check, options_for)."""
    engine = calibration_engine(request.engines)
    scene = request.scene
    if scene.psi1_star is not None:
        raise UserError("calibrate sweeps impact angles or tangential speeds (--angles, --vt), not --psi: an "
                        "engine given another e would see other impacts at the same Psi1*")
    if scene.spheres:
        raise UserError("calibrate runs against a wall; two spheres (--target sphere) are not calibrated yet")
    if not isinstance(request.resolution, (int, float)) or isinstance(request.resolution, bool):
        raise UserError("calibrate takes --steps-per-contact (an engine has no converged mode and --dt would "
                        "change with the input e), not --dt or --converged")
    if not engine.supports(request.law.name):
        raise UserError(f"{engine.NAME} has no counterpart of {request.law.name}")
    check_timestep_tolerance(timestep_tolerance)
    from ..engines.user_inputs import INPUT_OPTION
    fixed = options_for(request, engine.NAME)
    yours = None
    if INPUT_OPTION in fixed:              # --engine-input: the user's input is the stage before calibration
        yours = input_records(request.law, scene, {engine: fixed})[engine.NAME]
        yours["dialect"] = engine.dialect(request.law.name, fixed, "wall")
        fixed = {k: v for k, v in fixed.items() if k != INPUT_OPTION}
    (status,) = statuses(request)
    if not status.available and status.reason != engine.status(request.law.name, fixed).reason:
        raise UserError(f"{engine.NAME} cannot be calibrated on this scene: {status.reason}")   # not a missing engine
    return run_calibration(engine, request.law, scene, int(request.resolution), tolerances or request.tolerances,
                           timestep_tolerance, fixed=fixed, yours=yours)


def calibration_engine(names):
    """The one engine build a calibration is for, from the engines a request names: the reference solver, which
    computes the paper law itself, and several builds (ENGINE@all) are refused in one line."""
    names = tuple(names or ())
    if "reference" in names:
        raise UserError(f"calibrate finds the inputs of an engine ({', '.join(EXTERNAL)}); the reference solver "
                        f"computes the paper law itself and has none to calibrate")
    if len(names) != 1:
        code = names[0].partition("@")[0] if names else "ENGINE"
        raise UserError(f"calibrate takes one engine build, and {len(names)} were named ({', '.join(names)}): "
                        f"calibrate each with --engine {code}@VERSION")
    return ENGINES[names[0]]


def check_timestep_tolerance(value):
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not 1e-6 <= value <= 0.5:
        raise UserError(f"the time-step tolerance must be a number in [1e-6, 0.5], got {value!r}")


def compare_request(request, on_frame=None, progress=None, partial=None):
    """Run the comparison of a validated request (on_frame(frame) as each run of the comparison is done; progress
    told of every run and of the measurements) and return it. What needs no engine result (attribution, the sliding
    threshold, force histories, the precision check) runs in this thread while the engines' threads run theirs.
    With `partial` (harness.runs.partial or a campaign store), the runs it holds are taken from it, and each run that
    finishes is put there."""
    law, scene = request.law, request.scene
    found = statuses(request)
    engines = {ENGINES[s.name]: options_for(request, s.name) for s in found if s.available}
    engine_resolution = 1000 if request.resolution == CONVERGED else request.resolution
    plan = compare_plan(law, scene, request.resolution, engines, engine_resolution)
    specs_of(plan)                             # a time step above a stability limit: refused before anything runs
    checks = [(engine.NAME, engine.precision_runs(law, scene, options)) for engine, options in engines.items()]
    extra = [run_ for _, pair in checks for run_ in pair]
    if progress:
        progress.expect(len(plan) + len(extra) + 1)
    measured = []
    in_plan = {id(run_) for run_ in plan}

    def finished(run_, frame, failure=None):
        if on_frame is not None and id(run_) in in_plan:
            on_frame(frame)
        if progress:
            progress.advance(f"{run_.engine} ({run_.dialect.dialect} formulas) e_n {run_.e_n:g}"
                             + "".join(f" {k} {v}" for k, v in run_.options))
    done = run_all(plan + extra, finished, partial,
                   meanwhile=lambda: measured.append(measurements(law, scene, engines, engine_resolution,
                                                                  request.tolerances)))
    attributions, rows, sliding, histories = measured[0]
    if progress:
        progress.advance("attribution, sliding threshold, force histories")
    results = pd.concat([frame for frame, _ in done[:len(plan)]], ignore_index=True)
    states = gather([frame for frame, _ in done[:len(plan)]])
    failures = [failure for _, failure in done[:len(plan)] if failure is not None]
    precision, checked = None, iter(done[len(plan):])
    for name, pair in checks:
        if pair:
            (double, _), (high, _) = next(checked), next(checked)
            precision = precision_gap(double, high, name, pair[1].options_dict["precision"])
    return Comparison(law, scene, results, overrides=dict(request.overrides), engine_options=request.engine_options,
                      arithmetic=arithmetic_of(request.engine_options),
                      builds={e.NAME: {**e.build(), "note": e.dialect_note()} for e in engines},
                      engine_inputs=input_records(law, scene, engines),
                      requested=request.engines, skipped=[(s.name, s.reason) for s in found if not s.available],
                      failures=failures, attribution=attributions, attribution_rows=rows, sliding=sliding,
                      precision=precision, histories=histories, states=states, tolerances=request.tolerances)


def input_records(law, scene, engines):
    """{engine: {text, composition, flags}} of each engine that ran a user's own input: the text verbatim, the
    neutral sub-models it maps to, and the unphysical values it was run with."""
    from ..engines.user_inputs import INPUT_OPTION, parse
    out = {}
    for engine, options in engines.items():
        text = (options or {}).get(INPUT_OPTION)
        if text is not None:
            composition = engine.dialect(law.name, options, target_of(scene)).describe()
            flags = [f.why for f in parse(engine.code, text, engine.version()).flags(engine.version())]
            out[engine.NAME] = {"text": text, "composition": {k: str(v) for k, v in composition.items()},
                                "flags": flags}
    return out


def measurements(law, scene, engines, steps, tolerances):
    """What a comparison measures beside the runs: the attribution of each engine's difference from the paper law
    (with its rows of every impact, and pairs where the physics checks with `tolerances` need them) and of each pair
    of engines, the paper law's sliding-throughout threshold, its normal force histories."""
    done = {}

    def simulate_at(law_, s):               # each law once: the paper law and a switched law serve every engine
        key = law_key(law_)
        if key not in done:
            done[key] = simulate(law_, s, steps_per_contact=steps)[0]
        return done[key]

    dialects = {engine.NAME: engine.dialect(law.name, options, target_of(scene)) for engine, options in engines.items()}
    attributions, rows = {}, {}
    for name, dialect in dialects.items():
        attributions[f"{name} dialect -> paper"], rows[name] = attribute(law, dialect, scene, simulate_at, tolerances)
    names = list(dialects)
    for i, a in enumerate(names):                      # every pair of engines: which ingredients make the difference
        for b in names[i + 1:]:
            attributions[f"{a} dialect -> {b} dialect"] = attribution(dialects[b], dialects[a], scene, simulate_at)
    sliding = threshold_table(law.name, sliding_thresholds(law, scene)) if scene.mu > 0 else None
    return attributions, rows, sliding, normal_histories(law, scene, steps)


def normal_histories(law, scene, steps):
    """Force histories of the paper law's normal impact at the scene speed, one per e_n (for the report)."""
    normal = replace(scene, angles_deg=(0.0,), psi1_star=None, v_t=None)
    return simulate(law, normal, steps_per_contact=steps, history_points=HISTORY_POINTS)[1]
