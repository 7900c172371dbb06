"""The free approach from a starting gap (Scene.gap), in closed form: how many steps a row's stepper takes before its
contact's first step, and the state they leave it in. Under a constant acceleration velocity Verlet (and the paper
scheme, which is velocity Verlet on the same momentum) and the leapfrog are exact at their steps, so no step is
integrated here."""
from dataclasses import dataclass

import numpy as np

from ..infra.errors import UserError
from ..submodels.stepping import STEPPER_NAMES
from . import layout as L

FLAT = ("PAPER", "VELOCITY_VERLET", "LEAPFROG")         # against a plane; the others from the centres' distance
WITH_GRAVITY = FLAT                                      # the steppers that apply Scene.gravity
SEARCH = np.arange(-2, 4)                                # steps about the closed form's, for its rounding


@dataclass
class Approach:
    """Per row: free steps before the contact's first, and the start they leave (signed overlap, offsets along the
    tangent and the normal from touching, approach speed, the first step where it is not dt: else 0)."""
    steps: np.ndarray
    alpha0: np.ndarray
    x0: np.ndarray
    z0: np.ndarray
    speed: np.ndarray
    first_h: np.ndarray


def leapfrog(stepper):
    """A leapfrog starts its contact at the first step with overlap >= 0 (a step from a negative overlap ends it);
    the others at the last with overlap <= 0, whose next step drifts into contact."""
    return STEPPER_NAMES[stepper].startswith("LEAPFROG")


def travelled(stepper, v_n, g, dt, k):
    """Distance along the normal after k steps and the speed then: velocity Verlet V t + g t^2/2 and V + g t; the
    leapfrog, whose velocity is the half step's before, V k dt + g dt^2 k (k + 1)/2 and V + g k dt."""
    t = k * dt
    if leapfrog(stepper):
        return v_n * t + g * dt * dt * k * (k + 1) / 2.0, v_n + g * t
    return v_n * t + 0.5 * g * t * t, v_n + g * t


def overlap_after(stepper, gap, v_n, v_t, g, dt, k, centres):
    """Signed overlap after k free steps: -(gap - distance) on a plane, centres - |r| between two centres (r starts
    at (0, centres + gap) and moves at (v_t, -v_n))."""
    along, _ = travelled(stepper, v_n, g, dt, k)
    z = gap - along
    if centres is None:
        return -z, np.zeros_like(z), z
    x = v_t * k * dt
    return centres - np.hypot(x, centres + z), x, z


def touch_estimate(gap, v_n, v_t, g, centres):
    """Time to touch: gap = V t + g t^2/2 on a plane; |r(t)| = centres between two centres, NaN where they miss."""
    if centres is None:
        return np.where(g > 0.0, (np.sqrt(v_n * v_n + 2.0 * g * gap) - v_n) / np.where(g > 0.0, g, 1.0), gap / v_n)
    c, start = centres, centres + gap
    speed2 = v_n * v_n + v_t * v_t
    disc = (v_n * start) ** 2 - speed2 * (start * start - c * c)
    return np.where(disc >= 0.0, (v_n * start - np.sqrt(np.maximum(disc, 0.0))) / speed2, np.nan)


def free_approach(params, ints, gap):
    """The Approach of each kernel row from `gap` (its stepper, time step, incident velocities and gravity read
    from the row). A UserError where two spheres miss each other from that gap."""
    n = len(params)
    stepper = int(ints[0, L.I_STEPPER]) if n else 0
    name = STEPPER_NAMES[stepper]
    dt, v_n, v_t = params[:, L.DT], -params[:, L.VZ0], params[:, L.VX0]
    g = params[:, L.GRAVITY] if name in WITH_GRAVITY else np.zeros(n)
    centres = None
    if name == "LEAPFROG_SPHERE":
        centres = params[:, L.RADIUS] + params[:, L.GEOMETRY_STAND_IN_SPHERE_RADIUS]
    elif name not in FLAT:
        centres = params[:, L.RADIUS] + params[:, L.GEOMETRY_PAIR_CENTRES_LESS_RADIUS]
    t_touch = touch_estimate(gap, v_n, v_t, g, centres)
    if np.isnan(t_touch).any():
        raise UserError(f"from a gap of {gap:g} m the spheres pass each other without touching at the tangential "
                        f"speed {v_t[np.isnan(t_touch)][0]:g} m/s (give a smaller gap or a steeper approach)")
    if name == "PAPER":
        return exact_touch(t_touch, dt, v_n, g)
    base = np.floor(t_touch / dt)
    candidates = np.maximum(base[:, None] + SEARCH[None, :], 0.0)
    alphas = np.stack([overlap_after(stepper, gap, v_n, v_t, g, dt, candidates[:, j], centres)[0]
                       for j in range(len(SEARCH))], axis=1)
    if leapfrog(stepper):
        chosen = np.where(alphas >= 0.0, candidates, np.inf).min(axis=1)
    else:
        chosen = np.where(alphas <= 0.0, candidates, -np.inf).max(axis=1)
    alpha0, x0, z0 = overlap_after(stepper, gap, v_n, v_t, g, dt, chosen, centres)
    return Approach(chosen.astype(np.int64), alpha0, x0, z0, travelled(stepper, v_n, g, dt, chosen)[1],
                    np.zeros(n))


def exact_touch(t_touch, dt, v_n, g):
    """The paper scheme, which locates its events inside a step, starts at the exact touch (the contact's physics
    as from gap 0) with a first step onto the next step of the grid: k0 free steps, touch in (k0 dt, (k0 + 1) dt]."""
    steps = np.maximum(np.ceil(t_touch / dt) - 1.0, 0.0)
    zeros = np.zeros_like(t_touch)
    return Approach(steps.astype(np.int64), zeros, zeros, zeros, v_n + g * t_touch, (steps + 1.0) * dt - t_touch)


def place(params, ints, gap):
    """Start every row of the batch `gap` apart: its free approach (Approach) written into the row's start columns
    and its normal velocity; at gap 0 the rows are left at first touch."""
    approach = free_approach(params, ints, gap)
    params[:, L.ALPHA0], params[:, L.X0], params[:, L.Z0] = approach.alpha0, approach.x0, approach.z0
    params[:, L.FIRST_H] = approach.first_h
    params[:, L.VZ0] = -approach.speed
    return approach
