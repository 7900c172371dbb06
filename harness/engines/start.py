"""A scene's start and its named states as an engine's script takes them: the steps Scene.at_times name, the chunks
a starting gap's free approach adds to the run, and the states array an engine's read_batch returns."""
import math

import numpy as np

from ..scenes.scene import state_steps
from .runner import EngineFailure

STATE_COLUMNS = ("t", "overlap", "f_n", "f_t", "v_n", "v_t", "omega")


def named_steps(scene, dt):
    """The step whose end is the state at each named time: k = ceil(t/dt - 1e-9), the same in every engine."""
    return state_steps(scene.at_times, dt)


def start_chunks(scene, spec):
    """Separation checks a run needs beyond its spec's: those of the slowest free approach (twice gap/V_n, which
    covers an oblique approach to a sphere) and those up to the last named step; 0 at the defaults."""
    steps = 0
    if scene.gap > 0.0:
        steps = 2.0 * scene.gap / float(np.min(spec.v_n0)) / spec.dt
    last = max(named_steps(scene, spec.dt), default=0)
    return int(math.ceil(steps / spec.chunk)) + int(math.ceil(last / spec.chunk))


def states_array(rows, impacts, scene, dt, engine):
    """(impacts, times, 7) in STATE_COLUMNS from rows (impact, time index, overlap, f_n, f_t, v_n, v_t, omega);
    EngineFailure when a state is missing."""
    times = len(scene.at_times)
    out = np.full((impacts, times, len(STATE_COLUMNS)), np.nan)
    for row in rows:
        k, j = int(row[0]), int(row[1])
        if not (0 <= k < impacts and 0 <= j < times):
            raise EngineFailure(f"{engine} states file names impact {k}, time {j} of {impacts} and {times}")
        out[k, j, 1:] = row[2:]
    out[:, :, 0] = np.array(named_steps(scene, dt), dtype=float) * dt
    missing = np.isnan(out[:, :, 1])
    if missing.any():
        k, j = np.argwhere(missing)[0]
        raise EngineFailure(f"{engine} recorded no state of impact {k + 1} at t = {scene.at_times[j]:g} s "
                            f"({int(missing.sum())} of {missing.size} missing)")
    return out


def stepping(scene, spec):
    """What a script's stepping takes: dt, the separation check's cadence and count (with start_chunks), and the
    named steps as sorted (step, [time indices]) pairs (several times may end at one step)."""
    named = {}
    for j, k in enumerate(named_steps(scene, spec.dt)):
        named.setdefault(k, []).append(j)
    return dict(dt=spec.dt, chunk=spec.chunk, max_chunks=spec.chunks + start_chunks(scene, spec),
                named=sorted(named.items()))


def approach_drift(scene, v_n0, v_t0):
    """How far along the tangent the slowest-to-touch sphere may travel in its free approach from the gap: twice
    gap V_t/V_n at most (0 without a gap), by which neighbouring slots are set further apart."""
    if scene.gap <= 0.0:
        return 0.0
    return 2.0 * scene.gap * float(np.max(np.asarray(v_t0) / np.asarray(v_n0)))
