"""What 1e-4 relative error in e_t costs, side by side in one run: a 45-angle hertz-mindlin sweep (e_n 0.5)
through the reference (paper law, plain and --converged), LIGGGHTS and YADE. Each is refined along the same
ladder of steps per contact until the largest e_t error over the sweep (against the converged reference of its own
dialect, harness.cost) is <= 1e-4; the wall time of that run is its cost (engines: with and without start-up).

    .venv/bin/python benchmarks/bench_accuracy_cost.py [--smoke]

--smoke runs the smallest size: three angles and a target of 1e-2.
"""
import sys
import time

import numpy as np

from harness.analyses.cost import relative_errors
from harness.studies.cost_plan import startup_seconds
from harness.studies.cost_truth import truth_of
from harness.engines import ENGINES, EXTERNAL
from harness.runs.execute import execute
from harness.laws import compose
from harness.runs.plan import engine_runs
from harness.scenes.scene import Scene
from harness.solver.simulate import simulate
from harness.solver.stability import UnstableTimeStep

TARGET = 1e-4
LADDER = (20, 50, 100, 200, 500, 1000, 2000, 5000, 10000, 20000, 50000)
SCENE = Scene(e_n=(0.5,), angles_deg=tuple(np.arange(1.0, 90.0, 2.0)))
LAW = compose("hertz-mindlin")


def e_t_error(frame, truth):
    return relative_errors(frame, truth)["err_e_t"]


def reference_cost(law, truth):
    """Smallest rung reaching the target in the reference, and its kernel wall time."""
    for n in LADDER:
        try:
            frame, _ = simulate(law, SCENE, steps_per_contact=n)
        except UnstableTimeStep:
            continue
        error = e_t_error(frame, truth)
        if error <= TARGET:
            return n, float(frame.wall_s.sum()), error
    return None, np.nan, error


def engine_cost(name, truth):
    """Smallest rung reaching the target in the engine; wall time of that batched run and its start-up."""
    adapter = ENGINES[name]
    options = {"precision": "double", "linear": "viscel"} if name == "yade" else {}
    startup = startup_seconds(adapter, LAW, SCENE, options)[SCENE.e_n[0]][0]    # (fastest, spread)
    for n in LADDER:
        try:
            frame, failed = execute(engine_runs(adapter, LAW, SCENE, n, options))
        except UnstableTimeStep:
            continue
        if failed:
            return None, np.nan, startup, np.nan
        error = e_t_error(frame, truth)
        if error <= TARGET:
            return n, float(frame.wall_s.sum()), startup, error
    return None, np.nan, startup, error


def main(smoke=False):
    global SCENE, TARGET
    if smoke:
        SCENE, TARGET = Scene(e_n=(0.5,), angles_deg=(10.0, 40.0, 70.0)), 1e-2
    simulate(LAW, SCENE, steps_per_contact=20)                      # compile outside the timing
    results = {}
    truth = truth_of(LAW, SCENE).frame
    n, wall, error = reference_cost(LAW, truth)
    results["reference (paper law)"] = (n, wall, 0.0, error)
    start = time.perf_counter()
    converged, _ = simulate(LAW, SCENE, converged=True)
    evaluations = f"{converged.steps_per_contact.mean():.0f} evals"      # adaptive: force evaluations per impact
    results["reference --converged"] = (evaluations, time.perf_counter() - start, 0.0, e_t_error(converged, truth))
    for name in EXTERNAL:
        adapter = ENGINES[name]
        if not adapter.available():
            print(f"{name}: not installed, skipped")
            continue
        dialect_truth = truth_of(adapter.dialect(LAW.name), SCENE).frame
        results[name] = engine_cost(name, dialect_truth)
    base = results["reference (paper law)"][1]
    print(f"cost of max e_t error <= {TARGET:g} over a {len(SCENE.angles_deg)}-angle hertz-mindlin sweep at e_n 0.5 "
          "(one run, side by side)")
    print(f"{'':24s} {'steps/contact':>13s} {'wall [s]':>10s} {'start-up [s]':>12s} {'e_t error':>10s} "
          f"{'RATIO to reference':>19s} {'excl. start-up':>15s}")
    for label, (n, wall, startup, error) in results.items():
        net = wall - startup
        net_text = f"{net / base:15.1f}" if net > 0.1 * startup else f"{'< start-up noise':>15s}"
        print(f"{label:24s} {str(n):>13s} {wall:10.4f} {startup:12.4f} {error:10.2e} {wall / base:19.1f} {net_text}")


if __name__ == "__main__":
    main("--smoke" in sys.argv[1:])
