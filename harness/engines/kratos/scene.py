"""Kratos' input of one scene case (harness run --scene): its spheres on a rigid face of their own material (none in
free flight), gravity, the ball-ball relation acting only with several spheres, the law's counterpart as its impact
inputs name it, and the rows engines/scene_rows.py reads (docs/kratos-dialect.md#scenes)."""
import os

from ...infra.render import render
from ...infra.version import __version__
from ..base import SCENES_BEYOND_IMPACT as KINDS
from ..runner import EngineFailure, read_tail
from ..scene_rows import read_scene_rows, recorded_steps, start_vz
from .dialect import COUNTERPARTS
from .script import TEMPLATES



def scene_reason(kind, law_name, options):
    """Why Kratos' scene inputs cannot run `kind` for the law with these options, '' when they can."""
    if kind not in KINDS:
        return f"Kratos runs no {kind} scene"
    if law_name not in COUNTERPARTS:
        return f"Kratos has no counterpart of {law_name}"
    if options:
        return "Kratos' scene inputs take no engine options"
    return ""


def wall_span(case):
    """(centre x, half-width) of a face under every sphere's path: the horizontal reach at the start speeds over the
    run, and 4 R beyond."""
    v = case.variant
    reach = max(abs(s.vx) for s in v.spheres) * v.steps * v.dt + 4.0 * max(s.radius for s in v.spheres)
    xs = [s.x for s in v.spheres]
    return 0.5 * (min(xs) + max(xs)), 0.5 * (max(xs) - min(xs)) + reach


def render_scene(kind, case, grid, options=None):
    """The script of one scene case (Engine.render_scene): exactly the scene's effects (a rigid face unless it flies
    free, no neighbour search without contacts), the spheres at v(-dt/2), a state row every cadence step of `grid`,
    and the touches and partings for a bounce. A ceiling is refused (no face above yet)."""
    v = case.variant
    reason = scene_reason(kind, v.law.name, options)
    if reason:
        raise EngineFailure(reason)
    if v.ceiling is not None:
        raise EngineFailure("Kratos' scene inputs have no face above the spheres yet: stack with walls = 1 only")
    _, every = recorded_steps(grid, v.dt)
    wall = kind != "free-fall"
    centre, half = wall_span(case)
    spheres = [dict(x=s.x, z=s.z, radius=s.radius, vx=s.vx, vz=start_vz(s, v), w=s.w) for s in v.spheres]
    return render(TEMPLATES, "scene.py.j2", harness_version=__version__, kind=kind, law=v.law.name,
                  counterpart=COUNTERPARTS[v.law.name], e_n=case.e_n, mu=v.mu, E=v.E, nu=v.nu, rho=v.rho,
                  spheres=spheres, wall=wall, wall_x=centre, wall_half=half, contacts=wall or len(v.spheres) > 1,
                  gravity=v.gravity, dt=v.dt, steps=v.steps, every=every, events=kind == "bounce")


def read_scene(kind, case, grid, directory):
    """The SystemResult of a finished scene run in `directory` (Engine.read_scene); a failure carries the tail of the
    log there (each Kratos script runs, and logs, in its own directory)."""
    try:
        return read_scene_rows("Kratos", case, grid, directory)
    except EngineFailure as exc:
        raise EngineFailure(str(exc), exc.log_tail or read_tail(os.path.join(directory, "engine.log"))) from None
