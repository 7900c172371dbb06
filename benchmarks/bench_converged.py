"""The converged mode against brute-force refinement, side by side in one run, for every law on a 3 e_n x 45 angle
sweep: brute force doubles the steps per contact from 64 until two successive results agree to 1e-6 twice in a row
(the converged mode's own stopping rule, on plain results); the converged mode does the same on Richardson values
of graded meshes. Printed: impact-steps taken, wall time, the error reached against the converged reference
(harness.cost), and the cost ratios. A second table compares the two at equal error reached (hertz-mindlin),
the stopping tolerance of each swept.

    .venv/bin/python benchmarks/bench_converged.py
"""
import time

import numpy as np

from harness.cost import relative_errors, truth_of
from harness.laws import LAWS, compose
from harness.scene import Scene
from harness.solver import reference
from harness.solver.reference import simulate

SCENE = Scene(e_n=(0.9, 0.5, 0.1), angles_deg=tuple(np.arange(1.0, 90.0, 2.0)))


def worst_error(frame, truth):
    return max(relative_errors(frame[frame.e_n_target == e], truth[truth.e_n_target == e])["err_max"]
               for e in SCENE.e_n)


def run(law, extrapolate, tolerance=1e-6):
    """The ladder with or without extrapolation; (frame, impact-steps, seconds)."""
    counted = []
    kernel = reference.run_kernel

    def counting(batch, history_points=0, rows=None):
        out, history, wall = kernel(batch, history_points, rows)
        counted.append(out[:, 6].sum())
        return out, history, wall
    reference.run_kernel = counting
    try:
        start = time.perf_counter()
        frame, _ = simulate(law, SCENE, converged=True, extrapolate=extrapolate, tolerance=tolerance)
        seconds = time.perf_counter() - start
    finally:
        reference.run_kernel = kernel
    return frame, float(sum(counted)), seconds


def main():
    simulate(compose("hertz-mindlin"), SCENE, steps_per_contact=20)
    print(f"{'law':26s} {'brute force: steps':>19s} {'wall':>7s} {'error':>8s} | {'converged: steps':>16s} {'wall':>7s} "
          f"{'error':>8s} | {'RATIO steps':>11s} {'wall':>6s}")
    for name in LAWS:
        law = compose(name)
        truth, _ = truth_of(law, SCENE)
        brute, brute_steps, brute_s = run(law, extrapolate=False)
        conv, conv_steps, conv_s = run(law, extrapolate=True)
        print(f"{name:26s} {brute_steps:19.3g} {brute_s:7.3f} {worst_error(brute, truth):8.1e} | {conv_steps:16.3g} "
              f"{conv_s:7.3f} {worst_error(conv, truth):8.1e} | {brute_steps / conv_steps:11.2f} "
              f"{brute_s / conv_s:6.2f}")

    law = compose("hertz-mindlin")
    truth, _ = truth_of(law, SCENE)
    print(f"\nhertz-mindlin at equal error: the stopping tolerance swept\n{'method':12s} {'tolerance':>9s} "
          f"{'steps':>9s} {'wall':>7s} {'error':>8s}")
    for extrapolate in (False, True):
        for tolerance in (1e-4, 1e-5, 1e-6):
            frame, steps, seconds = run(law, extrapolate, tolerance)
            print(f"{'converged' if extrapolate else 'brute force':12s} {tolerance:9.0e} {steps:9.3g} {seconds:7.3f} "
                  f"{worst_error(frame, truth):8.1e}")


if __name__ == "__main__":
    main()
