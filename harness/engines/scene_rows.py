"""What YADE's and Kratos' scene scripts write (scene.txt, one tagged row a line) and how harness reads it back into
the small-system integrator's SystemResult (Engine.read_scene):

    state STEP BODY x z vx vz w fx fz ty   a body at a recorded step: the velocities as the engine stores them, and
                                    the contact force and torque of the step that led there (gravity apart)
    touch STEP CONTACT vz           the first step the sphere is inside the wall below; vz stored that step
    part STEP CONTACT vz            the first step after it that the sphere is clear of it again
    contact K overlap F_n F_t       contact K (contact_pairs order) at the end
    END

Both engines store v(t - dt/2) beside x(t), from the forces at x(t - dt) (leapfrog, symplectic Euler); the scripts
start each sphere at v(-dt/2) (start_vz). The reader gives v(t) ~ v(t - dt/2) + (F/m - g) dt/2 with the recorded
force (exact in flight and at rest, off by the force's change over one step in contact), the given v(0) at t = 0;
as the reference records them, a touch's V_n is the stored vz (the velocity that moved the sphere inside, before the
contact's first force) and a parting's vz - g dt/2 (v at its step's end, no contact force on that half step)."""
import math
import os

import numpy as np

from ..solver.system import (E_CONTACT, E_KIND, E_SLIP, E_TIME, E_VN, F_ALPHA, F_FN, F_FT, M_EVENTS, M_GAIN,
                             M_STATUS, M_STEPS, M_TIME, N_EVENT, N_FINAL, N_METRICS, PART, STATUS_NONFINITE,
                             STATUS_OK, TOUCH)
from ..solver.system_contacts import B_I, B_M
from ..solver.system_run import SystemResult, body_rows, contact_pairs
from .runner import EngineFailure

OUTPUT = "scene.txt"
STATE_FIELDS = 8                # x z vx vz w fx fz ty


def start_vz(sphere, variant):
    """The vertical velocity an engine is given for a sphere: v(-dt/2) = v(0) + g dt/2, except for a sphere that
    starts pressed into the wall below (slide-to-roll: at its static overlap, no net force, so v(-dt/2) = v(0))."""
    if sphere.z < sphere.radius:
        return sphere.vz
    return sphere.vz + 0.5 * variant.gravity * variant.dt


def recorded_steps(grid, dt):
    """The steps of the recorded times, and the cadence the engine records at (the steps between the first two)."""
    steps = np.rint(np.asarray(grid, dtype=float) / dt).astype(np.int64)
    every = int(steps[1] - steps[0]) if len(steps) > 1 else 1
    return steps, max(every, 1)


def full_step(row, body, gravity, dt):
    """(x, z, vx, vz, w) at the row's time from the stored half-step velocities and the recorded force and torque."""
    x, z, vx, vz, w, fx, fz, ty = row
    half = 0.5 * dt
    return (x, z, vx + half * fx / body[B_M], vz + half * (fz / body[B_M] - gravity), w + half * ty / body[B_I])


def parse(path, engine):
    """(states {step: {body: row}}, events [(kind, step, contact, vz)], contacts {k: (overlap, F_n, F_t)})."""
    try:
        with open(path) as handle:
            lines = handle.read().splitlines()
    except OSError:
        raise EngineFailure(f"{engine} wrote no {os.path.basename(path)}") from None
    if not lines or lines[-1] != "END":
        raise EngineFailure(f"{engine} {os.path.basename(path)} is truncated (no END line)")
    states, events, contacts = {}, [], {}
    try:
        for line in lines[:-1]:
            tag, *words = line.split()
            if tag == "state":
                states.setdefault(int(words[0]), {})[int(words[1])] = [float(w) for w in words[2:2 + STATE_FIELDS]]
            elif tag in ("touch", "part"):
                events.append((TOUCH if tag == "touch" else PART, int(words[0]), int(words[1]), float(words[2])))
            elif tag == "contact":
                contacts[int(words[0])] = tuple(float(w) for w in words[1:4])
            else:
                raise ValueError(tag)
    except (ValueError, IndexError):
        raise EngineFailure(f"{engine} {os.path.basename(path)} is malformed: {line[:80]!r}") from None
    return states, events, contacts


def read_scene_rows(engine, case, grid, directory):
    """The SystemResult of one scene case from `directory`/scene.txt: the trace at the times of `grid`, the touches
    and partings, each contact's overlap and forces at the end; the energy and the largest energy gain are NaN
    (not written)."""
    v = case.variant
    n_bodies, half_kick = len(v.spheres), 0.5 * v.gravity * v.dt
    states, events, contacts = parse(os.path.join(directory, OUTPUT), engine)
    steps, _ = recorded_steps(grid, v.dt)
    for step in list(steps) + [v.steps]:
        if len(states.get(int(step), {})) != n_bodies:
            raise EngineFailure(f"{engine} wrote no state of every sphere at step {int(step)} of {v.steps}")
    bodies = body_rows(v)
    trace = np.array([[full_step(states[int(s)][b], bodies[b], v.gravity, v.dt) for b in range(n_bodies)]
                      for s in steps])[None]
    if steps[0] == 0:
        trace[0, 0, :, 2:5] = [(s.vx, s.vz, s.w) for s in v.spheres]      # the velocities the engine was given
    pairs = contact_pairs(n_bodies, v.ceiling)
    final = np.full((1, len(pairs), N_FINAL), np.nan)
    for k, (overlap, f_n, f_t) in contacts.items():
        if 0 <= k < len(pairs):
            final[0, k, [F_ALPHA, F_FN, F_FT]] = overlap, f_n, f_t
    rows = np.full((max(len(events), 1), N_EVENT), np.nan)
    for r, (kind, step, contact, vz) in enumerate(events):
        rows[r, [E_TIME, E_KIND, E_CONTACT, E_VN, E_SLIP]] = step * v.dt, kind, contact, vz - (half_kick if kind == PART else 0.0), math.nan
    bodies[:, :5] = [full_step(states[v.steps][b], bodies[b], v.gravity, v.dt) for b in range(n_bodies)]
    metrics = np.full((1, N_METRICS), np.nan)
    finite = np.isfinite(trace).all() and np.isfinite(bodies).all()
    metrics[0, M_STATUS] = STATUS_OK if finite else STATUS_NONFINITE
    metrics[0, M_STEPS], metrics[0, M_TIME], metrics[0, M_EVENTS] = v.steps, v.steps * v.dt, len(events)
    metrics[0, M_GAIN] = math.nan
    return SystemResult(np.asarray(grid, dtype=float), pairs, trace, np.full((1, len(grid)), np.nan), rows[None],
                        np.array([len(events)]), bodies[None], final, metrics)
