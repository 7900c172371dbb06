"""Walton & Braun (1986) latching spring: K1 alpha loading, K2 (alpha - alpha0) unloading, K2 = K1/e^2 so that
e = sqrt(K1/K2) (docs/laws.md#normal-laws)."""
import math

from ...infra.jit import compiled
from .. import calibration as cal
from ..base import NormalModel, NormalParameters

NAME = "walton-braun"
SUMMARY = "K1 alpha loading, K2 (alpha - alpha0) unloading, alpha0 = alpha_max (1 - K1/K2) (Walton & Braun 1986)"
ADAPTIVE = True
SLOTS = ("k1", "k2")


class WaltonBraun(NormalModel):
    """K1 alpha loading, K2 (alpha - alpha0) unloading, K2 = K1/e^2 so that e = sqrt(K1/K2)."""
    name, kernel, plastic = "walton-braun", NAME, True

    def loading_stiffness(self, contact, e_n, speed):
        """K1 as for the linear spring with Hertz's peak overlap at the scene speed [provisional]."""
        return cal.hertz_equivalent_stiffness(contact.E_star, contact.radius, contact.mass, speed)

    def parameters(self, contact, e_n, speed):
        k1 = self.loading_stiffness(contact, e_n, speed)
        t_c = 0.5 * math.pi * math.sqrt(contact.mass / k1) * (1.0 + e_n)
        return NormalParameters.named(k1, t_c, k1=k1, k2=k1 / e_n ** 2)

    def peak(self, contact, e_n, speed):
        """Unloading is stiffest: K2; loading reaches V sqrt(m/K1)."""
        k1, k2 = self.parameters(contact, e_n, speed).values[:2]
        return max(k1, k2), speed * math.sqrt(contact.mass / k1)


@compiled
def force(k1, k2, radius, alpha, alpha_max):
    """Loading K1 alpha; unloading K2 (alpha - alpha0), alpha0 = alpha_max (1 - K1/K2) (Walton & Braun 1986)."""
    if alpha >= alpha_max:
        return k1 * alpha, math.sqrt(radius * alpha)
    alpha0 = alpha_max * (1.0 - k1 / k2)
    return k2 * (alpha - alpha0), math.sqrt(radius * alpha)


@compiled
def residual(k1, k2, radius, alpha_max):
    """The dent alpha_max (1 - K1/K2) where the unloading force returns to 0."""
    return alpha_max * (1.0 - k1 / k2)


@compiled
def slope(k1, k2, radius, alpha, loading, f, a):
    """K1 loading, K2 unloading; a = sqrt(R alpha)."""
    return (k1 if loading else k2), 0.5 / alpha
