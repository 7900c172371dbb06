"""Stronge's elastic-plastic law [provisional reconstruction]: Hertz to alpha_y, F_y (2 alpha/alpha_y - 1), Hertzian
unloading with R_c (docs/laws.md#normal-laws)."""
import math

from ...infra.jit import compiled
from .hertz_shapes import FOUR_THIRDS, hertz, hertz_slope
from .thornton import Thornton

NAME = "stronge"
SUMMARY = "Hertz to alpha_y, F_y (2 alpha/alpha_y - 1), Hertzian unloading with R_c [provisional reconstruction]"
ADAPTIVE = True
SLOTS = ("E_star", "alpha_y", "f_y")


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
def force(E_star, alpha_y, f_y, radius, alpha, alpha_max):
    """Hertz to alpha_y, F_y (2 alpha/alpha_y - 1), Hertz unloading with R_c (slots E*, alpha_y, F_y)."""
    a_y = math.sqrt(radius * alpha_y)
    if alpha >= alpha_max:
        if alpha <= alpha_y:
            return hertz(E_star, radius, alpha)
        f = f_y * (2.0 * alpha / alpha_y - 1.0)
        return f, a_y * math.sqrt(f / f_y)
    if alpha_max <= alpha_y:
        return hertz(E_star, radius, alpha)
    r_c, dent = unloading(E_star, alpha_y, f_y, radius, alpha_max)
    delta = alpha - dent
    if delta <= 0.0:
        return delta, 0.0
    return hertz(E_star, r_c, delta)


@compiled
def residual(E_star, alpha_y, f_y, radius, alpha_max):
    if alpha_max > alpha_y:
        return unloading(E_star, alpha_y, f_y, radius, alpha_max)[1]
    return 0.0


@compiled
def kink(E_star, alpha_y, f_y):
    """The loading curve bends at alpha_y."""
    return alpha_y


@compiled
def slope(E_star, alpha_y, f_y, radius, alpha, loading, f, a):
    """2 F_y/alpha_y on the plastic line, where a = a_y (F/F_y)^1/2; Hertzian elsewhere."""
    if loading and alpha >= alpha_y:
        plastic = 2.0 * f_y / alpha_y
        return plastic, plastic / (2.0 * f)
    return hertz_slope(E_star, f, a)
