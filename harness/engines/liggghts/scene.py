"""LIGGGHTS' input of one scene case (harness run --scene): its spheres against a `fix wall/gran` primitive plane
(and a second one as the ceiling), gravity where the scene has it, `pair_style gran` only for several spheres, and
the dumps engines/scene_output.py reads (docs/liggghts-dialect.md#scenes)."""
import math

import numpy as np

from ...infra.render import render
from ...infra.version import __version__
from ...solver.system_contacts import WALL_ABOVE, WALL_BELOW
from ..base import SCENES_BEYOND_IMPACT as KINDS
from ..runner import EngineFailure
from ..scene_output import box, contact_scenes, last_frame
from .deck import MIN_RESTITUTION, TEMPLATES, settings
from .dialect import COUNTERPARTS

SCENE_MODELS = ("hooke", "hertz")   # whose settings need no more of the scene than its contact, speed and friction


def scene_reason(kind, law_name):
    """Why LIGGGHTS' scene inputs cannot run `kind` for the law, '' when they can."""
    if kind not in KINDS:
        return f"LIGGGHTS runs no {kind} scene"
    if COUNTERPARTS.get(law_name) not in SCENE_MODELS:
        return f"LIGGGHTS' scene inputs take models {' and '.join(SCENE_MODELS)}, not {COUNTERPARTS.get(law_name)}"
    return ""


def render_scene(kind, case, grid, options=None):
    """The input of one scene case (Engine.render_scene): deck.settings of the wall contact (LIGGGHTS derives each
    contact's own k_n, damping and k_t from the materials); series.dump every `cadence` steps of the grid."""
    v = case.variant
    reason = scene_reason(kind, v.law.name)
    if reason:
        raise EngineFailure(reason)
    model, tangential, extra, properties, restitution = settings(v.law, contact_scenes(case)[0], case.e_n, options)
    if not MIN_RESTITUTION < restitution <= 1.0:
        raise EngineFailure(f"LIGGGHTS accepts coefficientRestitution in (0.05, 1] only; e_n = {case.e_n:g} was not "
                            "run")
    steps = [round(t / v.dt) for t in grid]
    every = steps[1] - steps[0] if len(steps) > 1 else max(v.steps, 1)
    x_lo, x_hi, z_lo, z_hi, half = box(case)
    radius = v.spheres[0].radius
    return render(TEMPLATES, "scene.in.j2", harness_version=__version__, kind=kind, law=v.law.name, model=model,
                  tangential=tangential, options=extra, properties=properties, e_n=restitution, E=v.E, nu=v.nu,
                  mu=v.mu, spheres=v.spheres, rho=v.rho, dt=v.dt, steps=v.steps, gravity=v.gravity,
                  ceiling=v.ceiling, x_lo=x_lo, x_hi=x_hi, z_lo=z_lo, z_hi=z_hi, box_half=half, skin=0.5 * radius,
                  every=every, near=kind == "bounce", radius=radius, contacts=len(v.spheres) > 1)


def read_forces(directory, state, variant):
    """{(i, j): (F_n, F_t)} at the end: walls.dump (`id fx fz` of the floor's store_force, then the ceiling's) gives
    each sphere's wall forces, fz below and -fz above (fx as F_t); pairs.dump (two positions, two ids, the force on
    the first, of compute pair/gran/local) each touching pair's force along the line of centres (F_t: NaN)."""
    ceiling = variant.ceiling is not None
    forces = {}
    for row in last_frame(f"{directory}/walls.dump", "LIGGGHTS", 5 if ceiling else 3):
        i = int(row[0]) - 1
        forces[(i, WALL_BELOW)] = (row[2], row[1])
        if ceiling:
            forces[(i, WALL_ABOVE)] = (-row[4], row[3])
    for row in last_frame(f"{directory}/pairs.dump", "LIGGGHTS", 11):
        first, second, a, b, force = row[0:3], row[3:6], int(row[6]) - 1, int(row[7]) - 1, row[8:11]
        line = (first - second) / np.linalg.norm(first - second)
        forces[(min(a, b), max(a, b))] = (abs(float(np.dot(force, line))), math.nan)
    return forces
