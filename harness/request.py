"""What a user asks for, from the CLI's options or the Python API's keywords (the same names): a law and its
sub-model replacements, a scene, a resolution, engines and their options; validated once, one clear line for bad
input."""
import math
from dataclasses import dataclass, field

from .errors import UserError
from .solver.plan import MAX_STEPS_PER_CONTACT
from .plan import CONVERGED
from .scene import DEFAULT_ANGLES, DEFAULT_EN, DEFAULT_SPEED, from_material
from .solver.plan import FixedTimeStep

SCENE_KEYWORDS = ("en", "angles", "psi", "vt", "mu", "material", "radius", "E", "nu", "rho", "speed", "normal_speed",
                  "omega0", "gravity", "wall", "target", "target_radius", "target_material", "target_omega",
                  "target_fixed")
TARGETS = ("wall", "sphere")


def scene_from(en=DEFAULT_EN, angles=None, psi=None, vt=None, mu=None, material="tcc13", radius=None, E=None,
               nu=None, rho=None, speed=None, normal_speed=None, omega0=0.0, gravity=0.0, wall="same", target="wall",
               target_radius=None, target_material="same", target_omega=0.0, target_fixed=False):
    """The validated Scene of the scene keywords; with target="sphere", the equivalent wall impact of the sphere
    hitting a target sphere at rest (harness.two_spheres.reduce)."""
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
                         **wall_fields(wall))
    if sphere is None:
        return scene
    from .two_spheres import reduce
    return reduce(scene, sphere(scene))


def target_sphere(target, radius, material, omega, fixed):
    """--target wall|sphere and the target sphere's options -> None (a wall) or a function of the projectile's scene
    giving the target Sphere (its radius and material default to the projectile's)."""
    from .bodies import Sphere
    if target not in TARGETS:
        raise UserError(f"--target must be one of {', '.join(TARGETS)}, got {target!r}")
    if target == "wall":
        given = [name for name, value, default in (("radius", radius, None), ("material", material, "same"),
                                                   ("omega", omega, 0.0), ("fixed", fixed, False))
                 if value != default]
        if given:
            raise UserError(f"--target-{given[0]} describes a sphere target: give --target sphere")
        return None
    if radius is not None and not (isinstance(radius, (int, float)) and math.isfinite(radius) and radius > 0):
        raise UserError(f"--target-radius must be a positive number of metres, got {radius!r}")
    if not (isinstance(omega, (int, float)) and math.isfinite(omega)):
        raise UserError(f"--target-omega must be a finite number, got {omega!r}")
    fields = target_material_fields(material)

    def sphere(scene):
        own = {"E": scene.E, "nu": scene.nu, "rho": scene.rho, **fields}
        return Sphere(scene.radius if radius is None else float(radius), own["E"], own["nu"], own["rho"],
                      omega=float(omega), fixed=bool(fixed))
    return sphere


def target_material_fields(text):
    """--target-material same|MATERIAL|E=PASCAL,nu=RATIO,rho=KG_M3 -> the target's E, nu, rho (same: the projectile's)."""
    if text == "same":
        return {}
    if "=" in text:
        fields = dict(part.partition("=")[::2] for part in text.split(","))
        if set(fields) != {"E", "nu", "rho"}:
            raise UserError(f"--target-material E=PASCAL,nu=RATIO,rho=KG_M3 takes E, nu and rho, got {text!r}")
        try:
            values = {k: float(v) for k, v in fields.items()}
        except ValueError:
            raise UserError(f"--target-material E, nu and rho must be numbers, got {text!r}") from None
        if not (values["E"] > 0 and -1.0 < values["nu"] < 0.5 and values["rho"] > 0):
            raise UserError(f"--target-material needs E > 0, -1 < nu < 0.5 and rho > 0, got {text!r}")
        return values
    from .materials import get_material
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
        try:
            return {"wall": "other", "wall_E": float(fields["E"]), "wall_nu": float(fields["nu"])}
        except ValueError:
            raise UserError(f"--wall E and nu must be numbers, got {text!r}") from None
    from .materials import get_material
    mat = get_material(text)
    return {"wall": "other", "wall_E": mat.E, "wall_nu": mat.nu}


def resolution_from(steps_per_contact=None, dt=None, converged=False):
    """--steps-per-contact N (a whole number >= 1, default 1000), --dt SECONDS (> 0) or --converged."""
    if sum((steps_per_contact is not None, dt is not None, bool(converged))) > 1:
        raise UserError("give one of --steps-per-contact, --dt, --converged")
    if converged:
        return CONVERGED
    if dt is not None:
        if not (math.isfinite(dt) and dt > 0.0):
            raise UserError(f"--dt must be a positive number of seconds, got {dt:g}")
        return FixedTimeStep(dt)
    steps = 1000 if steps_per_contact is None else steps_per_contact
    if isinstance(steps, bool) or not isinstance(steps, int) or steps < 1:
        raise UserError(f"--steps-per-contact must be a whole number >= 1, got {steps!r}")
    if steps > MAX_STEPS_PER_CONTACT:
        raise UserError(f"--steps-per-contact must be at most {MAX_STEPS_PER_CONTACT:.0e}, got {steps}")
    return steps


def engine_options_from(pairs):
    """[(engine, key, value)] from --engine-option ENGINE:KEY=VALUE -> {engine: {key: value}}; a key given twice is
    refused (the last would silently win)."""
    from .engines import get_engine
    out = {}
    for engine, key, value in pairs or ():
        get_engine(engine)
        if key in out.setdefault(engine, {}):
            raise UserError(f"engine option {engine}:{key} given twice")
        out[engine][key] = value
    return out


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
        from .laws import compose
        return compose(self.model, dict(self.overrides))

    @classmethod
    def from_keywords(cls, model, engines=None, engine_options=None, steps_per_contact=None, dt=None,
                      converged=False, tolerances=None, **keywords):
        """From the API's keywords (the CLI passes its options under the same names): `with_` or `overrides` for
        --with, `engine_options` as {engine: {key: value}} or [(engine, key, value)], `tolerances` as
        {name: value} or ["name=value"] (the physics verdict's, harness.analyses.physics.Tolerances)."""
        from .analyses.physics import Tolerances
        overrides = keywords.pop("with_", None) or keywords.pop("overrides", None) or ()
        unknown = set(keywords) - set(SCENE_KEYWORDS)
        if unknown:
            raise UserError(f"unknown keyword(s) {', '.join(sorted(unknown))}")
        pairs = dict(overrides).items() if isinstance(overrides, dict) else overrides
        keys = [k for k, _ in pairs]
        repeated = sorted({k for k in keys if keys.count(k) > 1})
        if repeated:
            raise UserError(f"--with {repeated[0]}=... given twice")
        options = engine_options_from(engine_options) if not isinstance(engine_options, dict) else \
            {e: dict(o) for e, o in (engine_options or {}).items()}
        ignored = sorted(set(options) - set(engines)) if engines is not None else []
        if ignored:
            raise UserError(f"--engine-option for {ignored[0]}, which is not among the engines asked for "
                            f"({', '.join(engines)})")
        request = cls(model, scene_from(**keywords), resolution_from(steps_per_contact, dt, converged),
                      tuple(pairs), None if engines is None else tuple(engines), options, Tolerances.of(tolerances))
        law = request.law                    # unknown law or sub-model: refused here, before anything runs
        if request.scene.spheres:
            from .two_spheres import refuse_engine_levers
            refuse_engine_levers(law)
        return request
