"""Scene: what to simulate (sphere, wall, impact set), validated once, with the effective contact properties."""
import math
import sys
from dataclasses import dataclass, field
from numbers import Real

import numpy as np

from .bodies import Sphere
from ..infra.errors import UserError
from .materials import get_material

DEFAULT_EN = (0.25, 0.5, 0.75, 0.9)                         # the paper's e_n
DEFAULT_ANGLES = tuple(float(a) for a in range(1, 90, 2))   # 45 impact angles, 1..89 deg
DEFAULT_SPEED = 5.0                                         # the paper's impact speed [m/s]
WALLS = ("same", "rigid")
SPEEDS = ("resultant", "normal")                            # what --speed holds fixed across impact angles


@dataclass(frozen=True)
class Contact:
    """Effective sphere-wall properties: E* and G* (docs/laws.md#contact), R* = R, m* = m, I = 2/5 m R^2."""
    radius: float
    mass: float
    inertia: float
    E_star: float
    G_star: float
    nu: float
    rho: float
    E: float = 0.0

    @property
    def kappa(self):
        """kappa = 4 G*/E*: Mindlin tangential to Hertz normal stiffness, 2(1 - nu)/(2 - nu) for one material."""
        return 4.0 * self.G_star / self.E_star

    @property
    def chi(self):
        """chi = 3.5 (1 - nu)/(2 - nu) for a solid sphere (Maw, Barber & Fawcett 1976)."""
        return 3.5 * (1.0 - self.nu) / (2.0 - self.nu)


@dataclass(frozen=True)
class Scene:
    """A sphere of radius R hitting a wall: at the listed angles (deg from the normal) with speed V the resultant
    (speed_is 'resultant', LIGGGHTS-PFM's way) or the normal speed (speed_is 'normal', Kratos' way: V_t = V tan
    theta), or at normal speed V with the listed Psi1* values or tangential speeds v_t. Defaults: the paper's scene
    (material tcc13, 5 m/s, e_n 0.25/0.5/0.75/0.9). With `spheres` (projectile, target: bodies.Sphere) the target is
    a sphere and the scene is their relative motion's equivalent wall impact (harness.solver.two_spheres.reduce)."""
    radius: float = 25e-3
    E: float = 70e9
    nu: float = 0.3
    rho: float = 2650.0
    mu: float = 0.1
    speed: float = DEFAULT_SPEED
    e_n: tuple = DEFAULT_EN
    angles_deg: tuple | None = DEFAULT_ANGLES
    psi1_star: tuple | None = None
    v_t: tuple | None = None
    omega0: float = 0.0
    wall: str = "same"
    wall_E: float | None = None
    wall_nu: float | None = None
    gravity: float = 0.0
    material: str = "tcc13"
    speed_is: str = "resultant"
    spheres: tuple | None = None
    gap: float = 0.0
    at_times: tuple = ()
    extra: dict = field(default_factory=dict, compare=False)

    def __post_init__(self):
        validate(self)

    @property
    def contact(self):
        return contact_properties(self)

    def impacts(self, e_n):
        """Incident (v_n, v_t, omega, theta_deg) arrays for one target e_n (Psi1* needs e_n: docs/laws.md)."""
        if self.angles_deg is not None:
            theta_deg = np.asarray(self.angles_deg, dtype=float)
            theta = np.radians(theta_deg)
            if self.speed_is == "normal":
                v_n, v_t = np.full_like(theta, self.speed), self.speed * np.tan(theta)
            else:
                v_n, v_t = self.speed * np.cos(theta), self.speed * np.sin(theta)
        else:
            if self.psi1_star is not None:      # Psi1* = 2 (V_t - R omega0)/(mu (1 + e_n) V_n)
                psi = np.asarray(self.psi1_star, dtype=float)
                v_t = psi * 0.5 * self.mu * (1.0 + e_n) * self.speed + self.radius * self.omega0
            else:
                v_t = np.asarray(self.v_t, dtype=float)
            v_n = np.full_like(v_t, self.speed)
            theta_deg = np.degrees(np.arctan2(v_t, v_n))
        return v_n, v_t, np.full_like(v_n, self.omega0), theta_deg


def scene_of_record(record):
    """The Scene of its fields as written to JSON: lists back to tuples, the two spheres back to bodies."""
    fields = {k: tuple(v) if isinstance(v, list) else v for k, v in dict(record).items()}
    if fields.get("spheres"):
        fields["spheres"] = tuple(Sphere(**body) for body in fields["spheres"])
    return Scene(**fields)


def contact_properties(scene):
    """E* = 1/[(1-nu1^2)/E1 + (1-nu2^2)/E2], G* = 1/[(2-nu1)/G1 + (2-nu2)/G2]; rigid wall: E2, G2 -> inf."""
    E1, nu1 = scene.E, scene.nu
    G1 = E1 / (2.0 * (1.0 + nu1))
    inv_e = (1.0 - nu1 ** 2) / E1
    inv_g = (2.0 - nu1) / G1
    if scene.wall == "same":
        inv_e, inv_g = 2.0 * inv_e, 2.0 * inv_g
    elif scene.wall == "other":
        E2, nu2 = scene.wall_E, scene.wall_nu
        inv_e += (1.0 - nu2 ** 2) / E2
        inv_g += (2.0 - nu2) / (E2 / (2.0 * (1.0 + nu2)))
    mass = 4.0 / 3.0 * math.pi * scene.radius ** 3 * scene.rho
    return Contact(radius=scene.radius, mass=mass, inertia=0.4 * mass * scene.radius ** 2,
                   E_star=1.0 / inv_e, G_star=1.0 / inv_g, nu=nu1, rho=scene.rho, E=E1)


def _is_number(value):
    return isinstance(value, Real) and not isinstance(value, bool) and math.isfinite(value)


def _subnormal(value):
    """0 < |value| < 2.2e-308: digits already lost, and whatever divides by it overflows."""
    return 0.0 < abs(value) < sys.float_info.min


def _positive(name, value):
    if not (_is_number(value) and value > 0):
        raise UserError(f"{name} must be a positive number, got {value!r}")


# the physical range a scene may take: contact mechanics of solid spheres, not molecules, planets or shock waves
BOUNDS = {"radius": (1e-7, 10.0, "m"), "E": (1e3, 1e13, "Pa"), "rho": (1.0, 3e6, "kg/m^3"),
          "speed": (1e-6, 1e3, "m/s"), "gravity": (0.0, 1e3, "m/s^2"), "mu": (0.0, 10.0, "")}
WHY = {"rho": " (at most 1000x aluminium's: Chung & Ooi's test 8 stands a near-rigid sphere in for a wall)"}
BODY = ("radius", "rho")        # of two spheres, bounds on the projectile's own (R* and m* are derived)
MAX_SURFACE_SPEED = 1e3          # m/s: tangential speed, R omega0
OTHER_E = (1e3, 1e14)            # Pa: a wall's or a target sphere's E, up to Chung & Ooi's test 8 (1000x aluminium's)
TARGET_RADIUS = (1e-7, 1e4, "m")  # a target far larger than the sphere is the wall's limit; its mass stays finite
TARGET_RADIUS_WHY = " (a target far larger than the sphere is the wall's limit)"
OTHER_E_WHY = " (up to 1000x aluminium's, the near-rigid target of Chung & Ooi's test 8)"
MIN_E_N = 1e-3                   # below, the damping calibrations leave their range (the linear no-tension one ends
                                 # near 1e-4, Tsuji's Appendix B fit sooner) and an impact is plastic to measurement
MAX_IMPACTS = 10 ** 6            # per run: e_n values x impacts
MAX_GAP_RADII = 10.0             # a starting gap of at most ten radii: the approach is stepped like the contact
MAX_TIMES = 1000                 # times a state is recorded at, per impact


def within_bounds(scene):
    """One line naming the bound a scene value lies outside (UserError); of two spheres, the projectile's radius and
    rho (their equivalent sphere's are derived; the target's own bounds: check_body)."""
    for name, (low, high, unit) in BOUNDS.items():
        value = getattr(scene.spheres[0], name) if scene.spheres and name in BODY else getattr(scene, name)
        if not low <= value <= high:
            raise UserError(f"{name} must lie in [{low:g}, {high:g}] {unit}{WHY.get(name, '')}, got {value!r}"
                            .replace(" ,", ","))
    if abs(scene.omega0) * scene.radius > MAX_SURFACE_SPEED:
        raise UserError(f"|omega0| R must be at most {MAX_SURFACE_SPEED:g} m/s, "
                        f"got {abs(scene.omega0) * scene.radius:g}")
    surface = list(scene.v_t or ()) + [p * scene.mu * scene.speed for p in scene.psi1_star or ()]   # V_t at e_n 1
    if any(v > MAX_SURFACE_SPEED for v in surface):
        raise UserError(f"tangential speeds must be at most {MAX_SURFACE_SPEED:g} m/s, got {max(surface):g}")
    if scene.angles_deg and scene.speed_is == "normal":
        steepest = max(scene.angles_deg)
        v_t = scene.speed * math.tan(math.radians(steepest))
        if v_t > MAX_SURFACE_SPEED:
            raise UserError(f"tangential speeds must be at most {MAX_SURFACE_SPEED:g} m/s, got V_n tan(angle) = "
                            f"{v_t:.3g} m/s at {steepest:g} deg and normal speed {scene.speed:g} m/s")
    if scene.wall == "other" and not OTHER_E[0] <= scene.wall_E <= OTHER_E[1]:
        raise UserError(f"{'target' if scene.spheres else 'wall'} E must lie in [{OTHER_E[0]:g}, {OTHER_E[1]:g}] Pa"
                        f"{OTHER_E_WHY}, got {scene.wall_E!r}")
    count = len(scene.e_n) * len(scene.angles_deg or scene.psi1_star or scene.v_t or ())
    if count > MAX_IMPACTS:
        raise UserError(f"at most {MAX_IMPACTS:.0e} impacts per run, got {count} (split the sweep)")


def check_body(sphere):
    """A target sphere within its bounds (a scene's sphere's, but its E a wall's, up to 1e14 Pa, and its radius up to
    1e4 m), before its mass or any effective property is computed (UserError naming the bound)."""
    for name in ("radius", "E", "nu", "rho", "v_n", "v_t", "omega"):
        value = getattr(sphere, name)
        if not _is_number(value) or _subnormal(value):
            raise UserError(f"target {name} must be a finite number of normal size, got {value!r}")
    for name, (low, high, unit), why in (("radius", TARGET_RADIUS, TARGET_RADIUS_WHY),
                                         ("E", (*OTHER_E, "Pa"), OTHER_E_WHY), ("rho", BOUNDS["rho"], WHY["rho"])):
        if not low <= getattr(sphere, name) <= high:
            raise UserError(f"target {name} must lie in [{low:g}, {high:g}] {unit}{why}, got {getattr(sphere, name)!r}")
    if not -1.0 < sphere.nu < 0.5:
        raise UserError(f"target nu must lie in (-1, 0.5), got {sphere.nu!r}")
    for name, value in (("|v_n|", sphere.v_n), ("|v_t|", sphere.v_t), ("|omega| R", sphere.omega * sphere.radius)):
        if abs(value) > MAX_SURFACE_SPEED:
            raise UserError(f"target {name} must be at most {MAX_SURFACE_SPEED:g} m/s, got {abs(value):g}")


def validate(scene):
    """Reject physically meaningless scenes with one clear line (UserError); only finite numbers get through."""
    for name in ("nu", "mu", "omega0", "gravity"):
        if not _is_number(getattr(scene, name)):
            raise UserError(f"{name} must be a finite number, got {getattr(scene, name)!r}")
    for name in ("e_n", "angles_deg", "psi1_star", "v_t"):
        values = getattr(scene, name)
        if values is not None and not (isinstance(values, tuple) and all(_is_number(v) for v in values)):
            raise UserError(f"{name} must be a tuple of finite numbers, got {values!r}")
    for name in ("radius", "E", "rho", "speed"):
        _positive(name, getattr(scene, name))
    if scene.spheres is not None:
        if not (isinstance(scene.spheres, tuple) and len(scene.spheres) == 2 and
                all(isinstance(b, Sphere) for b in scene.spheres)):
            raise UserError(f"spheres must be (projectile, target) Spheres, got {scene.spheres!r}"[:200])
        check_body(scene.spheres[1])
    if not -1.0 < scene.nu < 0.5:
        raise UserError(f"nu must lie in (-1, 0.5), got {scene.nu!r}")
    if not (math.isfinite(scene.mu) and scene.mu >= 0):
        raise UserError(f"mu must be >= 0, got {scene.mu!r}")
    if not math.isfinite(scene.omega0) or not math.isfinite(scene.gravity) or scene.gravity < 0:
        raise UserError("omega0 must be finite and gravity >= 0")
    if not isinstance(scene.material, str):
        raise UserError(f"material must be a name, got {scene.material!r}")
    if scene.speed_is not in SPEEDS:
        raise UserError(f"speed_is must be one of {', '.join(SPEEDS)}, got {scene.speed_is!r}")
    if scene.wall not in WALLS + ("other",):
        raise UserError(f"wall must be one of {', '.join(WALLS)}, got {scene.wall!r}")
    if scene.wall == "other":
        _positive("wall E", scene.wall_E)
        if scene.wall_nu is None or not -1.0 < scene.wall_nu < 0.5:
            raise UserError(f"wall nu must lie in (-1, 0.5), got {scene.wall_nu!r}")
    if not scene.e_n:
        raise UserError("at least one e_n is needed")
    for e in scene.e_n:
        if not (math.isfinite(e) and MIN_E_N <= e <= 1.0):
            raise UserError(f"e_n must lie in [{MIN_E_N:g}, 1] (below, the damping calibrations leave their range), "
                            f"got {e!r}")
    if sum(x is not None for x in (scene.angles_deg, scene.psi1_star, scene.v_t)) != 1:
        raise UserError("give exactly one of: impact angles, Psi1* values, tangential speeds")
    if scene.v_t is not None:
        if not scene.v_t or not all(math.isfinite(v) and v >= 0 for v in scene.v_t):
            raise UserError(f"tangential speeds must be finite and >= 0, got {scene.v_t!r}")
    if scene.angles_deg is not None:
        if not scene.angles_deg:
            raise UserError("at least one impact angle is needed")
        for a in scene.angles_deg:
            if not (math.isfinite(a) and 0.0 <= a < 90.0):
                raise UserError(f"impact angle must lie in [0, 90) degrees, got {a!r}")
    elif scene.psi1_star is not None:
        if scene.mu == 0:
            raise UserError("Psi1* is undefined for mu = 0 (Psi1* = 2 V_s/(mu (1 + e) V_n)); give angles instead")
        for psi in scene.psi1_star:
            if not (math.isfinite(psi) and psi >= 0):
                raise UserError(f"Psi1* must be >= 0, got {psi!r}")
    within_bounds(scene)
    check_start(scene)


def check_start(scene):
    """A gap of a finite number of metres in [0, MAX_GAP_RADII R] and times that are finite, >= 0 and increasing."""
    if not _is_number(scene.gap) or _subnormal(scene.gap) or not 0.0 <= scene.gap <= MAX_GAP_RADII * scene.radius:
        raise UserError(f"gap must be a distance in [0, {MAX_GAP_RADII:g} radii] = [0, "
                        f"{MAX_GAP_RADII * scene.radius:g}] m, got {scene.gap!r}")
    times = scene.at_times
    if not (isinstance(times, tuple) and all(_is_number(t) for t in times)):
        raise UserError(f"at_times must be a tuple of finite numbers of seconds, got {times!r}"[:200])
    if any(t < 0.0 for t in times):
        raise UserError(f"at_times must be >= 0 s, got {min(times)!r}")
    if any(b <= a for a, b in zip(times, times[1:])):
        raise UserError(f"at_times must increase, each time once, got {', '.join(f'{t:g}' for t in times)}"[:200])
    if len(times) > MAX_TIMES:
        raise UserError(f"at most {MAX_TIMES} at_times, got {len(times)}")


def from_material(name, **overrides):
    """Scene from a preset material (radius, E, nu, rho, mu where the preset has one) plus explicit overrides."""
    mat = get_material(name)
    values = dict(radius=mat.radius, E=mat.E, nu=mat.nu, rho=mat.rho, material=mat.name)
    if mat.mu is not None:
        values["mu"] = mat.mu
    material_keys = ("radius", "E", "nu", "rho", "mu")     # None here means "the preset's value"
    values.update({k: v for k, v in overrides.items() if v is not None or k not in material_keys})
    return Scene(**values)


STEP_ROUNDING = 1e-9            # a named time within this many steps of a step's end is that step's


def state_steps(times, dt):
    """k = ceil(t/dt - 1e-9) of each time: the step after which the state at t is taken, the same in the reference
    and in every engine."""
    return [int(math.ceil(t / dt - STEP_ROUNDING)) for t in times]
