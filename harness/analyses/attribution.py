"""Attribution: the deviation of an engine's dialect from the paper law, split into ingredients by switching one
sub-model at a time from the dialect's choice to the paper's and measuring what that alone changes; where a check of
the physics verdict fails and no ingredient alone explains its miss, combinations of them (causes.py reads them)."""
from dataclasses import replace

import numpy as np
import pandas as pd

from ..infra.errors import UserError
from ..laws.law import SUBMODEL_KEYS, check_composition
from .invariants import coulomb_ratio
from .causes import BASE, COUPLED, combined, explained_alone, strongest, units
from .misses import IMPACT, closed_share, misses, misses_at, with_paper

METRICS = ("e_n", "e_t", "omega_star", "psi2_star", "v_n1", "v_t1", "omega1", "coulomb_ratio", "ke_ratio")
FIELDS = {key: key.replace("-", "_") for key in SUBMODEL_KEYS}
STEPPING = ("integrator", "coulomb", "geometry", "touch")    # switched together: no stepper takes one without the rest
NOTES = {   # what switching an ingredient carries with it, beyond its name
    "integrator": "the scheme's own conventions go with it: the paper scheme's implicit tangential dashpot and sliding "
                  "kick, release located inside the step; the velocity-Verlet dialects also their force at first touch",
    "damping": "the calibration alone; the end rule stays the dialect's",
    "end": "clipping alone; the damping calibration stays the dialect's",
}
KEPT = IMPACT + ["v_n1", "v_t1", "omega1", "e_n", "ke_ratio", "t_contact", "status"]    # what the causes read


def differing_ingredients(paper, dialect):
    """Sub-model keys whose labels differ between the two laws, with both labels."""
    a, b = paper.describe(), dialect.describe()
    return [(key, b[key], a[key]) for key in SUBMODEL_KEYS if str(a[key]) != str(b[key])]


def switched_name(keys):
    """The name of a set of switched ingredients, in the order of SUBMODEL_KEYS: 'coulomb+end'."""
    keys = set(keys)
    return "+".join(k for k in SUBMODEL_KEYS if k in keys)


def attribution(paper, dialect, scene, simulate):
    """One row per differing ingredient: max |change| of each metric (the Coulomb ratio |J_t|/(mu J_n) among them)
    when only it is switched to the paper's (or to another dialect's, when `paper` is that dialect's law)."""
    return attribute(paper, dialect, scene, simulate)[0]


def attribute(paper, dialect, scene, simulate, tolerances=None):
    """(table, impacts): the attribution table, and the rows of every impact of the dialect (switched 'dialect') and of
    each law it was switched to (switched 'coulomb', 'integrator+coulomb', 'end+coulomb', ...). A stepping field
    switched with others it needs has the others switched without it too, so that its own part can be told from
    theirs. With `tolerances`, the paper law runs too, and the combinations a failed check needs
    (combinations_tried)."""
    runs = Runs(simulate, scene)
    base = runs(dialect)
    rows, laws = [], {BASE: base}
    for key, theirs, ours in differing_ingredients(paper, dialect):
        row = {"ingredient": key, "dialect": str(theirs), "target": str(ours), "switched": key}
        law, carried, refusal = separable(switch(dialect, paper, [key]), paper, key)
        if refusal:
            rows.append({**row, "note": f"not separable alone: {refusal}"})
            continue
        labels, before = law.describe(), dialect.describe()
        keys = [k for k in SUBMODEL_KEYS if k == key or str(labels[k]) != str(before[k])]
        row["switched"] = switched_name(keys)
        laws[row["switched"]] = switched = runs(law)
        if len(keys) > 1:                       # the others without it: its own part is the difference
            alone = compose_switched(dialect, paper, [k for k in keys if k != key])
            if alone is not None:
                laws[switched_name(k for k in keys if k != key)] = runs(alone)
        for metric in METRICS:
            diff = (switched[metric] - base[metric]).to_numpy()
            if np.all(np.isnan(diff)):
                continue
            worst = int(np.nanargmax(np.abs(diff)))
            row[f"d_{metric}"] = float(diff[worst])
        note = "; ".join(filter(None, [NOTES.get(key, ""), carried]))
        rows.append({**row, "note": note})
    table = pd.DataFrame(rows)
    if tolerances is not None and not table.empty:
        laws.update(combinations_tried(table, laws, runs(paper), tolerances, scene.gravity,
                                       lambda keys: runs(compose_switched(dialect, paper, keys))))
    impacts = pd.concat([frame[KEPT].assign(switched=name) for name, frame in laws.items() if frame is not None],
                        ignore_index=True)
    return table, impacts


class Runs:
    """simulate(law, scene) of each law once (a law is known by its sub-models' labels, as a run's key knows it),
    with the Coulomb ratio beside the results; None for None."""

    def __init__(self, simulate, scene):
        self.simulate, self.scene, self.done = simulate, scene, {}

    def __call__(self, law):
        if law is None:
            return None
        key = law_key(law)
        if key not in self.done:
            frame = self.simulate(law, self.scene)
            self.done[key] = frame.assign(coulomb_ratio=coulomb_ratio(frame, self.scene.gravity))
        return self.done[key]


def law_key(law):
    """What a law is: its name and its sub-models' labels (as a run's key knows it)."""
    return law.name, tuple(sorted((k, str(v)) for k, v in law.describe().items()))


def switch(dialect, paper, keys):
    """The dialect with the ingredients `keys` switched to the paper's (not checked)."""
    return replace(dialect, **{FIELDS[k]: getattr(paper, FIELDS[k]) for k in keys},
                   dialect=f"{dialect.dialect}+paper-{switched_name(keys)}")


def compose_switched(dialect, paper, keys):
    """The dialect with `keys` switched to the paper's, or None where that composes no law a stepper computes."""
    law = switch(dialect, paper, keys)
    try:
        check_composition(law)
    except UserError:
        return None
    return law


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


def combinations_tried(table, laws, paper, tolerances, gravity, run):
    """{name: rows} of the combinations run: for each check the dialect fails where no ingredient alone explains
    its miss (causes.EXPLAINS), the COUPLED sets, then the ingredient that closes most of it with each other one."""
    impacts = with_paper(laws[BASE], paper)
    base = misses(impacts, tolerances, gravity)
    failing = {check: miss > bound for check, (miss, bound) in base.items() if (miss > bound).any()}
    tried, known = {}, {}

    def measured(name):
        if name not in known:
            frame = laws.get(name, tried.get(name))
            known[name] = None if frame is None else misses_at(frame, paper, impacts, tolerances, gravity)
        return known[name]

    def share(check):
        out = {}
        for name in list(laws) + list(tried):
            misses_of = measured(name) if name != BASE else None
            if misses_of is not None:
                out[name] = closed_share(base[check][0][failing[check]], misses_of[check][0][failing[check]])
        return out
    for check in failing:
        if explained_alone(units(table, share(check))):
            continue
        for keys in COUPLED:
            if all(k in set(table.ingredient) for k in keys) and switched_name(keys) not in tried:
                tried[switched_name(keys)] = run(list(keys))
        candidates = units(table, share(check))
        best = strongest(candidates)
        for other in candidates if best is not None else ():
            name = switched_name(combined(best, other))
            if name not in laws and name not in tried:
                tried[name] = run(sorted(combined(best, other)))
    return {name: frame for name, frame in tried.items() if frame is not None}
