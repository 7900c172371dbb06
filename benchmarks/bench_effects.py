"""What simulating only the effects a scene calls for saves, side by side in one run: the reference integrator on a
normal-impact sweep and on a mu = 0 sweep with the tangential model on every row against only where the scene needs
it, and on an oblique sweep with force histories recorded against without; the engines with their per-step contact
output (their force histories) against without. Each pair must give the same rebounds; the ratio is the saving.

    .venv/bin/python benchmarks/bench_effects.py [--smoke]
"""
import sys
import time

import numpy as np

from harness.engines import ENGINES, EXTERNAL
from harness.runs.execute import execute
from harness.laws import compose
from harness.solver.resolution import run_spec
from harness.runs.plan import engine_runs
from harness.scenes.scene import DEFAULT_ANGLES, Scene
from harness.solver import codes as C
from harness.solver.batch import batch_of
from harness.solver.simulate import run_kernel

STEPS = 1000
REPEATS = 3
HISTORY_POINTS = 400


def kernel_seconds(law, scene, every_effect=False, history_points=0):
    """Fastest of REPEATS wall times of the integrator over every e_n of the scene, and the rebounds."""
    batches = [batch_of(law, scene, run_spec(law, scene, e, STEPS), every_effect=every_effect) for e in scene.e_n]
    run_kernel(batches[0], history_points)                        # compiled outside the timing
    best, outs = np.inf, None
    for _ in range(REPEATS):
        start = time.perf_counter()
        outs = [run_kernel(batch, history_points)[0] for batch in batches]
        best = min(best, time.perf_counter() - start)
    return best, np.concatenate(outs)[:, [C.O_VZ, C.O_VX, C.O_W]]


def engine_seconds(engine, law, scene, observe):
    """Fastest of REPEATS wall times of the engine's batches (one process for all), and the rebounds."""
    best, table = np.inf, None
    for _ in range(REPEATS):
        start = time.perf_counter()
        table, failures = execute(engine_runs(engine, law, scene, STEPS, observe=observe))
        best = min(best, time.perf_counter() - start)
        if failures:
            raise SystemExit(f"{engine.NAME}: {failures[0].message}")
    return best, table[["v_n1", "v_t1", "omega1"]].to_numpy()


def main(smoke=False):
    law = compose("hertz-mindlin")
    e_n = (0.5,) if smoke else tuple(round(0.1 * i, 1) for i in range(1, 10))
    angles = (10.0, 40.0) if smoke else DEFAULT_ANGLES
    normal = Scene(e_n=e_n, angles_deg=None, v_t=(0.0,) * (2 if smoke else 45))
    frictionless = Scene(e_n=e_n, angles_deg=angles, mu=0.0)
    oblique = Scene(e_n=e_n, angles_deg=angles)
    print(f"{'':52s} {'every effect [s]':>17s} {'only needed [s]':>16s} {'RATIO':>7s}  same rebounds")
    thornton = compose("thornton")           # no tangential dashpot: at mu = 0 nothing acts tangentially
    for name, case_law, scene, off in (
            ("reference, normal impacts: tangential model", law, normal, {"every_effect": True}),
            ("reference, mu = 0 (thornton): tangential model", thornton, frictionless, {"every_effect": True}),
            ("reference, oblique: force histories", law, oblique, {"history_points": HISTORY_POINTS})):
        slow, a = kernel_seconds(case_law, scene, **off)
        fast, b = kernel_seconds(case_law, scene)
        print(f"{name:52s} {slow:17.4f} {fast:16.4f} {slow / fast:7.2f}  {np.array_equal(a, b)}")
    engine_scene = Scene(e_n=e_n[:1], angles_deg=angles)
    for engine_name in EXTERNAL:
        engine = ENGINES[engine_name]
        if not engine.available():
            print(f"{engine_name}: not available, skipped")
            continue
        slow, a = engine_seconds(engine, law, engine_scene, observe=True)
        fast, b = engine_seconds(engine, law, engine_scene, observe=False)
        print(f"{engine_name + ', oblique: per-step contact output':52s} {slow:17.4f} {fast:16.4f} {slow / fast:7.2f}  "
              f"{np.array_equal(a, b)}")
    print("(the engines' decks and scripts need no switch for normal impacts or mu = 0: their tangential history "
          "stays zero there)")


if __name__ == "__main__":
    main("--smoke" in sys.argv[1:])
