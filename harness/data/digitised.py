"""The paper's published curves as the Kratos project digitised them (package data harness/data/, provenance in its
header): Psi2*, Omega* and e_t against Psi1* of the linear and Hertz laws at e 0.25, 0.5, 0.75 and 0.9."""
from functools import lru_cache
from importlib.resources import files

import numpy as np
import pandas as pd

from ..scenes.materials import get_material

FILE = "tcc13-digitised.csv"
LAWS = {"linear": "linear-spring-dashpot", "hertz": "hertz-mindlin"}           # the file's model -> harness' law
QUANTITIES = {"psi2s": "psi2_star", "omegas": "omega_star", "e_t": "e_t"}     # the file's quantity -> column


def path():
    """The shipped file (a Traversable: open it with .open())."""
    return files("harness") / "data" / FILE


def provenance():
    """The file's header comments, without their '# ' (source, scene, normalisation, digitising scatter)."""
    with path().open(encoding="utf-8") as handle:
        return [line[1:].strip() for line in handle if line.startswith("#")]


@lru_cache(maxsize=1)
def published_points():
    """The points as (model, quantity, e_n, psi1_star, value), in harness' law and column names."""
    with path().open(encoding="utf-8") as handle:
        raw = pd.read_csv(handle, comment="#")
    return pd.DataFrame({"model": raw.model.map(LAWS), "quantity": raw.quantity.map(QUANTITIES),
                         "e_n": raw.e.astype(float), "psi1_star": raw.psi1s.astype(float),
                         "value": raw.value.astype(float)})


def points_of(model, quantity, e_n):
    """The published points of one law, quantity and e_n (none where the paper has no curve), by Psi1*."""
    points = published_points()
    rows = points[(points.model == model) & (points.quantity == quantity) & np.isclose(points.e_n, e_n)]
    return rows.sort_values("psi1_star")


def published_curves_apply(scene, law_name):
    """Whether the published curves describe this law on this scene: a law the file covers, on the paper's sphere
    (the tcc13 preset's R, E, nu, rho), mu 0.1, a wall of the same material, no initial spin and no gravity. The
    impact speed, normal or resultant, does not matter: both laws' normalised rebounds are self-similar in it
    (a linear spring with constant coefficients; Hertz with its 2E*a-scaled dashpot and Mindlin's 8G*a)."""
    paper = get_material("tcc13")
    return (law_name in LAWS.values() and scene.spheres is None and scene.wall == "same"
            and (scene.radius, scene.E, scene.nu, scene.rho, scene.mu) == (paper.radius, paper.E, paper.nu,
                                                                            paper.rho, paper.mu)
            and scene.omega0 == 0.0 and scene.gravity == 0.0)
