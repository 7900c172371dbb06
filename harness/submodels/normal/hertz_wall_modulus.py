"""Hertz against a wall of the sphere's own material: F = 4/3 E_w R^1/2 alpha^3/2 with E_w = E/(2(1 - nu)), a wall's
mixing of the sphere's E and nu with themselves, where a pair of spheres gets E* = E/(2(1 - nu^2))."""
from .. import calibration as cal
from ..base import NormalParameters
from .hertz import Hertz


def wall_modulus(contact):
    """E_w = E/(2(1 - nu)): the sphere's E and nu mixed with themselves as a wall's."""
    return contact.E / (2.0 * (1.0 - contact.nu))


class HertzWallModulus(Hertz):
    """F = 4/3 E_w R^1/2 alpha^3/2, E_w = E/(2(1 - nu)) ; the Hertz kernel."""
    name = "hertz-wall-modulus"

    def parameters(self, contact, e_n, speed):
        e_w = wall_modulus(contact)
        return NormalParameters.named(cal.hertz_equivalent_stiffness(e_w, contact.radius, contact.mass, speed),
                                      cal.hertz_contact_time(e_w, contact.radius, contact.mass, speed), E_star=e_w)

    def peak(self, contact, e_n, speed):
        """Elastic Hertz with E_w: alpha_max = (5 m V^2/(4 k_h))^2/5, dF/dalpha = 2 E_w sqrt(R alpha)."""
        e_w = wall_modulus(contact)
        k_h = 4.0 / 3.0 * e_w * contact.radius ** 0.5
        alpha = (1.25 * contact.mass * speed ** 2 / k_h) ** 0.4
        return 2.0 * e_w * (contact.radius * alpha) ** 0.5, alpha
