"""YADE checks its own arithmetic: a few impacts in double against mpfr150 at the same time step."""
import copy
import tempfile

import numpy as np

from ...solver.codes import P_MAXSTEPS
from ...solver.plan import plan_batch
from ..batches import TIMEOUT_FLOOR_S
from .dialect import dialect as yade_dialect
from .flavours import available
from .script import run_batch


def precision_gap(paper_law, scene, steps_per_contact, precision="mpfr150", samples=3):
    """How far double-precision YADE is from `precision` on the same impacts and dt: a few impacts of the first
    e_n, max relative difference of v_n1, v_t1, omega1 (floor 1e-9 of the speed scale). None if absent."""
    if not available(precision):
        return None
    dialect = yade_dialect(paper_law.name)
    batch = plan_batch(dialect, scene, scene.e_n[0], steps_per_contact)
    rows = np.unique(np.linspace(0, len(batch.v_n0) - 1, samples).round().astype(int))
    small = copy.copy(batch)
    for name in ("params", "ints", "v_n0", "v_t0", "omega0", "theta_deg"):
        setattr(small, name, getattr(batch, name)[rows])
    max_steps = int(small.params[:, P_MAXSTEPS].max())
    results = {}
    for flavour in ("double", precision):
        with tempfile.TemporaryDirectory(prefix=f"harness-yade-{flavour}-") as workdir:
            results[flavour], _, _ = run_batch(paper_law, scene, small, max_steps, TIMEOUT_FLOOR_S * 5, workdir,
                                               {"precision": flavour})
    scale = {"v_n1": scene.speed, "v_t1": scene.speed, "omega1": scene.speed / scene.radius}
    gaps = {}
    for metric, floor in scale.items():
        a, b = results["double"][metric], results[precision][metric]
        gaps[metric] = float(np.max(np.abs(a - b) / np.maximum(np.abs(b), 1e-9 * floor)))
    return {"engine": "yade", "against": precision, "e_n_target": scene.e_n[0],
            "theta_deg": ", ".join(f"{t:g}" for t in small.theta_deg), **gaps}
