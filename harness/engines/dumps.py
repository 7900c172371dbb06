"""The dumps of the LAMMPS family (LIGGGHTS, LAMMPS): the final `id z vx vz omegay` per sphere, read whole or
refused, and the observe dump of `id z fz` of every sphere in contact at every step."""
import os

import numpy as np

from ..infra.wording import counted
from .runner import EngineFailure

DUMP_HEADER_LINES = 9           # TIMESTEP, NUMBER OF ATOMS, BOX BOUNDS (3 lines) and ATOMS items


def read_final(path, n_atoms, engine, columns=5):
    """Final (z, vx, vz, omegay) per atom id from the `id z vx vz omegay` dump `engine` wrote (with columns=6, (x, z,
    vx, vz, omegay) from `id x z vx vz omegay`); EngineFailure when it is missing, cut (its last line must end, and
    its rows must be the number of atoms its header declares) or holds another number of spheres."""
    try:
        with open(path) as handle:
            text = handle.read()
    except OSError:
        raise EngineFailure(f"{engine} wrote no final dump") from None
    lines = text.splitlines()
    try:
        declared = int(lines[lines.index("ITEM: NUMBER OF ATOMS") + 1])
        start = next(i for i, line in enumerate(lines) if line.startswith("ITEM: ATOMS")) + 1
        rows = np.array([[float(x) for x in line.split()] for line in lines[start:] if line.strip()])
    except (StopIteration, ValueError, IndexError):
        raise EngineFailure(f"{engine} final dump is malformed") from None
    ended = text.endswith("\n")
    if not ended or len(rows) < declared:
        complete = len(rows) - (0 if ended else 1)
        raise EngineFailure(f"{engine} final dump is cut short: {complete} complete rows of {declared}"
                            + ("" if ended else ", the last unterminated"))
    if rows.ndim != 2 or rows.shape[1] != columns or len(rows) != declared:
        raise EngineFailure(f"{engine} final dump is malformed: {counted(len(rows), 'row')} where its header says "
                            f"{declared}")
    if declared != n_atoms:
        raise EngineFailure(f"{engine} final dump holds {declared} spheres where the deck made {n_atoms}")
    rows = rows[np.argsort(rows[:, 0])]
    if not np.array_equal(rows[:, 0], np.arange(1, n_atoms + 1)):
        raise EngineFailure(f"{engine} final dump lacks some sphere ids")
    return rows[:, 1:]



def rebound(state, radius):
    """Rebound velocities, separation and whether each is finite, from a final dump's (z, vx, vz, omegay): a sphere
    whose state is not a number is a result (a row `non-finite`), not a failed run."""
    z, vx, vz, omegay = state.T
    return {"v_n1": vz, "v_t1": vx, "omega1": omegay, "separated": z > radius,
            "finite": np.isfinite(state).all(axis=1)}

def pair_rebound(state, scene):
    """The equivalent impact's rebound from each pair's final (x, z, vx, vz, omegay): v_n1 = vz1 - vz2, v_t1 =
    vx1 - vx2, omega1 = (R1 w1 + R2 w2)/R* in the frame where the line of centres was z at first touch, separated
    when the centres are more than R1 + R2 apart."""
    projectile, target = scene.spheres
    one, two = state[0::2], state[1::2]
    gap = np.hypot(one[:, 0] - two[:, 0], one[:, 1] - two[:, 1]) - (projectile.radius + target.radius)
    equivalent = np.column_stack([gap, one[:, 2] - two[:, 2], one[:, 3] - two[:, 3],
                                  (projectile.radius * one[:, 4] + target.radius * two[:, 4]) / scene.contact.radius])
    out = rebound(equivalent, 0.0)
    out["separated"] = gap > 0.0
    return out


def dump_frames(path, engine, columns):
    """(step, rows) of every row of a per-step dump of `columns` numbers each; EngineFailure when missing or
    malformed."""
    try:
        with open(path) as handle:
            frames = handle.read().split("ITEM: TIMESTEP\n")
    except OSError:
        raise EngineFailure(f"{engine} wrote no observe dump") from None
    try:
        heads = [frame.split("\n", DUMP_HEADER_LINES - 1) for frame in frames[1:]]
        if frames[0] or any(not head[-2].startswith("ITEM: ATOMS") for head in heads):
            raise ValueError("not a dump of atom frames")
        counts = np.array([int(head[2]) for head in heads], dtype=int)
        step = np.repeat([int(head[0]) for head in heads], counts).astype(int)
        rows = np.array(" ".join(head[-1] for head in heads).split(), dtype=float).reshape(len(step), columns)
    except (IndexError, ValueError):
        raise EngineFailure(f"{engine} observe dump is malformed") from None
    return step, rows


def dump_rows(path, engine):
    """(step, atom index, z, fz) of every row of the observe dump, one array each; EngineFailure when missing or
    malformed."""
    step, rows = dump_frames(path, engine, 3)
    return step, rows[:, 0].astype(int) - 1, rows[:, 1], rows[:, 2]


def read_observed_pairs(path, n_pairs, centres, dt, engine):
    """Per pair (atoms 2k-1 above 2k, touching at step 0) from an `id x z fx fz` dump of the atoms in contact: contact
    time from the touch to the first step out (dt each), peak normal force F1.n and peak overlap R1 + R2 - |r| with
    r = x1 - x2 and n = r/|r|, over its first contact."""
    step, rows = dump_frames(path, engine, 5)
    ids = rows[:, 0].astype(int) - 1
    order = np.lexsort((ids % 2, step, ids // 2))
    step, rows, ids = step[order], rows[order], ids[order]
    one, two = rows[0::2], rows[1::2]
    if len(rows) % 2 or np.any(ids[0::2] % 2 != 0) or np.any(ids[1::2] != ids[0::2] + 1) or \
            np.any(step[0::2] != step[1::2]):
        raise EngineFailure(f"{engine} observe dump holds a sphere in contact without its partner")
    pair, step = ids[0::2] // 2, step[0::2]
    if np.any(pair >= n_pairs) or len(np.unique(pair)) != n_pairs:
        raise EngineFailure(f"{engine} observe dump lacks some pairs")
    dx, dz = one[:, 1] - two[:, 1], one[:, 2] - two[:, 2]
    dist = np.hypot(dx, dz)
    force, overlap = (one[:, 3] * dx + one[:, 4] * dz) / dist, centres - dist
    keep = first_contact(step, pair)
    last, peak, deepest = np.full(n_pairs, -1), np.full(n_pairs, -np.inf), np.full(n_pairs, -np.inf)
    np.maximum.at(last, pair[keep], step[keep])
    np.maximum.at(peak, pair[keep], force[keep])
    np.maximum.at(deepest, pair[keep], overlap[keep])
    return {"t_contact": (last + 1) * dt, "f_n_max": peak, "overlap_max": deepest}


def first_contact(step, atom):
    """Mask of the rows in each atom's first run of consecutive steps (a repeated frame or a later contact is not)."""
    order = np.lexsort((step, atom))
    s, a = step[order], atom[order]
    new_atom = np.r_[True, a[1:] != a[:-1]]
    gap = np.diff(s, prepend=0)
    breaks = np.cumsum(~new_atom & (gap > 1))
    run = breaks - np.maximum.accumulate(np.where(new_atom, breaks, 0))      # contacts before this one, per atom
    mask = np.empty(len(step), dtype=bool)
    mask[order] = (run == 0) & (new_atom | (gap != 0))
    return mask


def read_observed(path, n_atoms, radius, dt, engine):
    """Per atom: contact time in whole steps (first step in contact to the first step out, dt each), peak fz (the
    wall force: no gravity, no sphere-sphere contact) and peak overlap R - z, over its first contact."""
    step, atom, z, fz = dump_rows(path, engine)
    if np.any((atom < 0) | (atom >= n_atoms)) or len(np.unique(atom)) != n_atoms:
        raise EngineFailure(f"{engine} observe dump lacks some sphere ids")
    keep = first_contact(step, atom)
    step, atom, z, fz = step[keep], atom[keep], z[keep], fz[keep]
    first, last = np.full(n_atoms, np.iinfo(int).max), np.full(n_atoms, -1)
    force, overlap = np.full(n_atoms, -np.inf), np.full(n_atoms, -np.inf)
    np.minimum.at(first, atom, step)
    np.maximum.at(last, atom, step)
    np.maximum.at(force, atom, fz)
    np.maximum.at(overlap, atom, radius - z)
    return {"t_contact": (last - first + 1) * dt, "f_n_max": force, "overlap_max": overlap}


def read_pair_batch(directory, scene, spec, observe, engine, observe_dump):
    """The equivalent impacts' rebounds of a two-sphere run in `directory` from its `final.dump` (id x z vx vz
    omegay, two atoms per impact) and, observed, contact time, peak force and overlap from `observe_dump`."""
    final = pair_rebound(read_final(os.path.join(directory, "final.dump"), 2 * spec.impacts, engine, 6), scene)
    if observe:
        projectile, target = scene.spheres
        final.update(read_observed_pairs(os.path.join(directory, observe_dump), spec.impacts,
                                         projectile.radius + target.radius, spec.dt, engine))
    return final
