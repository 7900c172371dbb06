"""Attribution: the deviation of an engine's dialect from the paper, split into ingredients by switching one
sub-model at a time from the dialect's choice to the paper's and measuring what that alone changes."""
from dataclasses import replace

import numpy as np
import pandas as pd

from ..errors import UserError
from ..laws.law import SUBMODEL_KEYS, check_composition
from .invariants import coulomb_ratio

METRICS = ("e_n", "e_t", "omega_star", "psi2_star", "v_n1", "v_t1", "omega1", "coulomb_ratio", "ke_ratio")
FIELDS = {key: key.replace("-", "_") for key in SUBMODEL_KEYS}
NOTES = {   # what switching an ingredient carries with it, beyond its name
    "integrator": "the scheme's conventions go with it: tangential dashpot after the Coulomb test without a second "
                  "cap, release at the step rather than inside it; LIGGGHTS also its force at first touch",
    "damping": "the calibration alone; the end rule stays the dialect's",
    "end": "clipping alone; the damping calibration stays the dialect's",
}


def differing_ingredients(paper, dialect):
    """Sub-model keys whose labels differ between the two laws, with both labels."""
    a, b = paper.describe(), dialect.describe()
    return [(key, b[key], a[key]) for key in SUBMODEL_KEYS if str(a[key]) != str(b[key])]


def attribution(paper, dialect, scene, simulate):
    """One row per differing ingredient: max |change| of each metric (the Coulomb ratio |J_t|/(mu J_n) among them)
    when only it is switched to the paper's (or to another dialect's, when `paper` is that dialect's law)."""
    def measured(law):
        frame = simulate(law, scene)
        return frame.assign(coulomb_ratio=coulomb_ratio(frame, scene.gravity))
    base = measured(dialect)
    rows = []
    for key, theirs, ours in differing_ingredients(paper, dialect):
        field = FIELDS[key]
        law = replace(dialect, **{field: getattr(paper, field)}, dialect=f"{dialect.dialect}+paper-{key}")
        row = {"ingredient": key, "dialect": str(theirs), "target": str(ours)}
        try:
            check_composition(law)
        except UserError as exc:
            rows.append({**row, "note": f"not separable alone: {exc}"})
            continue
        switched = measured(law)
        for metric in METRICS:
            diff = (switched[metric] - base[metric]).to_numpy()
            if np.all(np.isnan(diff)):
                continue
            worst = int(np.nanargmax(np.abs(diff)))
            row[f"d_{metric}"] = float(diff[worst])
        rows.append({**row, "note": NOTES.get(key, "")})
    return pd.DataFrame(rows)
