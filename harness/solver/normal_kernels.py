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
def thornton_unloading(E_star, p_y, alpha_y, f_y, radius, alpha_max):
    """Thornton's unloading from alpha_max > alpha_y: radius R_p = 4/3 E* a*^3/F* and residual overlap
    alpha_max - a*^2/R_p, a*^2 = R alpha_max, F* = F_y + pi p_y R (alpha_max - alpha_y)."""
    f_star = f_y + math.pi * p_y * radius * (alpha_max - alpha_y)
    a_star_sq = radius * alpha_max
    r_p = FOUR_THIRDS * E_star * a_star_sq * math.sqrt(a_star_sq) / f_star
    return r_p, alpha_max - a_star_sq / r_p


@njit(cache=True)
def thornton(E_star, p_y, alpha_y, f_y, radius, alpha, alpha_max):
    """Thornton (1997): Hertz to alpha_y, F_y + pi p_y R (alpha - alpha_y), Hertz unloading with R_p (MODELS 2.6)."""
    if alpha >= alpha_max:
        if alpha <= alpha_y:
            return hertz(E_star, radius, alpha)
        return f_y + math.pi * p_y * radius * (alpha - alpha_y), math.sqrt(radius * alpha)
    if alpha_max <= alpha_y:
        return hertz(E_star, radius, alpha)
    r_p, dent = thornton_unloading(E_star, p_y, alpha_y, f_y, radius, alpha_max)
    delta = alpha - dent
    if delta <= 0.0:
        return delta, 0.0          # negative: below the residual indentation, the force has ended
    return hertz(E_star, r_p, delta)


@njit(cache=True)
def stronge_unloading(E_star, alpha_y, f_y, radius, alpha_max):
    """Stronge's unloading from alpha_max > alpha_y: radius R_c = 4/3 E* a_c^3/F_c and residual overlap
    alpha_max - a_c^2/R_c, F_c = F_y (2 alpha_max/alpha_y - 1), a_c = a_y (F_c/F_y)^1/2 (MODELS 2.5)."""
    f_c = f_y * (2.0 * alpha_max / alpha_y - 1.0)
    a_c_sq = radius * alpha_y * f_c / f_y
    r_c = FOUR_THIRDS * E_star * a_c_sq * math.sqrt(a_c_sq) / f_c
    return r_c, alpha_max - a_c_sq / r_c


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
    r_c, dent = stronge_unloading(E_star, alpha_y, f_y, radius, alpha_max)
    delta = alpha - dent
    if delta <= 0.0:
        return delta, 0.0
    return hertz(E_star, r_c, delta)


@njit(cache=True)
def luding(k1, k2max, d_lim, radius, alpha, alpha_max):
    """LIGGGHTS hooke/hysteresis without adhesion: min(k1 d, k2 (d - d_max) + k1 d_max), k2 = k1 + (k2max - k1)
    d_max/d_lim; beyond d_lim the line k2max (d - d_lim) + k1 d_lim (read in LIGGGHTS 3.8.0, reproduced exactly)."""
    d_max = alpha if alpha > alpha_max else alpha_max
    if d_max >= d_lim:
        return k2max * (alpha - d_lim) + k1 * d_lim, math.sqrt(radius * alpha)
    k2 = k1 + (k2max - k1) * d_max / d_lim
    f = k2 * (alpha - d_max) + k1 * d_max
    return (k1 * alpha if f >= k1 * alpha else f), math.sqrt(radius * alpha)


@njit(cache=True)
def thornton_ning(E_star, a_y, radius, alpha, alpha_old, f_old, alpha_max, f_max, yielding, detached_at):
    """LIGGGHTS thornton_ning, surfaceEnergy 0: F += 2E* a (d - d_old) with a = sqrt(R d) at the new overlap,
    a = a_y once yielded while loading; unloading with R unchanged; F < 0 -> 0 and detached until d returns.
    Returns (F, a, yielding, detached_at, f_max); detached_at < 0 means attached."""
    if detached_at >= 0.0:
        if alpha < detached_at:
            return 0.0, math.sqrt(radius * alpha), yielding, detached_at, f_max
        alpha_old, f_old, detached_at = detached_at, 0.0, -1.0
    dn = alpha - alpha_old
    a = math.sqrt(radius * alpha)
    if alpha >= alpha_max:
        if a >= a_y:
            yielding = 1.0
        f = f_old + 2.0 * E_star * (a_y if yielding > 0.0 else a) * dn
    elif yielding > 0.0:
        r_p = radius * f_max / f_max
        f = f_old + 2.0 * E_star * math.sqrt(r_p * alpha) * dn
    else:
        f = f_old + 2.0 * E_star * a * dn
    if f < 0.0:
        f, detached_at = 0.0, alpha
    return f, a, yielding, detached_at, (f if f > f_max else f_max)


@njit(cache=True)
def luding_yade(k1, kp, delt_p_max, delt_p_null, delt, delt_max, delt_null, delt_prev):
    """YADE Law2_ScGeom_LudingPhys_Basic with kc = 0 (read in LudingPM.cpp): k2 from the previous largest overlap,
    k2 = k1 + (kp - k1) DeltMax/DeltPMax (<= kp); a new maximum moves DeltNull = min((1 - k1/k2) DeltMax,
    DeltPNull); force k1 d while k2 (d - DeltNull) >= k1 d (k2 line beyond DeltPMax), else k2 (d - DeltNull) down
    to 0, where an unloading contact resets DeltMax = d k2/(k2 - k1). Returns (F, DeltMax, DeltNull)."""
    k2 = kp if delt_max / delt_p_max >= 1.0 else k1 + (kp - k1) * delt_max / delt_p_max
    if k2 > kp:
        k2 = kp
    if delt > delt_max:
        delt_max = delt
        delt_null = min((1.0 - k1 / k2) * delt_max, delt_p_null)
    k2_delt = k2 * (delt - delt_null)
    if k2_delt >= k1 * delt:
        force = k1 * delt if delt < delt_p_max else k2_delt
    elif k2_delt > 0.0:
        force = k2_delt
    elif delt - delt_prev < 0.0:
        force = 0.0
        delt_max = delt * k2 / (k2 - k1)
        delt_null = min((1.0 - k1 / k2) * delt_max, delt_p_null)
    else:
        force = k2_delt
    return force, delt_max, delt_null


@njit(cache=True)
def residual_overlap(code, p1, p2, p3, p4, radius, alpha_max):
    """Overlap at which the unloading force from alpha_max returns to 0 (0 for the elastic laws)."""
    if code == C.NORMAL_WALTON_BRAUN:
        return alpha_max * (1.0 - p1 / p2)
    if code == C.NORMAL_THORNTON and alpha_max > p3:
        return thornton_unloading(p1, p2, p3, p4, radius, alpha_max)[1]
    if code == C.NORMAL_STRONGE and alpha_max > p2:
        return stronge_unloading(p1, p2, p3, radius, alpha_max)[1]
    return 0.0


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
    if code == C.NORMAL_LUDING:
        return luding(p1, p2, p3, radius, alpha, alpha_max)
    return stronge(p1, p2, p3, radius, alpha, alpha_max)
