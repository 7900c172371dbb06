"""Run a law through an external engine, one batched run per e_n, as result rows; a failed batch keeps its log."""
import tempfile
from dataclasses import dataclass

import numpy as np

from ..results import impact_frame
from ..solver.codes import P_MAXSTEPS
from ..solver.plan import plan_batch
from .runner import EngineFailure

TIMEOUT_FLOOR_S = 120.0
SECONDS_PER_ATOM_STEP = 2e-6        # generous: 30x what LIGGGHTS needs here


@dataclass
class FailedRun:
    """One engine batch that produced nothing usable, with the log tail for the report."""
    engine: str
    e_n: float
    message: str
    log_tail: str


def run_sweep(adapter, paper_law, scene, steps_per_contact, on_frame=None, options=None):
    """Every e_n of the scene through `adapter` at the dt of its dialect (equal dt, so agreement is exact)."""
    dialect = adapter.dialect(paper_law.name, options)
    frames, failures = [], []
    for e_n in scene.e_n:
        batch = plan_batch(dialect, scene, e_n, steps_per_contact)
        max_steps = int(batch.params[:, P_MAXSTEPS].max())
        timeout = TIMEOUT_FLOOR_S + SECONDS_PER_ATOM_STEP * len(batch.v_n0) * max_steps
        identity = dict(model=paper_law.name, dialect=dialect.dialect, engine=adapter.NAME,
                        engine_version=adapter.version(), dt=batch.dt, steps_per_contact=steps_per_contact)
        try:
            with tempfile.TemporaryDirectory(prefix=f"harness-{adapter.NAME}-") as workdir:
                final, wall, _ = adapter.run_batch(paper_law, scene, batch, max_steps, timeout, workdir, options)
            separated = final["separated"]
            frame = impact_frame(scene, batch, **identity, v_n1=final["v_n1"], v_t1=final["v_t1"],
                                 omega1=final["omega1"], wall_s=wall / len(batch.v_n0),
                                 status=np.where(separated, "ok", "no-separation"), message="")
        except EngineFailure as exc:
            failures.append(FailedRun(adapter.NAME, e_n, str(exc), exc.log_tail))
            nan = np.full(len(batch.v_n0), np.nan)
            frame = impact_frame(scene, batch, **identity, v_n1=nan, v_t1=nan, omega1=nan, wall_s=np.nan,
                                 status="failed", message=str(exc))
        frames.append(frame)
        if on_frame is not None:
            on_frame(frame)
    return frames, failures
