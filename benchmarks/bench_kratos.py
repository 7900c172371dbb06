"""Kratos' throughput, side by side in one run: the quick start's sweep (hertz-mindlin, the paper's scene, 45 angles,
e_n 0.5, 1000 steps per contact) as one batched Kratos run against one run per impact (the ratio), and the cost of
an impact-step in Kratos beside LIGGGHTS, YADE and LAMMPS on the same batch: every engine stepped a fixed number of
steps (one chunk, and the length of a contact, so that no sphere leaves early), whole (process start included) and
marginal (the difference of the two: the start-up cancels). Engines that are not installed are named and left out.

    .venv/bin/python benchmarks/bench_kratos.py [--smoke]

--smoke runs the smallest size: four angles at 100 steps per contact.
"""
import sys
import tempfile
import time
from dataclasses import replace

import numpy as np

from harness.engines import ENGINES
from harness.laws import compose
from harness.solver.resolution import RunSpec
from harness.solver.simulate import batch_at
from harness.scenes.scene import Scene

LAW = compose("hertz-mindlin")
REPEATS = 2
SAME = 1e-12        # batched and separate rebounds agree to this relative difference


def timed(engine, scene, spec):
    """(wall seconds of one run of `spec` in its own scratch directory, its final state)."""
    with tempfile.TemporaryDirectory() as workdir:
        start = time.perf_counter()
        final, _, _ = engine.run_batch(LAW, scene, spec, 900, workdir)
        return time.perf_counter() - start, final


def steps_run(spec):
    """The steps an engine takes when no sphere leaves: whole chunks up to the cap."""
    return spec.chunk * spec.chunks


def batching(engine, scene, steps):
    """(batched seconds, separate seconds, impacts, identical) of the sweep in Kratos."""
    batch = batch_at(engine.dialect(LAW.name), scene, 0.5, steps)
    spec = batch.spec
    batched, final = timed(engine, scene, spec)
    separate, alone = 0.0, []
    for i in range(spec.impacts):
        one = RunSpec(spec.e_n, spec.dt, spec.steps_per_contact, spec.step_cap, spec.theta_deg[i:i + 1],
                      spec.v_n0[i:i + 1], spec.v_t0[i:i + 1], spec.omega0[i:i + 1])
        seconds, single = timed(engine, scene, one)
        separate += seconds
        alone.append(single["v_t1"][0])
    return batched, separate, spec.impacts, bool(np.allclose(final["v_t1"], alone, rtol=SAME, atol=0))


def impact_step_costs(engine, scene, steps):
    """(whole, marginal) seconds per impact-step of the batch stepped one chunk and one contact's length (no sphere
    leaves before the last check), each the fastest of REPEATS runs."""
    batch = batch_at(engine.dialect(LAW.name), scene, 0.5, steps)
    short, long = replace(batch.spec, step_cap=0), replace(batch.spec, step_cap=steps - 1)
    t_short = min(timed(engine, scene, short)[0] for _ in range(REPEATS))
    t_long = min(timed(engine, scene, long)[0] for _ in range(REPEATS))
    n = short.impacts
    return t_long / (n * steps_run(long)), (t_long - t_short) / (n * (steps_run(long) - steps_run(short)))


def main(smoke=False):
    scene = Scene(e_n=(0.5,), angles_deg=(10.0, 30.0, 50.0, 70.0)) if smoke else Scene(e_n=(0.5,))
    steps = 100 if smoke else 1000
    kratos = ENGINES["kratos"]
    if not kratos.available():
        print(f"kratos is not installed ({kratos.missing_reason()}); nothing to measure")
        return
    batched, separate, impacts, same = batching(kratos, scene, steps)
    print(f"kratos {kratos.version()}: {impacts} impacts, {steps} steps per contact, hertz-mindlin, e_n = 0.5")
    print(f"batched: 1 run, {batched:.2f} s; separate: {impacts} runs, {separate:.2f} s")
    print(f"RATIO separate/batched: {separate / batched:.1f}x (same results to {SAME:g}: {same})")
    print(f"{'engine':24} {'s per impact-step (whole)':>26} {'(marginal)':>12} {'x kratos':>9}")
    costs = {}
    for name in ("kratos", "liggghts", "yade", "lammps"):
        engine = ENGINES[name]
        if not engine.available():
            print(f"{name:24} not installed: {engine.missing_reason()}")
            continue
        costs[name] = impact_step_costs(engine, scene, steps)
    for name, (whole, marginal) in costs.items():
        print(f"{name + ' ' + ENGINES[name].version():24} {whole:26.3g} {marginal:12.3g} "
              f"{whole / costs['kratos'][0]:9.2f}")


if __name__ == "__main__":
    main("--smoke" in sys.argv[1:])
