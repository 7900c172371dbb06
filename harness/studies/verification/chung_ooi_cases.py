"""Chung & Ooi (2011, Granular Matter 13:643)'s eight tests as published: each test's materials, radii, speeds, mu,
e and swept variable as its independent reproductions give them (docs/chung-ooi.md names the source of each number),
and each case's time step, fixed from its bodies' Rayleigh time and independent of the answer."""
import math
from dataclasses import dataclass

from ...analyses.cost import rayleigh_time
from ...scenes.bodies import Sphere
from ...scenes.materials import get_material
from ...scenes.scene import Scene
from ...solver.two_spheres import reduce

ANGLES = tuple(float(a) for a in range(5, 90, 5))   # Kratos' 17 incident angles, 5..85 deg (tests 4-8)
RESTITUTIONS = (0.2, 0.4, 0.6, 0.8, 1.0)            # test 3's e_in (PySPH's; e = 0 has no finite dashpot)
RIGID_TARGET = 1000.0                               # test 8: the target's density and modulus over the projectile's
TARGET_RADII = 5.0                                  # test 8: the target's radius over the projectile's
RAYLEIGH_STEPS = 1000                               # dt: a power of ten at or below T_R / this

TESTS = {   # number -> (title, scene, what is expected)
    1: ("elastic normal impact of two identical spheres",
        "Two glass (E 48 GPa, nu 0.20, rho 2800) and two limestone (E 20 GPa, nu 0.25, rho 2500) spheres, R 10 mm, "
        "each at 10 m/s towards the other, e = 1.",
        "Hertz's peak force, peak overlap and contact duration with R* = R/2, m* = m/2; e_n = 1."),
    2: ("elastic normal impact of a sphere with a rigid plane",
        "Aluminium alloy (E 70 GPa, nu 0.30, rho 2699) and magnesium alloy (E 40 GPa, nu 0.35, rho 1800) spheres, "
        "R 0.1 m, at 0.2 m/s, e = 1.",
        "Hertz's peak force, peak overlap and contact duration with E* = E/(1 - nu^2), R* = R, m* = m; e_n = 1."),
    3: ("normal impact with restitution",
        "Alumina (E 380 GPa, nu 0.23, rho 4000) and cast iron (E 100 GPa, nu 0.25, rho 7000) spheres, R 2.5 mm, at "
        "3.9 m/s on a rigid plane, mu 0, e_in 0.2, 0.4, 0.6, 0.8, 1.",
        "e_out = e_in."),
    4: ("oblique impact at constant resultant speed",
        "Alumina and aluminium alloy (E 70 GPa, nu 0.33, rho 2700) spheres, R 2.5 mm, 3.9 m/s at 5-85 deg in steps "
        "of 5, mu 0.092, e 0.98, on a rigid plane.",
        "In gross sliding the rigid-body impulses J_n = m (1 + e) V_n, |J_t| = mu J_n with the suite's e: "
        "v_t1 = v_t0 - mu (1 + e) V_n, omega1 = omega0 + 5 mu (1 + e) V_n/(2 R); e_n = e."),
    5: ("oblique impact at constant normal speed",
        "Steel (E 208 GPa, nu 0.30, rho 7850) and polyethylene (E 1 GPa, nu 0.40, rho 1400) spheres, R 10 um, "
        "normal speed 5 m/s, V_t = 5 tan(angle) m/s at 5-85 deg, mu 0.3, e 1, on a rigid plane.",
        "The gross-sliding lines of test 4 with e = 1; e_n = 1."),
    6: ("impact with spin on a rigid plane",
        "Aluminium alloy (as test 4) and nylon (E 2.5 GPa, nu 0.40, rho 1000) spheres, R 0.1 m, at 0.2 m/s normal "
        "to the plane with no tangential velocity, spinning so that R omega0 = -0.2 tan(angle) m/s at 5-85 deg, "
        "mu 0.4, e 0.5.",
        "The gross-sliding lines where |Psi1*| >= the threshold (the stick regime is reported); e_n = e."),
    7: ("two identical spheres with spin",
        "Two aluminium alloy (as test 4) and two copper (E 120 GPa, nu 0.35, rho 8900) spheres, R 0.1 m, each at "
        "0.2 m/s towards the other, spinning at +omega and -omega about one axis, omega = 2 tan(angle) rad/s at "
        "5-85 deg, mu 0.4, e 0.5: their contact points move together.",
        "No slip at first touch, so no tangential impulse: each body keeps v_t = 0 and its spin; e_n = e."),
    8: ("two spheres of different size with spin",
        "An aluminium alloy (as test 4) or nylon (as test 6) sphere, R 0.1 m, at 0.2 m/s with spin "
        "R omega0 = -0.2 tan(angle) m/s at 5-85 deg, on a sphere of the same material at rest with radius 5 R and "
        "1000x its density and Young's modulus (which tends to test 6), mu 0.4, e 0.5.",
        "Each body's gross-sliding impulses where |Psi1*| >= the threshold (the stick regime is reported); e_n = e."),
}


@dataclass(frozen=True)
class Case:
    """One impact configuration of a test: a wall scene, or a projectile scene and a target sphere; its time step."""
    test: int
    label: str
    scene: Scene
    target: Sphere | None = None

    @property
    def effective_scene(self):
        return self.scene if self.target is None else reduce(self.scene, self.target)

    @property
    def time_step(self):
        """dt = 10^floor(log10(T_R/1000)), T_R the smallest Rayleigh time of the bodies (Li, Xu & Thornton 2005):
        fixed by the materials and radii alone, whatever the speed or the closed form."""
        bodies = [self.scene] + ([self.target] if self.target is not None else [])
        return 10.0 ** math.floor(math.log10(min(rayleigh_time(b) for b in bodies) / RAYLEIGH_STEPS))


def material(name, **changes):
    """(E, nu, rho) of a preset of harness.scenes.materials, with the changes a test's sources make."""
    preset = get_material(name)
    return {**dict(E=preset.E, nu=preset.nu, rho=preset.rho), **changes}


def wall_scene(properties, radius, speed, e_n=1.0, mu=0.0, angles=(0.0,), omega0=0.0, speed_is="resultant"):
    """A sphere of `properties` (E, nu, rho) against a rigid plane."""
    return Scene(radius=radius, mu=mu, speed=speed, e_n=(e_n,), angles_deg=tuple(angles), omega0=omega0,
                 wall="rigid", material="chung-ooi", speed_is=speed_is, **properties)


def pair_scene(properties, radius, speed, e_n=1.0, mu=0.0, omega0=0.0):
    """A projectile of `properties` approaching its target at relative normal speed `speed`, without tangential
    velocity."""
    return Scene(radius=radius, mu=mu, speed=speed, e_n=(e_n,), angles_deg=None, v_t=(0.0,), omega0=omega0,
                 material="chung-ooi", **properties)


def cases():
    """The eight tests' impacts, both materials of each."""
    out = []
    for name in ("glass", "limestone"):
        own = material(name)
        out.append(Case(1, name, pair_scene(own, 0.010, 20.0), Sphere(0.010, **own, v_n=10.0)))
    for name, own in (("aluminium alloy", material("aluminium-alloy", nu=0.30, rho=2699.0)),
                      ("magnesium alloy", material("magnesium-alloy"))):
        out.append(Case(2, name, wall_scene(own, 0.1, 0.2)))
    for name in ("alumina", "cast-iron"):
        for e_n in RESTITUTIONS:
            out.append(Case(3, f"{name.replace('-', ' ')}, e_in {e_n:g}",
                            wall_scene(material(name), 2.5e-3, 3.9, e_n=e_n)))
    for name in ("alumina", "aluminium-alloy"):
        out.append(Case(4, name.replace("-", " "), wall_scene(material(name), 2.5e-3, 3.9, e_n=0.98, mu=0.092,
                                                              angles=ANGLES)))
    for name in ("steel", "polyethylene"):
        out.append(Case(5, name, wall_scene(material(name), 1e-5, 5.0, e_n=1.0, mu=0.3, angles=ANGLES,
                                            speed_is="normal")))
    for name in ("aluminium-alloy", "nylon"):
        for angle in ANGLES:
            slip = 0.2 * math.tan(math.radians(angle))
            out.append(Case(6, f"{name.replace('-', ' ')}, tan(angle) {slip / 0.2:.4g}",
                            wall_scene(material(name), 0.1, 0.2, e_n=0.5, mu=0.4, omega0=-slip / 0.1)))
    for name in ("aluminium-alloy", "copper"):
        own = material(name)
        for angle in ANGLES:
            omega = 0.2 * math.tan(math.radians(angle)) / 0.1
            out.append(Case(7, f"{name.replace('-', ' ')}, omega {omega:.4g} rad/s",
                            pair_scene(own, 0.1, 0.4, e_n=0.5, mu=0.4, omega0=omega),
                            Sphere(0.1, **own, v_n=0.2, omega=-omega)))
    for name in ("aluminium-alloy", "nylon"):
        own = material(name)
        heavy = Sphere(TARGET_RADII * 0.1, E=RIGID_TARGET * own["E"], nu=own["nu"], rho=RIGID_TARGET * own["rho"])
        for angle in ANGLES:
            slip = 0.2 * math.tan(math.radians(angle))
            out.append(Case(8, f"{name.replace('-', ' ')}, tan(angle) {slip / 0.2:.4g}",
                            pair_scene(own, 0.1, 0.2, e_n=0.5, mu=0.4, omega0=-slip / 0.1), heavy))
    return out


def published_e(case):
    """The suite's e of a case (not the rebound an impact achieves)."""
    return case.scene.e_n[0]

