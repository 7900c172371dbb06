"""The paper's figure set as data: for each law, Psi2*, Omega* and e_t against Psi1* at the paper's e_n on its scene
(normal speed held at 5 m/s, as Kratos draws them), elastic Hertz-Mindlin beside them, contact duration and peak
force of the normal impact against e_n relative to elastic Hertz, where each law slides throughout, and how far the
laws the paper's published curves cover lie from them."""
from dataclasses import replace

import numpy as np
import pandas as pd

from ..laws import LAWS, compose
from ..analyses.paper_axis import ELASTIC, PSI1_GRID
from ..submodels.calibration import hertz_contact_time
from ..submodels.normal.hertz import hertz_peak_overlap
from ..scenes.scene import DEFAULT_EN, Scene
from ..analyses.published import published_distances
from ..analyses.sliding import threshold_table
from .sliding_search import sliding_thresholds
from ..solver.resolution import MAX_STEPS_PER_CONTACT
from ..solver.simulate import simulate
from ..infra.errors import UserError

NORMAL_EN = tuple(sorted(set(np.round(np.arange(0.1, 0.951, 0.05), 6)) | set(DEFAULT_EN)))


def paper_scene(e_n=DEFAULT_EN):
    """The paper's scene with its Psi1* axis at the normal speed of 5 m/s."""
    return Scene(e_n=tuple(e_n), angles_deg=None, psi1_star=PSI1_GRID)


def elastic_law():
    """Hertz-Mindlin without dashpots (the elastic curve every inelastic one is read against)."""
    return compose("hertz-mindlin", {"damping": "none", "tangential-damping": "none"})


def oblique_curves(laws, scene, steps_per_contact):
    """Results rows of every law over the Psi1* axis at each e_n, and the elastic curve at e = 1."""
    frames = [simulate(compose(name), scene, steps_per_contact=steps_per_contact)[0] for name in laws]
    elastic = simulate(elastic_law(), replace(scene, e_n=(1.0,)), steps_per_contact=steps_per_contact)[0]
    return pd.concat(frames + [elastic.assign(model=ELASTIC)], ignore_index=True)


def normal_impacts(laws, scene, steps_per_contact):
    """Contact duration and peak force of each law's normal impact at the scene speed over NORMAL_EN, and both
    against elastic Hertz at the same speed: t_H = 2.8683 (m^2/(R E*^2 V))^1/5, F_H = 4/3 E* R^1/2 alpha_max^3/2."""
    normal = replace(scene, e_n=NORMAL_EN, angles_deg=(0.0,), psi1_star=None, v_t=None)
    contact = normal.contact
    t_h = hertz_contact_time(contact.E_star, contact.radius, contact.mass, normal.speed)
    f_h = 4.0 / 3.0 * contact.E_star * np.sqrt(contact.radius) * hertz_peak_overlap(contact, normal.speed) ** 1.5
    rows = []
    for name in laws:
        frame = simulate(compose(name), normal, steps_per_contact=steps_per_contact)[0]
        rows.append(pd.DataFrame({"model": name, "e_n_target": frame.e_n_target, "e_n": frame.e_n,
                                  "t_contact": frame.t_contact, "f_n_max": frame.f_n_max,
                                  "t_c/t_Hertz": frame.t_contact / t_h, "F_max/F_Hertz": frame.f_n_max / f_h,
                                  "provisional": LAWS[name].provisional}))
    return pd.concat(rows, ignore_index=True)


def figure_set(laws=tuple(LAWS), steps_per_contact=2000, progress=None):
    """(oblique rows, normal-impact table, sliding thresholds, distances from the published points) of the paper's
    figures for `laws`."""
    scene = paper_scene()
    if progress:
        progress.expect(2 + len(laws))
    oblique = oblique_curves(laws, scene, steps_per_contact)
    if progress:
        progress.advance("oblique impacts")
    normal = normal_impacts(laws, scene, steps_per_contact)
    if progress:
        progress.advance("normal impacts")
    sliding = []
    for name in laws:
        sliding.append(threshold_table(name, sliding_thresholds(compose(name), scene)))
        if progress:
            progress.advance(f"sliding threshold of {name}")
    return oblique, normal, pd.concat(sliding, ignore_index=True), published_distances(oblique)


def checked(laws, steps_per_contact, shown=None):
    """The laws of the figure set (None: every law), each known, and a resolution of 100 to MAX_STEPS_PER_CONTACT
    steps per contact (coarser draws the paper's figures visibly wrong)."""
    laws = tuple(LAWS) if laws is None else tuple(laws)
    unknown = [n for n in laws if n not in LAWS]
    if unknown or not laws:
        given = ", ".join(unknown) or repr(list(laws) if shown is None else shown)
        raise UserError(f"unknown law(s) {given}; known: {', '.join(LAWS)}")
    if steps_per_contact < 100:
        raise UserError(f"--steps-per-contact must be >= 100 for the paper's figures, got {steps_per_contact}")
    if steps_per_contact > MAX_STEPS_PER_CONTACT:
        raise UserError(f"--steps-per-contact must be at most {MAX_STEPS_PER_CONTACT:.0e} (the bound of every "
                        f"resolution), got {steps_per_contact}")
    return laws
