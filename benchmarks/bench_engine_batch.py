"""One batched engine run of a 45-angle sweep against 45 separate runs of one sphere each, side by side.

Run: .venv/bin/python benchmarks/bench_engine_batch.py [liggghts|yade] [--smoke]   (goal: batched at least 20x faster)

--smoke runs the smallest size: four angles at 100 steps per contact.
"""
import sys
import tempfile
import time
from dataclasses import replace

import numpy as np

from harness.engines import ENGINES
from harness.laws import compose
from harness.solver.simulate import batch_at
from harness.scenes.scene import Scene

STEPS = 1000


def one_row(batch, i):
    """The batch reduced to its i-th impact (its spec's incident conditions and its kernel rows)."""
    spec = replace(batch.spec, **{name: getattr(batch.spec, name)[i:i + 1]
                                  for name in ("theta_deg", "v_n0", "v_t0", "omega0")})
    return replace(batch, spec=spec, **{name: getattr(batch, name)[i:i + 1]
                                        for name in ("params", "ints", "tangential_active")})


def timed_run(engine, law, scene, batch):
    with tempfile.TemporaryDirectory() as workdir:
        start = time.perf_counter()
        final, _, _ = engine.run_batch(law, scene, batch.spec, 600, workdir)
        return time.perf_counter() - start, final


def main(name, smoke=False):
    global STEPS
    engine = ENGINES[name]
    if not engine.available():
        print(f"{name} is not installed; nothing to measure")
        return
    scene = Scene(e_n=(0.5,), angles_deg=(10.0, 30.0, 50.0, 70.0)) if smoke else Scene(e_n=(0.5,))
    STEPS = 100 if smoke else STEPS
    law = compose("hertz-mindlin")
    batch = batch_at(engine.dialect(law.name), scene, 0.5, STEPS)
    batched, final = timed_run(engine, law, scene, batch)
    separate, results = 0.0, []
    for i in range(len(batch.v_n0)):
        seconds, single = timed_run(engine, law, scene, one_row(batch, i))
        separate += seconds
        results.append(single["v_t1"][0])
    same = np.allclose(final["v_t1"], results, rtol=0, atol=0)
    print(f"{name}: {len(batch.v_n0)} impacts, {STEPS} steps per contact, hertz-mindlin, e_n = 0.5")
    print(f"batched: 1 run, {batched:.2f} s; separate: {len(batch.v_n0)} runs, {separate:.2f} s")
    print(f"RATIO separate/batched: {separate / batched:.1f}x (identical results: {same})")


if __name__ == "__main__":
    names = [a for a in sys.argv[1:] if not a.startswith("--")]
    main(names[0] if names else "liggghts", "--smoke" in sys.argv[1:])
