"""One run of the plan through an external engine as result rows (a failed batch keeps its log), and the input it
would be given."""
import tempfile
from dataclasses import dataclass

import numpy as np

from ..errors import UserError
from ..results import impact_frame
from ..solver.codes import P_MAXSTEPS
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


def run_batch_rows(engine, version, run_batch, run):
    """One run of the plan through an external engine (its name, version and run_batch) as result rows, and its
    FailedRun (None when it ran): a refused or failed run gives 'failed' rows carrying its one-line message."""
    batch = run.batch()
    scene, options = run.scene, run.options_dict
    max_steps = int(batch.params[:, P_MAXSTEPS].max())
    timeout = TIMEOUT_FLOOR_S + SECONDS_PER_ATOM_STEP * len(batch.v_n0) * max_steps
    identity = dict(model=run.law.name, dialect=run.dialect.dialect, engine=engine, engine_version=version,
                    dt=batch.dt, steps_per_contact=batch.steps_per_contact)
    try:
        with tempfile.TemporaryDirectory(prefix=f"harness-{engine}-") as workdir:
            final, wall, _ = run_batch(run.law, scene, batch, max_steps, timeout, workdir, options, observe=run.observe)
    except EngineFailure as exc:
        nan = np.full(len(batch.v_n0), np.nan)
        frame = impact_frame(scene, batch, **identity, v_n1=nan, v_t1=nan, omega1=nan, wall_s=np.nan,
                             status="failed", message=str(exc))
        return frame, FailedRun(engine, batch.e_n, str(exc), exc.log_tail)
    observed = {name: final[name] for name in OBSERVED if run.observe}
    frame = impact_frame(scene, batch, **identity, v_n1=final["v_n1"], v_t1=final["v_t1"], omega1=final["omega1"],
                         wall_s=wall / len(batch.v_n0), status=np.where(final["separated"], "ok", "no-separation"),
                         message="", **observed)
    return frame, None


def render_input(engine, suffix, render_batch, run):
    """(file name, text) of the input one run gives an external engine (harness render); a refusal of the engine's
    input rules is the user's to fix, so it is a UserError."""
    batch = run.batch()
    try:
        text = render_batch(run.law, run.scene, batch, int(batch.params[:, P_MAXSTEPS].max()), run.options_dict)
    except EngineFailure as exc:
        raise UserError(str(exc)) from None
    return f"{engine}-{run.law.name}-en{run.e_n:g}{suffix}", text
