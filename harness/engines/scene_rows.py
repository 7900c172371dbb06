"""What YADE's and Kratos' scene scripts write (scene.txt, one tagged row a line) and how harness reads it back into
the small-system integrator's SystemResult (Engine.read_scene):

    state STEP BODY x z vx vz w     a body at a recorded step, its velocities as the engine stores them
    next STEP BODY vx vz w          the stored velocities one step later
    touch STEP CONTACT vz           the first step the sphere is inside the wall below; vz stored that step
    part STEP CONTACT vz            the first step after it that the sphere is clear of it again
    contact K overlap F_n F_t       contact K (contact_pairs order) at the end
    END

Both engines store v(t - dt/2) beside x(t) and step v(t + dt/2) = v(t - dt/2) + dt F(x(t))/m (leapfrog, symplectic
Euler), the positions of velocity Verlet; the scripts start each sphere at v(-dt/2) (start_vz) and run one step
past the last. The reader gives velocity Verlet's v(t) = (v(t - dt/2) + v(t + dt/2))/2 at each recorded step; a
touch's V_n is the stored vz (the velocity that moved the sphere inside, before the contact's first force) and a
parting's vz - g dt/2 (v at its step's end, gravity alone on that half step), as the reference records them."""
import math
import os

import numpy as np

from ..solver.system import (E_CONTACT, E_KIND, E_SLIP, E_TIME, E_VN, F_ALPHA, F_FN, F_FT, M_EVENTS, M_GAIN,
                             M_STATUS, M_STEPS, M_TIME, N_EVENT, N_FINAL, N_METRICS, PART, STATUS_NONFINITE,
                             STATUS_OK, TOUCH)
from ..solver.system_run import SystemResult, body_rows, contact_pairs
from .runner import EngineFailure, ended_lines

OUTPUT = "scene.txt"
STATE_FIELDS = 5                # x z vx vz w


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


def parse(path, engine):
    """(states {step: {body: row}}, later {step: {body: (vx, vz, w) a step later}}, events [(kind, step, contact,
    vz)], contacts {k: (overlap, F_n, F_t)})."""
    lines = ended_lines(path, engine, os.path.basename(path))
    states, later, events, contacts = {}, {}, [], {}
    try:
        for line in lines:
            tag, *words = line.split()
            if tag == "state":
                states.setdefault(int(words[0]), {})[int(words[1])] = [float(w) for w in words[2:2 + STATE_FIELDS]]
            elif tag == "next":
                later.setdefault(int(words[0]), {})[int(words[1])] = [float(w) for w in words[2:5]]
            elif tag in ("touch", "part"):
                events.append((TOUCH if tag == "touch" else PART, int(words[0]), int(words[1]), float(words[2])))
            elif tag == "contact":
                contacts[int(words[0])] = tuple(float(w) for w in words[1:4])
            else:
                raise ValueError(tag)
    except (ValueError, IndexError):
        raise EngineFailure(f"{engine} {os.path.basename(path)} is malformed: {line[:80]!r}") from None
    return states, later, events, contacts


def read_scene_rows(engine, case, grid, directory):
    """The SystemResult of one scene case from `directory`/scene.txt: the trace at the times of `grid`, the touches
    and partings, each contact's overlap and forces at the end; the energy and the largest energy gain are NaN
    (not written)."""
    v = case.variant
    n_bodies, half_kick = len(v.spheres), 0.5 * v.gravity * v.dt
    states, later, events, contacts = parse(os.path.join(directory, OUTPUT), engine)
    steps, _ = recorded_steps(grid, v.dt)
    for step in list(steps) + [v.steps]:
        if len(states.get(int(step), {})) != n_bodies or len(later.get(int(step), {})) != n_bodies:
            raise EngineFailure(f"{engine} wrote no state of every sphere at step {int(step)} of {v.steps}")

    def at(step, body):
        """(x, z, vx, vz, w) at `step`: the mean of the half-step velocities either side."""
        x, z, *before = states[step][body]
        return (x, z, *(0.5 * (a + b) for a, b in zip(before, later[step][body])))

    trace = np.array([[at(int(s), b) for b in range(n_bodies)] for s in steps])[None]
    pairs = contact_pairs(n_bodies, v.ceiling)
    final = np.full((1, len(pairs), N_FINAL), np.nan)
    for k, (overlap, f_n, f_t) in contacts.items():
        if 0 <= k < len(pairs):
            final[0, k, [F_ALPHA, F_FN, F_FT]] = overlap, f_n, f_t
    rows = np.full((max(len(events), 1), N_EVENT), np.nan)
    for r, (kind, step, contact, vz) in enumerate(events):
        v_n = vz - half_kick if kind == PART else vz
        rows[r, [E_TIME, E_KIND, E_CONTACT, E_VN, E_SLIP]] = step * v.dt, kind, contact, v_n, math.nan
    bodies = body_rows(v)
    bodies[:, :STATE_FIELDS] = [at(v.steps, b) for b in range(n_bodies)]
    metrics = np.full((1, N_METRICS), np.nan)
    finite = np.isfinite(trace).all() and np.isfinite(bodies).all()
    metrics[0, M_STATUS] = STATUS_OK if finite else STATUS_NONFINITE
    metrics[0, M_STEPS], metrics[0, M_TIME], metrics[0, M_EVENTS] = v.steps, v.steps * v.dt, len(events)
    metrics[0, M_GAIN] = math.nan
    return SystemResult(np.asarray(grid, dtype=float), pairs, trace, np.full((1, len(grid)), np.nan), rows[None],
                        np.array([len(events)]), bodies[None], final, metrics)
