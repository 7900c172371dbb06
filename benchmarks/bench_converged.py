"""The converged mode against brute-force refinement, side by side in one run, for every law on a 3 e_n x 45 angle
sweep. Three methods, one stopping rule (successive results within 1e-6):
- brute force: uniform steps per contact doubled from 64 until two successive results agree, twice in a row;
- graded Richardson: the same on Richardson values of graded meshes (the converged mode of the laws the adaptive
  integrator does not cover);
- adaptive: the converged mode, Dormand-Prince 5(4) (SDIRK4(3) under Walton-Braun's tangential spring) at tolerance
  1e-8 and 1e-9 (tighter while they differ).
Printed: force evaluations (a kernel step costs one, plus its event location), wall time, the error reached
against the truth, and the wall-time ratios. The truth is the adaptive integrator at tol 1e-12: the 2^16-step
uniform runs harness.cost uses stop near 1e-5 under Walton-Braun's spring at grazing incidence (order 1.5). Its
last column checks it against those uniform runs, an independent discretisation (the tests check it against
closed forms, scipy and the deep graded ladder). A second table compares the methods at equal error reached
(hertz-kuwabara-kono: Hertz and Mindlin without a tangential dashpot), the stopping tolerance of each swept. Laws
with a tangential dashpot (linear-spring-dashpot, hertz-mindlin on the paper's scene) are outside the adaptive
integrator: their converged mode is the graded ladder, and they are listed, not measured.

    .venv/bin/python benchmarks/bench_converged.py [--smoke]
"""
import sys
import time

import numpy as np

from harness.analyses.cost import relative_errors
from harness.studies.cost_truth import truth_of
from harness.laws import LAWS, compose
from harness.scenes.scene import Scene
from harness.solver import simulate as simulation
from harness.solver.simulate import adaptive_batch, simulate, simulate_adaptive

SCENE = Scene(e_n=(0.9, 0.5, 0.1), angles_deg=tuple(np.arange(1.0, 90.0, 2.0)))


def truth_of_bench(law):
    """The adaptive integrator at tol 1e-12, and its worst difference from the 2^16-step uniform runs."""
    truth = simulate_adaptive(law, SCENE, 1e-12)
    assert (truth.status == "ok").all(), truth.message[truth.status != "ok"].tolist()
    return truth, worst_error(truth_of(law, SCENE).frame, truth)


def worst_error(frame, truth):
    return max(relative_errors(frame[frame.e_n_target == e], truth[truth.e_n_target == e])["err_max"]
               for e in SCENE.e_n)


SECOND_TABLE = "hertz-kuwabara-kono"
METHODS = {"brute force": False, "graded Richardson": True, "adaptive": None}


def run(law, method, tolerance=1e-6):
    """One method of the converged mode; (frame, force evaluations, seconds)."""
    counted = []
    kernel = simulation.run_kernel

    def counting(batch, history_points=0, rows=None):
        out, history, wall = kernel(batch, history_points, rows)
        counted.append(out[:, 6].sum())
        return out, history, wall
    simulation.run_kernel = counting
    try:
        start = time.perf_counter()
        frame, _ = simulate(law, SCENE, converged=True, extrapolate=METHODS[method], tolerance=tolerance)
        seconds = time.perf_counter() - start
    finally:
        simulation.run_kernel = kernel
    adaptive = frame.message.str.contains("adaptive")
    return frame, float(sum(counted)) + float(frame.steps_per_contact[adaptive].sum()), seconds


def main(smoke=False):
    global SCENE
    if smoke:                                  # the smallest size: one e_n, two angles, two laws, no second table
        SCENE = Scene(e_n=(0.5,), angles_deg=(10.0, 40.0))
    warm = Scene(e_n=(0.5,), angles_deg=(10.0,))
    for method in METHODS:
        run(compose(SECOND_TABLE), method)
    simulate(compose(SECOND_TABLE), warm, steps_per_contact=20)
    header = " | ".join(f"{m + ': evals':>24s} {'wall':>7s} {'error':>8s}" for m in METHODS)
    print(f"{'law':26s} {header} | {'WALL RATIO brute/adaptive':>25s} {'ladder/adaptive':>15s} "
          f"{'truth vs 2^16 steps':>19s}")
    covered = [name for name in LAWS if adaptive_batch(compose(name), warm, 0.5)[1].all()]
    for name in ((SECOND_TABLE, "walton-braun") if smoke else covered):
        law = compose(name)
        truth, check = truth_of_bench(law)
        cells, walls = [], {}
        for method in METHODS:
            frame, evaluations, seconds = run(law, method)
            walls[method] = seconds
            cells.append(f"{evaluations:24.3g} {seconds:7.3f} {worst_error(frame, truth):8.1e}")
        print(f"{name:26s} {' | '.join(cells)} | {walls['brute force'] / walls['adaptive']:25.1f} "
              f"{walls['graded Richardson'] / walls['adaptive']:15.1f} {check:19.1e}")
    if smoke:
        return
    print(f"outside the adaptive integrator (tangential dashpot; converged mode = graded ladder): "
          f"{', '.join(sorted(set(LAWS) - set(covered)))}")
    law = compose(SECOND_TABLE)
    truth, _ = truth_of_bench(law)
    print(f"\n{SECOND_TABLE} at equal error: the stopping tolerance swept\n{'method':18s} {'tolerance':>9s} "
          f"{'evals':>9s} {'wall':>7s} {'error':>8s}")
    for method in METHODS:
        for tolerance in (1e-4, 1e-5, 1e-6, 1e-7):
            if method != "adaptive" and tolerance < 1e-6:
                continue                              # beyond brute force's reach in reasonable time
            frame, evaluations, seconds = run(law, method, tolerance)
            print(f"{method:18s} {tolerance:9.0e} {evaluations:9.3g} {seconds:7.3f} {worst_error(frame, truth):8.1e}")


if __name__ == "__main__":
    main("--smoke" in sys.argv[1:])
