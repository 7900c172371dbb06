"""YADE's input of one scene case (harness run --scene): its spheres on a wall (and under a ceiling) of their own
material, gravity, sphere-sphere contacts only with several spheres, the contact law as its impact inputs give it,
and the rows engines/scene_rows.py reads (docs/yade-dialect.md#scenes)."""
import math
from types import SimpleNamespace

from ...infra.render import render
from ...infra.version import __version__
from ..base import SCENES_BEYOND_IMPACT as KINDS
from ..runner import EngineFailure
from ..scene_rows import read_scene_rows, recorded_steps, start_vz
from ...solver.system_run import contact_pairs
from .dialect import COUNTERPARTS
from .script import TEMPLATES, viscel_contact_time

LAWS = ("hertz-mindlin", "linear-spring-dashpot")       # the laws whose impact inputs on a wall scenes reuse
DEFAULTS = {"precision": "double", "linear": "viscel"}  # the only option values they take: the defaults


def scene_reason(kind, law_name, options):
    """Why YADE's scene inputs cannot run `kind` for the law with these options, '' when they can."""
    if kind not in KINDS:
        return f"YADE runs no {kind} scene"
    if law_name not in LAWS:
        return f"YADE's scene inputs run {' and '.join(LAWS)}, not {law_name}"
    if any(DEFAULTS.get(key) != value for key, value in dict(options or {}).items()):
        return "YADE's scene inputs take no engine options (double precision, ViscEl for linear-spring-dashpot)"
    return ""


def material(law, case):
    """The material and physics functor of the law, as the impact inputs on a wall of the sphere's own material
    give them: FrictMat with Ip2 MindlinPhys(en, es) for Hertz-Mindlin, ViscElMat(tc, en, et) for the linear law."""
    v = case.variant
    if law.name == "linear-spring-dashpot":
        tc = viscel_contact_time(law, SimpleNamespace(contact=case.contact, speed=v.speed), case.e_n)
        return dict(material="ViscElMat", tc=tc, en=case.e_n, et=case.e_n, ip2="Ip2_ViscElMat_ViscElMat_ViscElPhys",
                    ip2_args=[])
    return dict(material="FrictMat", young=v.E, poisson=v.nu, ip2="Ip2_FrictMat_FrictMat_MindlinPhys",
                ip2_args=[("en", case.e_n), ("es", case.e_n)])


def render_scene(kind, case, grid, options=None):
    """The script of one scene case (Engine.render_scene): exactly the scene's effects (a wall unless it flies
    free, a ceiling where the case has one, Ig2_Sphere_Sphere_ScGeom only with several spheres), the spheres at
    v(-dt/2), a state row every cadence step of `grid`, and the touches and partings for a bounce."""
    v = case.variant
    reason = scene_reason(kind, v.law.name, options)
    if reason:
        raise EngineFailure(reason)
    _, every = recorded_steps(grid, v.dt)
    wall = kind != "free-fall"
    spheres = [dict(x=s.x, z=s.z, radius=s.radius, vx=s.vx, vz=start_vz(s, v), w=s.w) for s in v.spheres]
    pairs = contact_pairs(len(v.spheres), v.ceiling)
    return render(TEMPLATES, "scene.py.j2", harness_version=__version__, kind=kind, law=v.law.name,
                  law2=COUNTERPARTS[v.law.name], e_n=case.e_n, rho=v.rho, friction_angle=math.atan(v.mu),
                  spheres=spheres, wall=wall, ceiling=v.ceiling, contacts=wall, pairs=len(v.spheres) > 1,
                  gravity=v.gravity, dt=v.dt, steps=v.steps, every=every, events=kind == "bounce",
                  contact_list=[(k, int(i), int(j)) for k, (i, j) in enumerate(pairs)] if wall else [],
                  **material(v.law, case))


def read_scene(kind, case, grid, directory):
    """The SystemResult of a finished scene run in `directory` (Engine.read_scene)."""
    return read_scene_rows("YADE", case, grid, directory)
