"""Thornton (1997) elastoplastic: Hertz to the yield pressure p_y, F_y + pi p_y R (alpha - alpha_y), Hertzian
unloading with the radius R_p (docs/laws.md#normal-laws)."""
import math

from ...infra.jit import compiled
from .. import calibration as cal
from ..base import NormalModel, NormalParameters
from .hertz import Hertz
from .hertz_shapes import FOUR_THIRDS, hertz, hertz_slope

NAME = "thornton"
SUMMARY = "Hertz to alpha_y, F_y + pi p_y R (alpha - alpha_y), Hertzian unloading with R_p (Thornton 1997)"
ADAPTIVE = True
SLOTS = ("E_star", "p_y", "alpha_y", "f_y")


def yield_point(E_star, p_y, radius):
    """alpha_y = (pi p_y/(2E*))^2 R, F_y = pi^3 p_y^3 R^2/(6 E*^2)."""
    return (math.pi * p_y / (2.0 * E_star)) ** 2 * radius, math.pi ** 3 * p_y ** 3 * radius ** 2 / (6.0 * E_star ** 2)


class Thornton(NormalModel):
    """Thornton (1997): Hertz to p_y, F_y + pi p_y R (alpha - alpha_y), Hertz unloading, R_p; p_y gives e_n at V."""
    name, kernel, plastic, law = "thornton", NAME, True, "thornton"

    def yield_pressure(self, contact, e_n, speed):
        """p_y from r = V_y/V solving e(r) = e_n."""
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
        return NormalParameters.named(k_lin, t_c, **self.kernel_values(contact, p_y, alpha_y, f_y))

    def kernel_values(self, contact, p_y, alpha_y, f_y):
        return {"E_star": contact.E_star, "p_y": p_y, "alpha_y": alpha_y, "f_y": f_y}

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


@compiled
def unloading(E_star, p_y, alpha_y, f_y, radius, alpha_max):
    """Thornton's unloading from alpha_max > alpha_y: radius R_p = 4/3 E* a*^3/F* and residual overlap
    alpha_max - a*^2/R_p, a*^2 = R alpha_max, F* = F_y + pi p_y R (alpha_max - alpha_y)."""
    f_star = f_y + math.pi * p_y * radius * (alpha_max - alpha_y)
    a_star_sq = radius * alpha_max
    r_p = FOUR_THIRDS * E_star * a_star_sq * math.sqrt(a_star_sq) / f_star
    return r_p, alpha_max - a_star_sq / r_p


@compiled
def force(E_star, p_y, alpha_y, f_y, radius, alpha, alpha_max):
    """Hertz to alpha_y, F_y + pi p_y R (alpha - alpha_y), Hertz unloading with R_p (slots E*, p_y, alpha_y, F_y)."""
    if alpha >= alpha_max:
        if alpha <= alpha_y:
            return hertz(E_star, radius, alpha)
        return f_y + math.pi * p_y * radius * (alpha - alpha_y), math.sqrt(radius * alpha)
    if alpha_max <= alpha_y:
        return hertz(E_star, radius, alpha)
    r_p, dent = unloading(E_star, p_y, alpha_y, f_y, radius, alpha_max)
    delta = alpha - dent
    if delta <= 0.0:
        return delta, 0.0          # negative: below the residual indentation, the force has ended
    return hertz(E_star, r_p, delta)


@compiled
def residual(E_star, p_y, alpha_y, f_y, radius, alpha_max):
    """The dent alpha_p of the unloading curve (0 below yield)."""
    if alpha_max > alpha_y:
        return unloading(E_star, p_y, alpha_y, f_y, radius, alpha_max)[1]
    return 0.0


@compiled
def kink(E_star, p_y, alpha_y, f_y):
    """The loading curve bends at alpha_y."""
    return alpha_y


@compiled
def slope(E_star, p_y, alpha_y, f_y, radius, alpha, loading, f, a):
    """pi p_y R on the plastic line (a = sqrt(R alpha)), Hertzian elsewhere."""
    if loading and alpha >= alpha_y:
        return math.pi * p_y * radius, 0.5 / alpha
    return hertz_slope(E_star, f, a)
