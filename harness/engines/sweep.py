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


OBSERVED = ("t_contact", "f_n_max", "overlap_max")


def run_sweep(adapter, paper_law, scene, steps_per_contact, on_frame=None, options=None, observe=False):
    """Every e_n of the scene through `adapter` at the dt of its dialect (equal dt, so agreement is exact); with
    `observe` the rows also get the engine's t_contact, f_n_max and overlap_max (else NaN)."""
    dialect = adapter.dialect(paper_law.name, options)
    frames, failures = [], []
    for e_n in scene.e_n:
        frame, failure = run_batch_rows(adapter, paper_law, dialect, scene, plan_batch(dialect, scene, e_n,
                                                                                        steps_per_contact),
                                        options, observe)
        if failure is not None:
            failures.append(failure)
        frames.append(frame)
        if on_frame is not None:
            on_frame(frame)
    return frames, failures


def run_batch_rows(adapter, paper_law, dialect, scene, batch, options=None, observe=False):
    """One batched engine run as result rows, and its FailedRun (None when it ran): a refused or failed run gives
    'failed' rows carrying its one-line message."""
    max_steps = int(batch.params[:, P_MAXSTEPS].max())
    timeout = TIMEOUT_FLOOR_S + SECONDS_PER_ATOM_STEP * len(batch.v_n0) * max_steps
    identity = dict(model=paper_law.name, dialect=dialect.dialect, engine=adapter.NAME,
                    engine_version=adapter.version(), dt=batch.dt, steps_per_contact=batch.steps_per_contact)
    try:
        with tempfile.TemporaryDirectory(prefix=f"harness-{adapter.NAME}-") as workdir:
            final, wall, _ = adapter.run_batch(paper_law, scene, batch, max_steps, timeout, workdir, options,
                                               observe=observe)
    except EngineFailure as exc:
        nan = np.full(len(batch.v_n0), np.nan)
        frame = impact_frame(scene, batch, **identity, v_n1=nan, v_t1=nan, omega1=nan, wall_s=np.nan,
                             status="failed", message=str(exc))
        return frame, FailedRun(adapter.NAME, batch.e_n, str(exc), exc.log_tail)
    observed = {name: final[name] for name in OBSERVED if observe}
    frame = impact_frame(scene, batch, **identity, v_n1=final["v_n1"], v_t1=final["v_t1"], omega1=final["omega1"],
                         wall_s=wall / len(batch.v_n0), status=np.where(final["separated"], "ok", "no-separation"),
                         message="", **observed)
    return frame, None


def precision_gap(adapter, paper_law, scene, steps_per_contact, precision="mpfr150", samples=3):
    """How far the double-precision engine is from `precision` on the same impacts and dt: a few impacts of the
    first e_n, max relative difference of v_n1, v_t1, omega1 (floor 1e-9 of the speed scale). None if absent."""
    import copy
    if not adapter.available(precision):
        return None
    dialect = adapter.dialect(paper_law.name)
    batch = plan_batch(dialect, scene, scene.e_n[0], steps_per_contact)
    rows = np.unique(np.linspace(0, len(batch.v_n0) - 1, samples).round().astype(int))
    small = copy.copy(batch)
    for name in ("params", "ints", "v_n0", "v_t0", "omega0", "theta_deg"):
        setattr(small, name, getattr(batch, name)[rows])
    max_steps = int(small.params[:, P_MAXSTEPS].max())
    results = {}
    for flavour in ("double", precision):
        with tempfile.TemporaryDirectory(prefix=f"harness-{adapter.NAME}-{flavour}-") as workdir:
            results[flavour], _, _ = adapter.run_batch(paper_law, scene, small, max_steps, TIMEOUT_FLOOR_S * 5,
                                                       workdir, {"precision": flavour})
    scale = {"v_n1": scene.speed, "v_t1": scene.speed, "omega1": scene.speed / scene.radius}
    gaps = {}
    for metric, floor in scale.items():
        a, b = results["double"][metric], results[precision][metric]
        gaps[metric] = float(np.max(np.abs(a - b) / np.maximum(np.abs(b), 1e-9 * floor)))
    return {"engine": adapter.NAME, "against": precision, "e_n_target": scene.e_n[0],
            "theta_deg": ", ".join(f"{t:g}" for t in small.theta_deg), **gaps}
