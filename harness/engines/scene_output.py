"""What the LAMMPS family's scene inputs write and how harness reads it back into the small-system integrator's
SystemResult: `start.dump` and `final.dump` (every sphere's `id x z vx vz omegay fz` before and after the run),
`series.dump` (the same at the series' recorded times, and for a bounce every step near the wall), and for a stack
each engine's own dumps of the contact forces at the end (read by the engine, last_frame)."""
import math
import os
from dataclasses import dataclass

import numpy as np

from ..solver.system import (E_CONTACT, E_KIND, E_SLIP, E_TIME, E_VN, M_EVENTS, M_GAIN, M_STATUS, M_STEPS, M_TIME,
                             N_EVENT, N_FINAL, N_METRICS, PART, STATUS_NONFINITE, STATUS_OK, TOUCH, F_ALPHA, F_FN,
                             F_FT)
from ..solver.system_contacts import WALL_ABOVE, WALL_BELOW
from ..solver.system_rows import contact_properties, sphere_mass
from ..solver.system_run import SystemResult, contact_pairs
from .dumps import dump_frames
from .runner import EngineFailure

COLUMNS = 7                     # id x z vx vz omegay fz
X, Z, VX, VZ, W, FZ = 1, 2, 3, 4, 5, 6


@dataclass(frozen=True)
class ContactScene:
    """What an engine's contact settings read of a scene (harness.scenes.scene.Scene's contact, speed, mu, E, nu and
    spheres) for one contact of a scene case: the wall's, or a pair's (contact_properties of two spheres)."""
    contact: object
    speed: float
    mu: float
    E: float
    nu: float
    spheres: tuple | None = None


def contact_scenes(case):
    """(the wall's ContactScene, a pair's or None) of a scene case: the contacts its spheres make."""
    v = case.variant
    radius = v.spheres[0].radius
    wall = ContactScene(contact_properties(radius, None, v.E, v.nu, v.rho), v.speed, v.mu, v.E, v.nu)
    if len(v.spheres) < 2:
        return wall, None
    return wall, ContactScene(contact_properties(radius, radius, v.E, v.nu, v.rho), v.speed, v.mu, v.E, v.nu)


def box(case):
    """(x_lo, x_hi, z_lo, z_hi, half width in y) holding every sphere for the whole run: its flight under gravity
    (or at constant speed without), the wall at z = 0 and the ceiling."""
    v = case.variant
    duration = v.steps * v.dt
    radius = max(s.radius for s in v.spheres)
    reach = max(abs(s.vx) for s in v.spheres) * duration + 4.0 * radius
    top = max(s.z + (max(s.vz, 0.0) ** 2 / (2.0 * v.gravity) if v.gravity > 0 else max(s.vz, 0.0) * duration)
              for s in v.spheres)
    z_hi = v.ceiling if v.ceiling is not None else top
    return (min(s.x for s in v.spheres) - reach, max(s.x for s in v.spheres) + reach, -2.0 * radius,
            z_hi + 4.0 * radius, 2.0 * radius)


def read_dump(path, engine, n_bodies):
    """{step: rows (id order)} of a dump of `id x z vx vz omegay fz`; EngineFailure when missing or malformed."""
    if not os.path.exists(path):
        raise EngineFailure(f"{engine} wrote no {os.path.basename(path)}")
    steps, rows = dump_frames(path, engine, COLUMNS)
    frames = {}
    for step in np.unique(steps):
        frame = rows[steps == step]
        frame = frame[np.argsort(frame[:, 0])]
        if len(frame) != n_bodies:
            raise EngineFailure(f"{engine} {os.path.basename(path)} holds {len(frame)} spheres at step {step}, "
                                f"not {n_bodies}")
        frames[int(step)] = frame
    return frames


def read_scene_output(engine, kind, case, grid, directory, read_forces=None):
    """The SystemResult of a finished scene run in `directory` (Engine.read_scene); with several spheres,
    read_forces(directory, state, variant) gives {(i, j): (F_n, F_t)} of the contacts at the end (j < 0 a wall)."""
    v = case.variant
    n_bodies = len(v.spheres)
    frames = read_dump(os.path.join(directory, "series.dump"), engine, n_bodies)
    frames.update(read_dump(os.path.join(directory, "start.dump"), engine, n_bodies))
    last = read_dump(os.path.join(directory, "final.dump"), engine, n_bodies)
    frames[v.steps] = next(iter(last.values()))
    grid_steps = np.rint(np.asarray(grid) / v.dt).astype(np.int64)
    absent = [int(s) for s in grid_steps if s not in frames]
    if absent:
        raise EngineFailure(f"{engine} wrote no state at step {absent[0]} of the series ({len(absent)} missing)")
    trace = np.stack([frames[int(s)][:, [X, Z, VX, VZ, W]] for s in grid_steps])[None]
    pairs = contact_pairs(n_bodies, v.ceiling)
    final_state = frames[v.steps]
    events = bounce_events(frames, v) if kind == "bounce" else np.zeros((0, N_EVENT))
    final = np.full((1, len(pairs), N_FINAL), np.nan)
    final[0, :, F_ALPHA] = [overlap(final_state, v, i, j) for i, j in pairs]
    if n_bodies == 1:
        final[0, 0, F_FN] = final_state[0, FZ] + sphere_mass(v.spheres[0].radius, v.rho) * v.gravity
    else:
        forces = read_forces(directory, final_state, v)
        final[0, :, F_FN], final[0, :, F_FT] = contact_forces(forces, pairs, final_state, v)
    metrics = np.full((1, N_METRICS), np.nan)
    metrics[0, M_STATUS] = STATUS_OK if np.isfinite(trace).all() else STATUS_NONFINITE
    metrics[0, M_STEPS], metrics[0, M_TIME], metrics[0, M_EVENTS] = v.steps, v.steps * v.dt, len(events)
    metrics[0, M_GAIN] = math.nan
    kept = max(len(events), 1)
    padded = np.full((1, kept, N_EVENT), np.nan)
    padded[0, :len(events)] = events
    return SystemResult(np.asarray(grid, dtype=float), pairs, trace, np.full((1, len(grid)), np.nan), padded,
                        np.array([len(events)]), final_state[None], final, metrics)


def overlap(state, variant, i, j):
    """The overlap of contact (i, j) in a state: R - z (wall below), z + R - ceiling (above), R_i + R_j - distance."""
    r_i = variant.spheres[i].radius
    if j == WALL_BELOW:
        return r_i - state[i, Z]
    if j == WALL_ABOVE:
        return state[i, Z] + r_i - variant.ceiling
    distance = math.hypot(state[j, X] - state[i, X], state[j, Z] - state[i, Z])
    return r_i + variant.spheres[j].radius - distance


def bounce_events(frames, variant):
    """Each touch and parting of the one sphere with the wall below, from the per-step rows near the wall: a touch at
    the first step with z < R, its V_n the half-step velocity before the contact force acts (vz + dt/2 fz/m of the
    step before); a parting at the first step after with z >= R, its V_n that step's vz (as note_events gives them)."""
    radius, dt = variant.spheres[0].radius, variant.dt
    mass = sphere_mass(radius, variant.rho)
    steps = sorted(frames)
    rows, touching = [], False
    for before, step in zip(steps, steps[1:]):
        if step != before + 1:
            continue
        row, previous = frames[step][0], frames[before][0]
        inside = row[Z] < radius
        if inside and not touching and previous[Z] >= radius:
            rows.append((step * dt, TOUCH, 0, previous[VZ] + 0.5 * dt * previous[FZ] / mass, math.nan))
            touching = True
        elif touching and not inside:
            rows.append((step * dt, PART, 0, row[VZ], math.nan))
            touching = False
    events = np.array(rows, dtype=float).reshape(-1, N_EVENT)
    order = [E_TIME, E_KIND, E_CONTACT, E_VN, E_SLIP]
    out = np.empty_like(events)
    out[:, order] = events
    return out


def last_frame(path, engine, columns):
    """The rows of the last frame of a dump (atoms or local entries) of `columns` numbers; EngineFailure when it is
    missing or malformed."""
    try:
        with open(path) as handle:
            frame = handle.read().rsplit("ITEM: TIMESTEP\n", 1)[-1]
    except OSError:
        raise EngineFailure(f"{engine} wrote no {os.path.basename(path)}") from None
    lines = frame.splitlines()
    try:
        declared = int(lines[2])
        rows = np.array(" ".join(lines[8:]).split(), dtype=float).reshape(-1, columns)
    except (IndexError, ValueError):
        raise EngineFailure(f"{engine} {os.path.basename(path)} is malformed") from None
    if len(rows) != declared:
        raise EngineFailure(f"{engine} {os.path.basename(path)} is cut short: {len(rows)} rows of {declared}")
    return rows


def contact_forces(forces, pairs, state, variant):
    """(F_n, F_t) of each contact of `pairs` at the end from {(i, j): (F_n, F_t)} of those an engine wrote (j < 0 a
    wall); 0 where a contact does not touch."""
    f_n, f_t = np.zeros(len(pairs)), np.zeros(len(pairs))
    for k, (i, j) in enumerate(pairs):
        if overlap(state, variant, i, j) > 0.0:
            f_n[k], f_t[k] = forces.get((int(i), int(j)), (0.0, 0.0))
    return f_n, f_t
