"""The reference engine: runs a law over a scene in the compiled batch kernel and returns the results table."""
import time

import numpy as np
import pandas as pd

from .. import __version__
from ..results import impact_frame
from . import codes as C
from .kernel import integrate
from .plan import plan_batch

CONVERGED_START = 1000           # steps per contact of the first level of the converged ladder
CONVERGED_LIMIT = 2 ** 21        # finest level tried
CONVERGED_TOLERANCE = 1e-7       # change between levels; the error of a second-order scheme is ~ change/3
STATUS_TEXT = {C.STATUS_OK: "ok", C.STATUS_NO_SEPARATION: "no-separation", C.STATUS_NONFINITE: "non-finite"}


def run_kernel(batch, history_points=0, rows=None):
    """Integrate the batch (or the given rows of it); returns (out, history, wall seconds)."""
    params, ints = batch.params, batch.ints
    if rows is not None:
        params, ints = params[rows], ints[rows]
    stride = 0
    history = np.zeros((len(params), history_points, 4))
    if history_points:
        stride = max(1, int(batch.steps_per_contact * 3 // history_points))   # ~3 contact times recorded
    out = np.zeros((len(params), C.N_OUT))
    start = time.perf_counter()
    integrate(params, ints, out, history, stride)
    return out, history, time.perf_counter() - start


def _scaled(out, speed, radius):
    """Outcome vector normalised for the convergence test: velocities / V, R omega / V, t_c and F_max relative."""
    return np.column_stack([out[:, C.O_VZ] / speed, out[:, C.O_VX] / speed, radius * out[:, C.O_W] / speed])


def run_converged(law, scene, e_n):
    """Double the steps per contact until v_n1, v_t1, R omega1 (per V), t_c and F_max change < 1e-7; keep the finest."""
    n = CONVERGED_START
    batch = plan_batch(law, scene, e_n, n)
    out, _, wall = run_kernel(batch)
    levels = np.full(len(out), n)
    change = np.full(len(out), np.inf)
    pending = np.arange(len(out))
    while len(pending) and n < CONVERGED_LIMIT:
        n *= 2
        finer = plan_batch(law, scene, e_n, n)
        new, _, seconds = run_kernel(finer, rows=pending)
        wall += seconds
        old = out[pending]
        diff = np.abs(_scaled(new, scene.speed, scene.radius) - _scaled(old, scene.speed, scene.radius)).max(axis=1)
        for col in (C.O_TC, C.O_FMAX):
            diff = np.maximum(diff, np.abs(new[:, col] - old[:, col]) / np.abs(new[:, col]))
        out[pending] = new
        levels[pending] = n
        change[pending] = diff
        pending = pending[diff > CONVERGED_TOLERANCE]
    dt = batch.dt * CONVERGED_START / levels
    return batch, out, levels, change, dt, wall


def simulate(law, scene, steps_per_contact=1000, converged=False, history_points=0):
    """Results table of `law` over every (e_n, impact) of `scene`; histories {e_n: array} if points are asked for."""
    frames, histories = [], {}
    for e_n in scene.e_n:
        if converged:
            batch, out, levels, change, dt, wall = run_converged(law, scene, e_n)
            messages = [f"converged: {lv} steps/contact, last change {ch:.1e}" if ch <= CONVERGED_TOLERANCE else
                        f"not converged at {lv} steps/contact (change {ch:.1e})" for lv, ch in zip(levels, change)]
            steps = levels
        else:
            batch = plan_batch(law, scene, e_n, steps_per_contact)
            out, history, wall = run_kernel(batch, history_points)
            if history_points:
                histories[e_n] = history
            messages = ["" if status == C.STATUS_OK else
                        f"{STATUS_TEXT[int(status)]} after {int(steps)} steps ({steps * batch.dt:.3g} s of contact)"
                        for status, steps in zip(out[:, C.O_STATUS], out[:, C.O_STEPS])]
            steps, dt = batch.steps_per_contact, batch.dt
        frames.append(impact_frame(
            scene, batch, model=law.name, dialect=law.dialect, engine="reference", engine_version=__version__, dt=dt,
            steps_per_contact=steps, v_n1=out[:, C.O_VZ], v_t1=out[:, C.O_VX], omega1=out[:, C.O_W],
            t_contact=out[:, C.O_TC], f_n_max=out[:, C.O_FMAX], overlap_max=out[:, C.O_AMAX], wall_s=wall / len(out),
            status=[STATUS_TEXT[int(s)] for s in out[:, C.O_STATUS]], message=messages))
    return pd.concat(frames, ignore_index=True), histories
