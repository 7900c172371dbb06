"""Normal sub-models: the elastic/plastic part of F_n and its parameters for one contact, target e_n and speed."""
import math
from dataclasses import dataclass

from ..errors import UserError
from ..solver import codes as C
from . import calibration as cal


@dataclass(frozen=True)
class NormalParameters:
    """What the kernel needs (p1..p4), plus k_n for linear tangential springs and a contact-time estimate for dt."""
    values: tuple
    linear_stiffness: float
    contact_time: float


class NormalModel:
    """Shared face of the normal sub-models: the label `harness models` prints."""
    name = ""

    def label(self):
        return self.name


class LinearSpring(NormalModel):
    """F = k_n alpha; k_n = m (pi/t_H)^2, the elastic Hertz contact duration at V ('duration', the paper's), or
    16/15 sqrt(R) E* (15 m V^2/(16 sqrt(R) E*))^1/5, Hertz's peak overlap at V ('peak-overlap', LIGGGHTS hooke's)."""
    name, code, plastic = "linear", C.NORMAL_LINEAR, False
    CALIBRATIONS = ("duration", "peak-overlap")

    def __init__(self, calibration="duration"):
        if calibration not in self.CALIBRATIONS:
            raise UserError(f"the linear spring's calibration is one of {', '.join(self.CALIBRATIONS)}, "
                            f"got {calibration!r}")
        self.calibration = calibration

    def label(self):
        return f"{self.name}:{self.calibration}"

    def stiffness(self, contact, speed):
        if self.calibration == "duration":
            return cal.hertz_duration_stiffness(contact.E_star, contact.radius, contact.mass, speed)
        return cal.hertz_equivalent_stiffness(contact.E_star, contact.radius, contact.mass, speed)

    def parameters(self, contact, e_n, speed):
        k = self.stiffness(contact, speed)
        return NormalParameters((k, 0.0, 0.0, 0.0), k, math.pi * math.sqrt(contact.mass / k))

    def peak(self, contact, e_n, speed):
        """(stiffest dF/dalpha, deepest overlap) of an impact at normal speed <= V: k, V sqrt(m/k)."""
        k = self.parameters(contact, e_n, speed).values[0]
        return k, speed * math.sqrt(contact.mass / k)


class Hertz(NormalModel):
    """F = 4/3 E* R^1/2 alpha^3/2 (paper eq. 1)."""
    name, code, plastic = "hertz", C.NORMAL_HERTZ, False

    def parameters(self, contact, e_n, speed):
        return NormalParameters((contact.E_star, 0.0, 0.0, 0.0),
                                cal.hertz_equivalent_stiffness(contact.E_star, contact.radius, contact.mass, speed),
                                cal.hertz_contact_time(contact.E_star, contact.radius, contact.mass, speed))

    def peak(self, contact, e_n, speed):
        """Elastic Hertz bounds damped impacts: alpha_max = (5 m V^2/(4 k_h))^2/5, dF/dalpha = 2 E* sqrt(R alpha)."""
        alpha = hertz_peak_overlap(contact, speed)
        return 2.0 * contact.E_star * math.sqrt(contact.radius * alpha), alpha


class WaltonBraun(NormalModel):
    """K1 alpha loading, K2 (alpha - alpha0) unloading, K2 = K1/e^2 so that e = sqrt(K1/K2) (MODELS 2.4)."""
    name, code, plastic = "walton-braun", C.NORMAL_WALTON_BRAUN, True

    def loading_stiffness(self, contact, e_n, speed):
        """K1 as for the linear spring: Hertz's peak overlap at the scene speed [prov]."""
        return cal.hertz_equivalent_stiffness(contact.E_star, contact.radius, contact.mass, speed)

    def parameters(self, contact, e_n, speed):
        k1 = self.loading_stiffness(contact, e_n, speed)
        t_c = 0.5 * math.pi * math.sqrt(contact.mass / k1) * (1.0 + e_n)
        return NormalParameters((k1, k1 / e_n ** 2, 0.0, 0.0), k1, t_c)

    def peak(self, contact, e_n, speed):
        """Unloading is stiffest: K2 (p2); loading reaches V sqrt(m/K1)."""
        k1, k2 = self.parameters(contact, e_n, speed).values[:2]
        return max(k1, k2), speed * math.sqrt(contact.mass / k1)


class PartiallyLatchingSpring(WaltonBraun):
    """Provisional PLS: Walton-Braun with K1 = pi p_y R, p_y of Thornton's law for e_n at V (MODELS 2.7) [prov]."""
    name = "partially-latching-spring"

    def loading_stiffness(self, contact, e_n, speed):
        return math.pi * Thornton().yield_pressure(contact, e_n, speed) * contact.radius


def hertz_peak_overlap(contact, speed):
    """alpha_max of an elastic Hertz impact at V: 2/5 k_h alpha^5/2 = 1/2 m V^2, k_h = 4/3 E* sqrt(R)."""
    k_h = 4.0 / 3.0 * contact.E_star * math.sqrt(contact.radius)
    return (1.25 * contact.mass * speed ** 2 / k_h) ** 0.4


def yield_point(E_star, p_y, radius):
    """alpha_y = (pi p_y/(2E*))^2 R, F_y = pi^3 p_y^3 R^2/(6 E*^2) (MODELS 2.6)."""
    return (math.pi * p_y / (2.0 * E_star)) ** 2 * radius, math.pi ** 3 * p_y ** 3 * radius ** 2 / (6.0 * E_star ** 2)


class Thornton(NormalModel):
    """Thornton (1997): Hertz to p_y, F_y + pi p_y R (alpha - alpha_y), Hertz unloading, R_p; p_y gives e_n at V."""
    name, code, plastic, law = "thornton", C.NORMAL_THORNTON, True, "thornton"

    def yield_pressure(self, contact, e_n, speed):
        """p_y from r = V_y/V solving e(r) = e_n (MODELS 2.6)."""
        return cal.yield_pressure(cal.yield_velocity_ratio(e_n, self.law), speed, contact.E_star, contact.rho)

    def plastic_stiffness(self, p_y, alpha_y, f_y, contact):
        return math.pi * p_y * contact.radius

    def parameters(self, contact, e_n, speed):
        p_y = self.yield_pressure(contact, e_n, speed)
        alpha_y, f_y = yield_point(contact.E_star, p_y, contact.radius)
        k_plastic = self.plastic_stiffness(p_y, alpha_y, f_y, contact)
        t_c = max(cal.hertz_contact_time(contact.E_star, contact.radius, contact.mass, speed),
                  0.5 * math.pi * math.sqrt(contact.mass / k_plastic) * (1.0 + e_n))
        k_lin = cal.hertz_equivalent_stiffness(contact.E_star, contact.radius, contact.mass, speed)
        return NormalParameters(self.kernel_values(contact, p_y, alpha_y, f_y), k_lin, t_c)

    def kernel_values(self, contact, p_y, alpha_y, f_y):
        return (contact.E_star, p_y, alpha_y, f_y)

    def peak(self, contact, e_n, speed):
        """Energy balance 1/2 m V^2 = W_y + F_y d + k_p d^2/2 gives F_max = sqrt(F_y^2 + 2 k_p (E0 - W_y)); Hertzian
        unloading returning e^2 E0 has dF/dalpha = 0.6 F_max^2/(e^2 E0) at its start."""
        energy = 0.5 * contact.mass * speed ** 2
        p_y = self.yield_pressure(contact, e_n, speed)
        alpha_y, f_y = yield_point(contact.E_star, p_y, contact.radius)
        if energy <= 0.4 * f_y * alpha_y:
            return Hertz().peak(contact, e_n, speed)
        k_p = self.plastic_stiffness(p_y, alpha_y, f_y, contact)
        f_max = math.sqrt(f_y ** 2 + 2.0 * k_p * (energy - 0.4 * f_y * alpha_y))
        alpha = alpha_y + (f_max - f_y) / k_p
        k_hertz = 2.0 * contact.E_star * math.sqrt(contact.radius * alpha)     # unloading with R unmodified
        return max(k_p, k_hertz, 0.6 * f_max ** 2 / (e_n ** 2 * energy)), alpha


class Stronge(Thornton):
    """Provisional Stronge: Hertz to alpha_y, F_y (2 alpha/alpha_y - 1), Hertz unloading with R_c (MODELS 2.5) [prov]."""
    name, code, law = "stronge", C.NORMAL_STRONGE, "stronge"

    def plastic_stiffness(self, p_y, alpha_y, f_y, contact):
        return 2.0 * f_y / alpha_y

    def kernel_values(self, contact, p_y, alpha_y, f_y):
        return (contact.E_star, alpha_y, f_y, 0.0)


NORMAL_MODELS = {cls.name: cls for cls in (LinearSpring, Hertz, WaltonBraun, PartiallyLatchingSpring, Thornton, Stronge)}


class LudingHysteresis(NormalModel):
    """LIGGGHTS hooke/hysteresis (engine dialect): k1 as the linear spring; d_lim = 2 x the undamped normal
    peak overlap at V and k2max = k1 (2/e^2 - 1), so that at the scene speed the unloading stiffness is K1/e^2."""
    name, code, plastic = "liggghts-hysteresis", C.NORMAL_LUDING, True

    def parameters(self, contact, e_n, speed):
        k1 = cal.hertz_equivalent_stiffness(contact.E_star, contact.radius, contact.mass, speed)
        k2max, d_lim = self.stiffness_and_limit(k1, contact, e_n, speed)
        t_c = 0.5 * math.pi * math.sqrt(contact.mass / k1) * (1.0 + e_n)
        return NormalParameters((k1, k2max, d_lim, 0.0), k1, t_c)

    def peak(self, contact, e_n, speed):
        """k2 grows to k2max (p2) with the overlap; loading reaches V sqrt(m/k1)."""
        k1, k2max = self.parameters(contact, e_n, speed).values[:2]
        return max(k1, k2max), speed * math.sqrt(contact.mass / k1)

    @staticmethod
    def stiffness_and_limit(k1, contact, e_n, speed):
        return k1 * (2.0 / e_n ** 2 - 1.0), 2.0 * speed * math.sqrt(contact.mass / k1)


class ThorntonNing(Thornton):
    """LIGGGHTS thornton_ning (engine dialect): incremental dF = 2E* a dd, a = sqrt(R d) capped at a_y = pi p_y R/(2E*)
    while loading, unloading with R unmodified, no damping; p_y as the paper's Thornton law at the scene speed."""
    name, code = "liggghts-thornton-ning", C.NORMAL_THORNTON_NING

    def kernel_values(self, contact, p_y, alpha_y, f_y):
        return (contact.E_star, math.pi * p_y * contact.radius / (2.0 * contact.E_star), 0.0, 0.0)


class CundallStrackSpring(LinearSpring):
    """YADE FrictPhys against a wall (default geometry, wall radius R): K_n = 2 E R E R/(E R + E R) = E R, with E
    Young's modulus, whatever the impact speed (engine dialect)."""
    name = "yade-cundall-strack"

    def label(self):
        return self.name

    def parameters(self, contact, e_n, speed):
        k = contact.E * contact.radius
        return NormalParameters((k, 0.0, 0.0, 0.0), k, math.pi * math.sqrt(contact.mass / k))


class YadeLuding(LudingHysteresis):
    """YADE LudingMat against a huge fixed sphere (engine dialect): k1 as the linear spring, kp = k1 (2/e^2 - 1),
    DeltPMax = 2x the normal peak overlap, so k2 = K1/e^2 at the scene speed; DeltPNull = PhiF 2R* with
    R* = R_big R/(R_big + R) of the huge sphere, kc = 0, G0 = 0."""
    name, code = "yade-luding", C.NORMAL_LUDING_YADE
    HUGE = 3e5      # radius of the fixed sphere standing in for the wall, in sphere radii (the kernel reproduces
                    # YADE's sphere-sphere geometry with it: overlap round-off, tilting normal, rotated shear force)

    def parameters(self, contact, e_n, speed):
        base = super().parameters(contact, e_n, speed)
        k1, kp, d_p_max, _ = base.values
        return NormalParameters((k1, kp, d_p_max, self.plasticity_depth(k1, kp, d_p_max, contact) * 2.0 *
                                 self.reduced_radius(contact)), base.linear_stiffness, base.contact_time)

    def stand_in_radius(self, contact):
        """Radius of the fixed sphere that plays the wall (the kernel then uses YADE's sphere-sphere geometry)."""
        return self.HUGE * contact.radius

    def reduced_radius(self, contact):
        big = self.stand_in_radius(contact)
        return big * contact.radius / (big + contact.radius)

    def plasticity_depth(self, k1, kp, d_p_max, contact):
        """PhiF from DeltPMax = kp/(kp - k1) PhiF 2R* (YADE's equation (7) of Luding 2008)."""
        return d_p_max * (kp - k1) / (kp * 2.0 * self.reduced_radius(contact))


ENGINE_NORMAL_MODELS = {cls.name: cls for cls in (LudingHysteresis, ThorntonNing, CundallStrackSpring, YadeLuding)}
