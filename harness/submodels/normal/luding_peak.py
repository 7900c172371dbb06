"""Luding's hysteretic spring as a function of the overlap and its peak, without adhesion: the unloading stiffness
grows with the peak up to a limit overlap (Luding 2008)."""
import math

from ...infra.jit import compiled
from .. import calibration as cal
from ..base import NormalModel, NormalParameters

NAME = "luding-peak"
SUMMARY = "k1 alpha loading, unloading stiffness growing with the peak overlap up to d_lim (Luding 2008)"
ADAPTIVE = False
SLOTS = ("k1", "k2_max", "d_lim")


class LudingPeak(NormalModel):
    """k1 as the linear spring; d_lim = 2 x the undamped normal peak overlap at V and
    k2max = k1 (2/e^2 - 1), so that at the scene speed the unloading stiffness is K1/e^2."""
    name, kernel, plastic = "luding-peak", NAME, True

    def parameters(self, contact, e_n, speed):
        k1 = cal.hertz_equivalent_stiffness(contact.E_star, contact.radius, contact.mass, speed)
        k2max, d_lim = self.stiffness_and_limit(k1, contact, e_n, speed)
        t_c = 0.5 * math.pi * math.sqrt(contact.mass / k1) * (1.0 + e_n)
        return NormalParameters.named(k1, t_c, k1=k1, k2_max=k2max, d_lim=d_lim)

    def peak(self, contact, e_n, speed):
        """k2 grows to k2max with the overlap; loading reaches V sqrt(m/k1)."""
        k1, k2max = self.parameters(contact, e_n, speed).values[:2]
        return max(k1, k2max), speed * math.sqrt(contact.mass / k1)

    @staticmethod
    def stiffness_and_limit(k1, contact, e_n, speed):
        return k1 * (2.0 / e_n ** 2 - 1.0), 2.0 * speed * math.sqrt(contact.mass / k1)


@compiled
def force(k1, k2_max, d_lim, radius, alpha, alpha_max):
    """min(k1 d, k2 (d - d_max) + k1 d_max), k2 = k1 + (k2max - k1) d_max/d_lim; beyond d_lim the line
    k2max (d - d_lim) + k1 d_lim."""
    d_max = alpha if alpha > alpha_max else alpha_max
    if d_max >= d_lim:
        return k2_max * (alpha - d_lim) + k1 * d_lim, math.sqrt(radius * alpha)
    k2 = k1 + (k2_max - k1) * d_max / d_lim
    f = k2 * (alpha - d_max) + k1 * d_max
    return (k1 * alpha if f >= k1 * alpha else f), math.sqrt(radius * alpha)


@compiled
def kink(k1, k2_max, d_lim):
    """The loading curve becomes a straight line at d_lim."""
    return d_lim
