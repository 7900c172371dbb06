"""LAMMPS' input of one scene case (harness run --scene): its spheres against a `fix wall/gran granular` plane (and a
ceiling), gravity where the scene has it, `pair_style granular` only for several spheres, and the dumps
engines/scene_output.py reads (docs/lammps-dialect.md#scenes)."""
from ...infra.render import render
from ...infra.version import __version__
from ..base import SCENES_BEYOND_IMPACT as KINDS
from ..runner import EngineFailure
from ..scene_output import box, contact_scenes, last_frame, overlap
from ...solver.system_contacts import WALL_ABOVE, WALL_BELOW
from .deck import TEMPLATES, settings
from .dialect import words



def scene_reason(kind, law_name, options, version):
    """Why LAMMPS' scene inputs cannot run `kind` for the law with these options, '' when they can."""
    if kind not in KINDS:
        return f"LAMMPS runs no {kind} scene"
    if words(law_name, dict(options or {}), version)[0] != "granular":
        return ("LAMMPS' scene inputs take the granular style (fix wall/gran granular), not --engine-option "
                "style=history")
    return ""


def render_scene(kind, case, grid, options=None, version=None):
    """The input of one scene case for LAMMPS `version` (Engine.render_scene): the contact words of deck.settings for
    the wall contact and, with several spheres, for a pair of them; series.dump every `cadence` steps of the grid."""
    reason = scene_reason(kind, case.variant.law.name, options, version)
    if reason:
        raise EngineFailure(reason)
    v = case.variant
    law = v.law
    wall, pair = contact_scenes(case)
    values = settings(law, wall, case.e_n, options, version)
    pair_values = settings(law, pair, case.e_n, options, version) if pair else values
    steps = [round(t / v.dt) for t in grid]
    every = steps[1] - steps[0] if len(steps) > 1 else max(v.steps, 1)
    x_lo, x_hi, z_lo, z_hi, half = box(case)
    radius = v.spheres[0].radius
    return render(TEMPLATES, "scene.in.j2", harness_version=__version__, kind=kind, law=law.name, e_n=case.e_n,
                  normal=values["normal"], damping=values["damping"], tangential=values["tangential"],
                  normal_args=values["normal_args"], k_t=values["k_t"], x_gamma_t=values["x_gamma_t"],
                  pair_normal_args=pair_values["normal_args"], pair_k_t=pair_values["k_t"],
                  pair_x_gamma_t=pair_values["x_gamma_t"], mu=v.mu, spheres=v.spheres, rho=v.rho, dt=v.dt,
                  steps=v.steps, gravity=v.gravity, ceiling=v.ceiling, x_lo=x_lo, x_hi=x_hi, z_lo=z_lo, z_hi=z_hi,
                  box_half=half, skin=0.5 * radius, every=every, near=kind == "bounce", radius=radius,
                  contacts=len(v.spheres) > 1)


def read_forces(directory, state, variant):
    """{(i, j): (F_n, F_t)} at the end: walls.dump (`id flag fx fz` of fix wall/gran's contacts) gives each touching
    sphere's wall force, fz below and -fz above (fx as F_t); pairs.dump (`id1 id2 F_n` of compute pair/local force)
    each touching pair's normal force (its F_t not written: NaN)."""
    forces = {}
    for atom, flag, fx, fz in last_frame(f"{directory}/walls.dump", "LAMMPS", 4):
        i = int(atom) - 1
        if flag:
            above = variant.ceiling is not None and overlap(state, variant, i, WALL_ABOVE) > 0.0
            forces[(i, WALL_ABOVE if above else WALL_BELOW)] = (-fz if above else fz, fx)
    for a, b, f_n in last_frame(f"{directory}/pairs.dump", "LAMMPS", 3):
        forces[(int(min(a, b)) - 1, int(max(a, b)) - 1)] = (f_n, float("nan"))
    return forces
