"""What the decks of the LAMMPS family (LAMMPS, LIGGGHTS) add for a starting gap and states at named times: the
steps of the free approach, the steps whose state each deck dumps (`state<j>.dump`, `id z vx vz omegay fx fz`), and
reading them back as the states array (harness.data.states)."""
import math
import os

import numpy as np

from ..scenes.scene import state_steps
from .dumps import read_final
from .runner import EngineFailure

STATE_DUMP = "state{}.dump"


def refuse_between_spheres(scene, engine):
    """An EngineFailure for a gap or states between two spheres, which the decks of the LAMMPS family do not write
    yet (their wall decks do)."""
    if scene.gap or scene.at_times:
        raise EngineFailure(f"{engine}'s decks of two spheres do not take a starting gap or states at given times "
                            f"yet (its wall decks do)")


def approach_steps(scene, spec):
    """Steps by which every sphere has touched the wall from the scene's gap: ceil(gap/(V_n dt)) + 1 of the slowest
    (gravity only shortens the approach); 0 without a gap."""
    if not scene.gap:
        return 0
    return int(math.ceil(scene.gap / (float(np.min(spec.v_n0)) * spec.dt))) + 1


def dumped_steps(scene, spec):
    """The steps at which the deck dumps the state (those of the scene's at_times within its step cap)."""
    if not scene.at_times:
        return []
    cap = approach_steps(scene, spec) + spec.chunk * spec.chunks
    return [int(k) for k in state_steps(scene.at_times, spec.dt) if k <= cap]


def gap_and_states(scene, spec):
    """The template values: `state_steps`, the steps dumped, and `approach`, the step the free approach runs to
    after them (0: none left to run)."""
    steps = dumped_steps(scene, spec)
    approach = approach_steps(scene, spec)
    return {"state_steps": steps, "approach": approach if approach > max(steps, default=0) else 0}


def read_states(directory, scene, spec, radius, engine):
    """(impacts, times, 7) states from the state dumps: t = k dt, overlap R - z, F_n = fz, F_t = fx (the wall's force
    on the sphere: no gravity, no sphere-sphere contact), v_n = vz, v_t = vx, omega = omegay; NaN at a time beyond
    the deck's step cap."""
    steps = np.asarray(state_steps(scene.at_times, spec.dt), dtype=float)
    out = np.full((spec.impacts, len(steps), 7), np.nan)
    out[:, :, 0] = steps * spec.dt
    for j in range(len(dumped_steps(scene, spec))):
        z, vx, vz, omegay, fx, fz = read_final(os.path.join(directory, STATE_DUMP.format(j)), spec.impacts,
                                               engine, 7).T
        out[:, j, 1:] = np.column_stack([radius - z, fz, fx, vz, vx, omegay])
    return out
