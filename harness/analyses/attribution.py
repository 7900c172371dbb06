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
STEPPING = ("integrator", "coulomb", "geometry", "touch")    # switched together where no stepper takes one without the others
NOTES = {   # what switching an ingredient carries with it, beyond its name
    "integrator": "the scheme's conventions go with it: tangential dashpot after the Coulomb test without a second "
                  "cap, release at the step rather than inside it; the velocity-Verlet dialects also their force at "
                  "first touch",
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
        law, carried, refusal = separable(law, paper, key)
        if refusal:
            rows.append({**row, "note": f"not separable alone: {refusal}"})
            continue
        switched = measured(law)
        for metric in METRICS:
            diff = (switched[metric] - base[metric]).to_numpy()
            if np.all(np.isnan(diff)):
                continue
            worst = int(np.nanargmax(np.abs(diff)))
            row[f"d_{metric}"] = float(diff[worst])
        note = "; ".join(filter(None, [NOTES.get(key, ""), carried]))
        rows.append({**row, "note": note})
    return pd.DataFrame(rows)


def separable(law, paper, key):
    """(law, what it carries, refusal): the law with one ingredient switched, or, for a stepping field no stepper
    takes alone, with the other stepping fields switched to the paper's too (and said); a refusal when neither
    composes."""
    try:
        check_composition(law)
        return law, "", ""
    except UserError as exc:
        refusal = str(exc)
    if key not in STEPPING:
        return law, "", refusal
    others = [k for k in STEPPING if k != key and getattr(law, FIELDS[k]) != getattr(paper, FIELDS[k])]
    both = replace(law, **{FIELDS[k]: getattr(paper, FIELDS[k]) for k in others})
    try:
        check_composition(both)
    except UserError:
        return law, "", refusal
    return both, f"switched with its {' and '.join(others)} ({refusal})", ""
