"""Compiled small-system integrator: a handful of spheres in the x-z plane (spins about y) under gravity, on a wall
at z = 0 and under an optional one at z = ceiling, every contact at once, one variant per row.

Velocity Verlet at a fixed step: half kick with the last forces and gravity, drift, each contact's forces from the
new positions and the half-step velocities (system_contacts.contact_forces, through the sub-model dispatch), closing
half kick. A contact is created at the first step its overlap is positive and its history cleared at the first step
it is not (an event each); the state is recorded at the stated times, the energy at every step."""
import math

import numpy as np
from numba import njit

from ..infra.jit import compiled
from ..submodels.tangential.state import N_TSTATE
from . import layout as L
from .dispatch import NORMAL_HISTORY
from .state import S_FN, S_FT
from .system_contacts import (B_I, B_M, B_R, B_VX, B_VZ, B_W, B_X, B_Z, N_CONTACT, clear, contact_forces, geometry,
                              relative_motion, stored_energy)

TRACE = (B_X, B_Z, B_VX, B_VZ, B_W)          # what the trace records of each body
E_TIME, E_KIND, E_CONTACT, E_VN, E_SLIP = 0, 1, 2, 3, 4   # an event: time, kind, contact, V_n (> 0 parting), slip
N_EVENT = 5
TOUCH, PART = 1.0, -1.0                      # event kinds
F_ALPHA, F_FN, F_FT = 0, 1, 2                # a contact at the end: overlap, normal and tangential force
N_FINAL = 3
M_GAIN, M_STEPS, M_TIME, M_STATUS, M_EVENTS = 0, 1, 2, 3, 4   # per variant: largest energy gain after gain_from,
N_METRICS = 5                                # steps, end time, status, events (all, also those not kept)
STATUS_OK, STATUS_NONFINITE = 0.0, 1.0


@njit(cache=True)
def integrate_systems(bodies, pairs, params, ints, gravity, ceiling, dt, steps, grid, gain_from, start_friction,
                      trace, energy, events, final, metrics, ext):
    """Integrate every variant (row): `bodies` (variants, bodies, N_BODY) to their final state; `trace` (variants,
    times, bodies, len(TRACE)) and `energy` (variants, times) at the times of `grid`; `events` (variants, kept,
    N_EVENT); `final` (variants, contacts, N_FINAL); `metrics` (variants, N_METRICS). start_friction (variants): 1 where
    the forces of the starting state include the tangential force, 0 where they are the normal force alone."""
    n_bodies, n_pairs = bodies.shape[1], pairs.shape[0]
    for v in range(bodies.shape[0]):
        forces = np.zeros((n_bodies, 3))
        contacts = np.zeros((n_pairs, N_CONTACT))
        tangential = np.zeros((n_pairs, N_TSTATE))
        touching = np.zeros(n_pairs, dtype=np.int64)
        changed = np.zeros(n_pairs, dtype=np.int64)
        work = np.zeros(2 * N_TSTATE + NORMAL_HISTORY)
        touched = np.zeros((n_pairs, 2))
        for k in range(n_pairs):
            clear(contacts[k], tangential[k], ints[v, k, L.I_NORMAL])
        integrate_variant(bodies[v], pairs, params[v], ints[v], gravity[v], ceiling[v], dt[v], steps[v], grid,
                          gain_from[v], start_friction[v], trace[v], energy[v], events[v], final[v], metrics[v],
                          forces, contacts, tangential, touching, changed, touched, work, ext)


@compiled
def integrate_variant(bodies, pairs, p, ints, g, ceiling, h, steps, grid, gain_from, start_friction, trace, energy,
                      events, final, metrics, forces, contacts, tangential, touching, changed, touched, work, ext):
    """One variant from its initial state for `steps` steps of h (or to a non-finite state)."""
    ot, scratch, history = work[0:N_TSTATE], work[N_TSTATE:2 * N_TSTATE], work[2 * N_TSTATE:]
    collide(bodies, forces, pairs, p, ints, ceiling, 0.0, contacts, tangential, touching, changed, touched, ot,
            scratch, history, ext, start_friction)      # the forces of the starting state, for the first half kick
    n_events = note_events(bodies, pairs, ceiling, changed, touched, 0.0, events, 0)
    next_time = record(bodies, pairs, p, ints, g, contacts, tangential, touching, grid, 0, 0.0, h, trace, energy)
    e_ref, gain, status, t = math.nan, 0.0, STATUS_OK, 0.0
    if gain_from <= 0.0:
        e_ref = total_energy(bodies, pairs, p, ints, g, contacts, tangential, touching)
    done = 0
    for step in range(steps):
        kick_drift(bodies, forces, g, h)
        collide(bodies, forces, pairs, p, ints, ceiling, h, contacts, tangential, touching, changed, touched, ot,
                scratch, history, ext, 1.0)
        kick(bodies, forces, g, h)
        done = step + 1
        t = done * h
        n_events = note_events(bodies, pairs, ceiling, changed, touched, t, events, n_events)
        if not finite(bodies):
            status = STATUS_NONFINITE
            break
        e_now = total_energy(bodies, pairs, p, ints, g, contacts, tangential, touching)
        if t >= gain_from - 0.5 * h:
            if e_ref != e_ref:
                e_ref = e_now
            gain = max(gain, e_now - e_ref)
        next_time = record(bodies, pairs, p, ints, g, contacts, tangential, touching, grid, next_time, t, h, trace,
                           energy)
    for k in range(next_time, grid.shape[0]):
        energy[k] = math.nan
        for b in range(bodies.shape[0]):
            for q in range(len(TRACE)):
                trace[k, b, q] = math.nan
    for k in range(pairs.shape[0]):
        final[k, F_ALPHA] = geometry(bodies, pairs[k, 0], pairs[k, 1], ceiling)[0]
        final[k, F_FN] = contacts[k, S_FN] if touching[k] else 0.0
        final[k, F_FT] = contacts[k, S_FT] if touching[k] else 0.0
    metrics[M_GAIN], metrics[M_STEPS], metrics[M_TIME] = gain, done, t
    metrics[M_STATUS], metrics[M_EVENTS] = status, n_events


@njit(cache=True, inline="always")
def kick_drift(bodies, forces, g, h):
    """Half kick with the last forces and gravity, then the drift over h."""
    for b in range(bodies.shape[0]):
        m = bodies[b, B_M]
        bodies[b, B_VX] += 0.5 * h * forces[b, 0] / m
        bodies[b, B_VZ] += 0.5 * h * (forces[b, 1] / m - g)
        bodies[b, B_W] += 0.5 * h * forces[b, 2] / bodies[b, B_I]
        bodies[b, B_X] += h * bodies[b, B_VX]
        bodies[b, B_Z] += h * bodies[b, B_VZ]


@njit(cache=True, inline="always")
def kick(bodies, forces, g, h):
    """Closing half kick with the new forces and gravity."""
    for b in range(bodies.shape[0]):
        m = bodies[b, B_M]
        bodies[b, B_VX] += 0.5 * h * forces[b, 0] / m
        bodies[b, B_VZ] += 0.5 * h * (forces[b, 1] / m - g)
        bodies[b, B_W] += 0.5 * h * forces[b, 2] / bodies[b, B_I]


@njit(cache=True, inline="always")
def collide(bodies, forces, pairs, p, ints, ceiling, h, contacts, tangential, touching, changed, touched, ot,
            scratch, history, ext, friction):
    """Every contact's forces at the drifted positions into `forces` (F_x, F_z, torque per body); a contact
    created where its overlap turns positive (its V_n and slip before any of its force acts into `touched`),
    cleared where it ends (changed: +1, -1, else 0); each tangential force times `friction` (1, or 0 for none)."""
    for b in range(bodies.shape[0]):
        forces[b, 0] = forces[b, 1] = forces[b, 2] = 0.0
    for k in range(pairs.shape[0]):
        i, j = pairs[k, 0], pairs[k, 1]
        alpha, nx, nz = geometry(bodies, i, j, ceiling)
        changed[k] = 0
        if alpha > 0.0:
            rate, slip = relative_motion(bodies, i, j, nx, nz, p[k, L.LEVER] * alpha)
            if touching[k] == 0:
                touching[k], changed[k] = 1, 1
                touched[k, 0], touched[k, 1] = -rate, slip
            f_n, f_t = contact_forces(contacts[k], tangential[k], ot, p[k], ints[k], h, scratch, history, alpha,
                                      rate, slip, ext)
            f_t *= friction
            fx, fz = f_n * nx + f_t * nz, f_n * nz - f_t * nx
            forces[i, 0] += fx
            forces[i, 1] += fz
            shorter = p[k, L.TORQUE_LEVER] * alpha
            forces[i, 2] -= (bodies[i, B_R] - shorter) * f_t
            if j >= 0:
                forces[j, 0] -= fx
                forces[j, 1] -= fz
                forces[j, 2] -= (bodies[j, B_R] - shorter) * f_t
        elif touching[k] == 1:
            touching[k], changed[k] = 0, -1
            clear(contacts[k], tangential[k], ints[k, L.I_NORMAL])


@njit(cache=True, inline="always")
def note_events(bodies, pairs, ceiling, changed, touched, t, events, n_events):
    """Each contact created or cleared this step, with its bodies' relative normal velocity (> 0 parting) and slip:
    at a touch before the contact's force acts (the half-step velocities), at a parting at the step's end; events
    beyond the room kept are counted, not written."""
    for k in range(pairs.shape[0]):
        if changed[k] != 0:
            v_n, slip = touched[k, 0], touched[k, 1]
            if changed[k] < 0:
                _, nx, nz = geometry(bodies, pairs[k, 0], pairs[k, 1], ceiling)
                rate, slip = relative_motion(bodies, pairs[k, 0], pairs[k, 1], nx, nz, 0.0)
                v_n = -rate
            if n_events < events.shape[0]:
                e = events[n_events]
                e[E_TIME], e[E_CONTACT], e[E_VN], e[E_SLIP] = t, k, v_n, slip
                e[E_KIND] = TOUCH if changed[k] > 0 else PART
            n_events += 1
    return n_events


@njit(cache=True, inline="always")
def finite(bodies):
    """Every body's position, velocity and spin are numbers."""
    for b in range(bodies.shape[0]):
        for q in TRACE:
            if not math.isfinite(bodies[b, q]):
                return False
    return True


@njit(cache=True, inline="always")
def total_energy(bodies, pairs, p, ints, g, contacts, tangential, touching):
    """E = sum of m v^2/2 + I w^2/2 + m g z over the bodies, plus what each contact holds (stored_energy)."""
    e = 0.0
    for b in range(bodies.shape[0]):
        m = bodies[b, B_M]
        e += 0.5 * m * (bodies[b, B_VX] ** 2 + bodies[b, B_VZ] ** 2) + 0.5 * bodies[b, B_I] * bodies[b, B_W] ** 2
        e += m * g * bodies[b, B_Z]
    for k in range(pairs.shape[0]):
        if touching[k]:
            e += stored_energy(contacts[k], tangential[k], p[k], ints[k])
    return e


@njit(cache=True, inline="always")
def record(bodies, pairs, p, ints, g, contacts, tangential, touching, grid, next_time, t, h, trace, energy):
    """The state and energy at each stated time within half a step of t; returns the next time to record."""
    while next_time < grid.shape[0] and grid[next_time] <= t + 0.5 * h:
        for b in range(bodies.shape[0]):
            for q in range(len(TRACE)):
                trace[next_time, b, q] = bodies[b, TRACE[q]]
        energy[next_time] = total_energy(bodies, pairs, p, ints, g, contacts, tangential, touching)
        next_time += 1
    return next_time
