"""Stronge's elastic-plastic law [provisional reconstruction]: Hertz to alpha_y, F_y (2 alpha/alpha_y - 1), Hertzian
unloading with R_c (docs/laws.md#normal-laws)."""
import math

from ...jit import compiled
from .hertz_shapes import FOUR_THIRDS, hertz, hertz_slope
from .thornton import Thornton

NAME = "stronge"
ADAPTIVE = True
SLOTS = ("E_star", "alpha_y", "f_y")         # kernel slots p1..


class Stronge(Thornton):
    """Provisional Stronge: Hertz to alpha_y, F_y (2 alpha/alpha_y - 1), Hertz unloading with R_c [provisional]."""
    name, kernel, law = "stronge", NAME, "stronge"

    def plastic_stiffness(self, p_y, alpha_y, f_y, contact):
        return 2.0 * f_y / alpha_y

    def kernel_values(self, contact, p_y, alpha_y, f_y):
        return {"E_star": contact.E_star, "alpha_y": alpha_y, "f_y": f_y}


@compiled
def unloading(E_star, alpha_y, f_y, radius, alpha_max):
    """Stronge's unloading from alpha_max > alpha_y: radius R_c = 4/3 E* a_c^3/F_c and residual overlap
    alpha_max - a_c^2/R_c, F_c = F_y (2 alpha_max/alpha_y - 1), a_c = a_y (F_c/F_y)^1/2."""
    f_c = f_y * (2.0 * alpha_max / alpha_y - 1.0)
    a_c_sq = radius * alpha_y * f_c / f_y
    r_c = FOUR_THIRDS * E_star * a_c_sq * math.sqrt(a_c_sq) / f_c
    return r_c, alpha_max - a_c_sq / r_c


@compiled
def force(p1, p2, p3, p4, radius, alpha, alpha_max):
    """Hertz to alpha_y, F_y (2 alpha/alpha_y - 1), Hertz unloading with R_c (slots E*, alpha_y, F_y)."""
    a_y = math.sqrt(radius * p2)
    if alpha >= alpha_max:
        if alpha <= p2:
            return hertz(p1, radius, alpha)
        f = p3 * (2.0 * alpha / p2 - 1.0)
        return f, a_y * math.sqrt(f / p3)
    if alpha_max <= p2:
        return hertz(p1, radius, alpha)
    r_c, dent = unloading(p1, p2, p3, radius, alpha_max)
    delta = alpha - dent
    if delta <= 0.0:
        return delta, 0.0
    return hertz(p1, r_c, delta)


@compiled
def residual(p1, p2, p3, p4, radius, alpha_max):
    if alpha_max > p2:
        return unloading(p1, p2, p3, radius, alpha_max)[1]
    return 0.0


@compiled
def kink(p1, p2, p3, p4):
    """The loading curve bends at alpha_y."""
    return p2


@compiled
def slope(p1, p2, p3, p4, radius, alpha, loading, f, a):
    """2 F_y/alpha_y on the plastic line, where a = a_y (F/F_y)^1/2; Hertzian elsewhere."""
    if loading and alpha >= p2:
        plastic = 2.0 * p3 / p2
        return plastic, plastic / (2.0 * f)
    return hertz_slope(p1, f, a)
