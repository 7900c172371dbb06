"""Hertz F = 4/3 E* R^1/2 alpha^3/2 (paper eq. 1)."""
import math

from ...infra.jit import compiled
from .. import calibration as cal
from ..base import NormalModel, NormalParameters
from .hertz_shapes import hertz, hertz_slope

NAME = "hertz"
SUMMARY = "F = 4/3 E* R^1/2 alpha^3/2 (paper eq. 1)"
ADAPTIVE = True
SLOTS = ("E_star",)


def hertz_peak_overlap(contact, speed):
    """alpha_max of an elastic Hertz impact at V: 2/5 k_h alpha^5/2 = 1/2 m V^2, k_h = 4/3 E* sqrt(R)."""
    k_h = 4.0 / 3.0 * contact.E_star * math.sqrt(contact.radius)
    return (1.25 * contact.mass * speed ** 2 / k_h) ** 0.4


class Hertz(NormalModel):
    """F = 4/3 E* R^1/2 alpha^3/2 (paper eq. 1)."""
    name, kernel, plastic = "hertz", NAME, False

    def parameters(self, contact, e_n, speed):
        stiffness = cal.hertz_equivalent_stiffness(contact.E_star, contact.radius, contact.mass, speed)
        return NormalParameters.named(stiffness, cal.hertz_contact_time(contact.E_star, contact.radius, contact.mass,
                                                                        speed), E_star=contact.E_star)

    def peak(self, contact, e_n, speed):
        """Elastic Hertz bounds damped impacts: alpha_max = (5 m V^2/(4 k_h))^2/5, dF/dalpha = 2 E* sqrt(R alpha)."""
        alpha = hertz_peak_overlap(contact, speed)
        return 2.0 * contact.E_star * math.sqrt(contact.radius * alpha), alpha


@compiled
def force(E_star, radius, alpha, alpha_max):
    """Hertz F = 4/3 E* R^1/2 alpha^3/2, a = sqrt(R alpha)."""
    return hertz(E_star, radius, alpha)


@compiled
def slope(E_star, radius, alpha, loading, f, a):
    return hertz_slope(E_star, f, a)
