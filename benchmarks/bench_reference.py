"""Reference solver throughput: a 9 e_n x 45 angle hertz-mindlin sweep at 1000 steps per contact through the
compiled integrator on one thread and on every core, side by side with LIGGGHTS running the same batches (its deck as
harness writes it, start-up measured by the same deck stopped after one step and subtracted); then all seven laws on
the default sweep.

    .venv/bin/python benchmarks/bench_reference.py [--smoke]
"""
import sys
import tempfile
import time
from dataclasses import replace

import numpy as np

from harness.engines import liggghts
from harness.laws import LAWS, compose
from harness.scenes.scene import Scene
from harness.solver import codes as C
from harness.solver.extension import table as extension_table
from harness.solver.kernel import integrate
from harness.solver.simulate import batch_at, simulate
from harness.solver.threads import THREADS

STEPS = 1000


def reference_seconds(batches, threads):
    """Wall time and impact-steps of the compiled integrator over the batches (compiled before timing)."""
    ext = extension_table()

    def one(batch):
        out = np.zeros((len(batch.params), C.N_OUT))
        integrate(batch.params, batch.ints, out, np.zeros((len(batch.params), 0, 4)), 0, ext, threads=threads)
        return out
    one(batches[0])
    start = time.perf_counter()
    steps = sum(int(one(batch)[:, C.O_STEPS].sum()) for batch in batches)
    return time.perf_counter() - start, steps


def liggghts_seconds(law, scene, batches):
    """LIGGGHTS' wall time over the same batches, and its start-up (the same decks stopped after one step)."""
    total = startup = 0.0
    for batch in batches:
        with tempfile.TemporaryDirectory(prefix="harness-bench-") as workdir:
            total += liggghts.ENGINE.run_batch(law, scene, batch.spec, 600, workdir)[1]
        with tempfile.TemporaryDirectory(prefix="harness-bench-") as workdir:
            startup += liggghts.ENGINE.run_batch(law, scene, replace(batch.spec, step_cap=1), 600, workdir)[1]
    return total, startup


def main(smoke=False):
    e_n = (0.5,) if smoke else tuple(round(0.1 * i, 1) for i in range(1, 10))
    scene = Scene(e_n=e_n, angles_deg=(10.0, 40.0) if smoke else None, psi1_star=None) if smoke else Scene(e_n=e_n)
    law = compose("hertz-mindlin")
    batches = [batch_at(law, scene, e, STEPS) for e in scene.e_n]
    impacts = sum(len(b.v_n0) for b in batches)
    print(f"hertz-mindlin, {len(batches)} e_n x {impacts // len(batches)} angles, {STEPS} steps per contact")
    rates = {}
    for threads in sorted({1, THREADS}):
        seconds, steps = reference_seconds(batches, threads)
        rates[threads] = seconds / steps * 1e6
        print(f"reference, {threads} thread(s): {steps} impact-steps in {seconds:.3f} s = {rates[threads]:.4f} us per "
              f"impact-step")
    if liggghts.ENGINE.available():
        dialect_batches = [batch_at(liggghts.dialect(law.name), scene, e, STEPS) for e in scene.e_n]
        total, startup = liggghts_seconds(law, scene, dialect_batches)
        reference, _ = reference_seconds(dialect_batches, 1)
        print(f"liggghts: {total:.3f} s for the same sweep, of which start-up {startup:.3f} s")
        print(f"RATIO liggghts/reference (its dialect, one thread), start-up excluded: "
              f"{(total - startup) / reference:.1f}; with start-up: {total / reference:.1f}")
    else:
        print(f"liggghts: not available ({liggghts.ENGINE.missing_reason()}), no side-by-side timing")
    if smoke:
        return
    start = time.perf_counter()
    default = Scene()
    for name in LAWS:
        simulate(compose(name), default, steps_per_contact=STEPS)
    print(f"all {len(LAWS)} laws on the default sweep ({len(default.e_n)} e_n x {len(default.angles_deg)} angles, "
          f"{STEPS} steps/contact): {time.perf_counter() - start:.2f} s")


if __name__ == "__main__":
    main("--smoke" in sys.argv[1:])
