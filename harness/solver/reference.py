"""The reference engine: runs a law over a scene in the compiled batch kernel and returns the results table."""
import time

import numpy as np
import pandas as pd

from .. import __version__
from ..kinematics import rebound_quantities
from ..results import impact_frame
from . import codes as C
from .kernel import integrate
from .plan import plan_batch

CONVERGED_START = 64             # steps per contact of the first level of the converged ladder
CONVERGED_LIMIT = 2 ** 20        # finest level tried
CONVERGED_TOLERANCE = 1e-6       # between successive Richardson values (v/V, R omega/V, relative t_c and F_max)
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


KEPT = [C.O_VZ, C.O_VX, C.O_W, C.O_TC, C.O_FMAX, C.O_AMAX]     # outcome columns the converged mode extrapolates


def _change(a, b, scene, batch, rows):
    """Largest difference per row of the paper's normalised outcomes e_n, e_t, Omega* (absolute; they are O(1) and
    amplify velocity errors at grazing and near-normal angles) and of t_c and F_max (relative)."""
    def normalised(x):
        q = rebound_quantities(scene.contact, scene.mu, batch.v_n0[rows], batch.v_t0[rows], batch.omega0[rows],
                               x[:, 0], x[:, 1], x[:, 2])
        return np.column_stack([q["e_n"], q["e_t"], q["omega_star"]])
    diff = np.abs(normalised(a) - normalised(b))
    diff = np.where(np.isnan(normalised(b)) & np.isnan(normalised(a)), 0.0, diff)   # e_t of a normal impact
    relative = np.abs(a[:, 3:5] - b[:, 3:5]) / np.abs(b[:, 3:5])
    return np.column_stack([diff, relative]).max(axis=1)


def run_converged(law, scene, e_n, tolerance=CONVERGED_TOLERANCE, extrapolate=None):
    """Richardson-extrapolated ladder: double the steps per contact from 64; the paper scheme's error is ~c h^2
    (onset exact, release, turning point and stick-slip transitions located inside their steps), so
    R_N = f_N + (f_N - f_N/2)/3 removes it; a row stops when R_N and R_N/2 differ by less than `tolerance`,
    twice in a row (one agreement can be a crossing), which bounds the error of R_N/2 and so of R_N. Engine schemes
    (first order) double without extrapolating (extrapolate=False does the same for any law: plain refinement)."""
    extrapolate = law.integrator == "paper" if extrapolate is None else extrapolate
    n = CONVERGED_START
    batch = plan_batch(law, scene, e_n, n)
    out, _, wall = run_kernel(batch)
    plain = out[:, KEPT]
    best = np.full_like(plain, np.nan)          # R needs two levels: nothing to compare with at the first
    levels = np.full(len(out), n)
    change = np.full(len(out), np.inf)
    pending = np.arange(len(out))
    passes = np.zeros(len(out), dtype=int)
    while len(pending) and n < CONVERGED_LIMIT:
        n *= 2
        finer, _, seconds = run_kernel(plan_batch(law, scene, e_n, n), rows=pending)
        wall += seconds
        new = finer[:, KEPT]
        estimate = new + (new - plain[pending]) / 3.0 if extrapolate else new
        out[pending] = finer
        plain[pending] = new
        diff = _change(estimate, best[pending], scene, batch, pending)
        best[pending] = estimate
        levels[pending] = n
        diff = np.where(np.isnan(diff), np.inf, diff)
        passes[pending] = np.where(diff < tolerance, passes[pending] + 1, 0)
        change[pending] = diff
        pending = pending[passes[pending] < 2]
    out[:, KEPT] = best
    dt = batch.dt * CONVERGED_START / levels
    return batch, out, levels, change, dt, wall


def simulate(law, scene, steps_per_contact=1000, converged=False, history_points=0, extrapolate=None):
    """Results table of `law` over every (e_n, impact) of `scene`; histories {e_n: array} if points are asked for."""
    frames, histories = [], {}
    for e_n in scene.e_n:
        if converged:
            batch, out, levels, change, dt, wall = run_converged(law, scene, e_n, extrapolate=extrapolate)
            messages = [f"converged: Richardson on {lv // 2} and {lv} steps/contact, last change {ch:.1e}"
                        if ch <= CONVERGED_TOLERANCE else
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
