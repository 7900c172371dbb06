"""The final dump of the LAMMPS family (LIGGGHTS, LAMMPS): `id z vx vz omegay` per sphere, read whole or refused."""
import numpy as np

from .runner import EngineFailure


def read_final(path, n_atoms, engine):
    """Final (z, vx, vz, omegay) per atom id from the `id z vx vz omegay` dump `engine` wrote; EngineFailure when it
    is missing, cut (its last line must end, and its rows must be the number of atoms its header declares) or holds
    another number of spheres."""
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
    if rows.ndim != 2 or rows.shape[1] != 5 or len(rows) != declared:
        raise EngineFailure(f"{engine} final dump is malformed: {len(rows)} rows where its header says {declared}")
    if declared != n_atoms:
        raise EngineFailure(f"{engine} final dump holds {declared} spheres where the deck made {n_atoms}")
    rows = rows[np.argsort(rows[:, 0])]
    if not np.array_equal(rows[:, 0], np.arange(1, n_atoms + 1)):
        raise EngineFailure(f"{engine} final dump lacks some sphere ids")
    return rows[:, 1:]
