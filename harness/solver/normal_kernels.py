"""Compiled normal force laws F_el(alpha, alpha_max) and contact radius a, one function per model (MODELS 2)."""
import math

from numba import njit

from . import codes as C

FOUR_THIRDS = 4.0 / 3.0


@njit(cache=True)
def hertz(E_star, radius, alpha):
    """Hertz F = 4/3 E* R^1/2 alpha^3/2, a = sqrt(R alpha) (paper eqs. 1-2)."""
    a = math.sqrt(radius * alpha)
    return FOUR_THIRDS * E_star * a * alpha, a


@njit(cache=True)
def walton_braun(k1, k2, radius, alpha, alpha_max):
    """Loading K1 alpha; unloading K2 (alpha - alpha0), alpha0 = alpha_max (1 - K1/K2) (Walton & Braun 1986)."""
    if alpha >= alpha_max:
        return k1 * alpha, math.sqrt(radius * alpha)
    alpha0 = alpha_max * (1.0 - k1 / k2)
    return k2 * (alpha - alpha0), math.sqrt(radius * alpha)


@njit(cache=True)
def thornton(E_star, p_y, alpha_y, f_y, radius, alpha, alpha_max):
    """Thornton (1997): Hertz to alpha_y, F_y + pi p_y R (alpha - alpha_y), Hertz unloading with R_p (MODELS 2.6)."""
    if alpha >= alpha_max:
        if alpha <= alpha_y:
            return hertz(E_star, radius, alpha)
        return f_y + math.pi * p_y * radius * (alpha - alpha_y), math.sqrt(radius * alpha)
    if alpha_max <= alpha_y:
        return hertz(E_star, radius, alpha)
    f_star = f_y + math.pi * p_y * radius * (alpha_max - alpha_y)
    a_star_sq = radius * alpha_max
    r_p = FOUR_THIRDS * E_star * a_star_sq * math.sqrt(a_star_sq) / f_star
    delta = alpha - (alpha_max - a_star_sq / r_p)
    if delta <= 0.0:
        return delta, 0.0          # negative: below the residual indentation, the force has ended
    return hertz(E_star, r_p, delta)


@njit(cache=True)
def stronge(E_star, alpha_y, f_y, radius, alpha, alpha_max):
    """Provisional Stronge: Hertz to alpha_y, F_y (2 alpha/alpha_y - 1), Hertz unloading with R_c (MODELS 2.5)."""
    a_y = math.sqrt(radius * alpha_y)
    if alpha >= alpha_max:
        if alpha <= alpha_y:
            return hertz(E_star, radius, alpha)
        f = f_y * (2.0 * alpha / alpha_y - 1.0)
        return f, a_y * math.sqrt(f / f_y)
    if alpha_max <= alpha_y:
        return hertz(E_star, radius, alpha)
    f_c = f_y * (2.0 * alpha_max / alpha_y - 1.0)
    a_c = a_y * math.sqrt(f_c / f_y)
    r_c = FOUR_THIRDS * E_star * a_c * a_c * a_c / f_c
    delta = alpha - (alpha_max - a_c * a_c / r_c)
    if delta <= 0.0:
        return delta, 0.0
    return hertz(E_star, r_c, delta)


@njit(cache=True)
def normal_elastic(code, p1, p2, p3, p4, radius, alpha, alpha_max):
    """Dispatch to the normal model selected by `code`; returns (F_el, contact radius a)."""
    if code == C.NORMAL_LINEAR:
        return p1 * alpha, math.sqrt(radius * alpha)
    if code == C.NORMAL_HERTZ:
        return hertz(p1, radius, alpha)
    if code == C.NORMAL_WALTON_BRAUN:
        return walton_braun(p1, p2, radius, alpha, alpha_max)
    if code == C.NORMAL_THORNTON:
        return thornton(p1, p2, p3, p4, radius, alpha, alpha_max)
    return stronge(p1, p2, p3, radius, alpha, alpha_max)
