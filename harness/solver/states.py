"""Each impact's state at the times a scene names (Scene.at_times), after step k = ceil(t/dt - 1e-9), its time k dt:
from the free approach before its contact (approach.py), the kernel's steps in it, the free flight after it."""
import numpy as np

from . import codes as C
from . import layout as L
from .approach import FLAT, WITH_GRAVITY, leapfrog, overlap_after
from ..scenes.scene import state_steps as named_steps
from ..submodels.stepping import STEPPER_NAMES

COLUMNS = ("t", "overlap", "f_n", "f_t", "v_n", "v_t", "omega")


def state_steps(times, dt):
    """The steps of the named times (harness.scenes.scene.state_steps) as an array."""
    return np.asarray(named_steps(times, dt), dtype=np.int64)


def kernel_markers(batch, times):
    """The array the kernel records states into (kernel.record_states): (rows, times, 7), column 0 the step of the
    row's own count (its free approach's steps taken off), the rest NaN."""
    steps = state_steps(times, batch.dt)
    marks = np.full((len(batch.params), len(steps), len(COLUMNS)), np.nan)
    marks[:, :, 0] = steps[None, :] - batch.free_steps[:, None]
    return marks


def states(batch, out, recorded, times, gap):
    """(rows, times, 7) states in COLUMNS: before the row's start its free approach from `gap`, from its first step
    to its last the kernel's records, after a release its free flight (NaN after a row that did not separate). v_n,
    v_t and omega as the results table's v_n1, v_t1, omega1 (v_n > 0 away from the wall)."""
    steps = state_steps(times, batch.dt)
    result = recorded.copy()
    result[:, :, 0] = steps[None, :] * batch.dt
    for i, p in enumerate(batch.params):
        stepper = int(batch.ints[i, L.I_STEPPER])
        own = recorded[i, :, 0]
        before = own <= 0
        if before.any():
            incident = (batch.v_n0[i], batch.v_t0[i], batch.omega0[i])
            result[i, before, 1:] = approach_state(stepper, p, incident, gap, batch.dt, steps[before])
        after = own > out[i, C.O_STEPS]
        if out[i, C.O_STATUS] == C.STATUS_OK:
            start = batch.free_steps[i] * batch.dt + (batch.dt - p[L.FIRST_H] if p[L.FIRST_H] > 0.0 else 0.0)
            since = steps[after] * batch.dt - (start + out[i, C.O_TC])
            result[i, after, 1:] = flight_state(stepper, p, out[i], own[after] - out[i, C.O_STEPS], since)
        else:
            result[i, after, 1:] = np.nan
    return result


def gravity_of(stepper, p):
    return p[L.GRAVITY] if STEPPER_NAMES[stepper] in WITH_GRAVITY else 0.0


def centres_of(stepper, p):
    """The centres' distance at touch for a stepper that measures the overlap from it, else None (a plane)."""
    name = STEPPER_NAMES[stepper]
    if name in FLAT:
        return None
    offset = L.GEOMETRY_STAND_IN_SPHERE_RADIUS if name == "LEAPFROG_SPHERE" else L.GEOMETRY_PAIR_CENTRES_LESS_RADIUS
    return p[L.RADIUS] + p[offset]


def approach_state(stepper, p, incident, gap, dt, steps):
    """(overlap, F_n, F_t, v_n, v_t, omega) after each of `steps` of the free approach from `gap`: no force, the
    incident velocities and gravity's gain."""
    v_n, v_t, omega = incident
    g = gravity_of(stepper, p)
    k = steps.astype(float)
    alpha, _, _ = overlap_after(stepper, gap, v_n, v_t, g, dt, k, centres_of(stepper, p))
    zeros = np.zeros_like(k)
    return np.column_stack([alpha, zeros, zeros, -(v_n + g * k * dt), v_t + zeros, omega + zeros])


def flight_state(stepper, p, last, steps, since):
    """(overlap, F_n, F_t, v_n, v_t, omega) `steps` after the kernel's last step, `since` seconds after its end (the
    paper scheme's located release falls inside its last step): the free flight from the kernel's last state
    (velocity Verlet exact under gravity: alpha - v t + g t^2/2; the leapfrog's half-step velocities: g dt^2 m (m +
    1)/2)."""
    dt, g = p[L.DT], gravity_of(stepper, p)
    k = steps.astype(float)
    t = since
    v_z, v_x, omega = last[C.O_VZ], last[C.O_VX], last[C.O_W]
    fall = g * dt * dt * k * (k + 1) / 2.0 if leapfrog(stepper) else 0.5 * g * t * t
    centres = centres_of(stepper, p)
    if centres is None:
        alpha = last[C.O_ALPHA] - v_z * t + fall
    else:
        x = last[C.O_X] + v_x * t
        z = centres + last[C.O_Z] - p[L.RADIUS] + v_z * t
        alpha = centres - np.hypot(x, z)
    zeros = np.zeros_like(k)
    return np.column_stack([alpha, zeros, zeros, v_z - g * t, v_x + zeros, omega + zeros])
