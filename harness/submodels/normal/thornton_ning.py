"""Thornton & Ning's incremental elastoplastic normal law without adhesion: dF = 2E* a dd (Thornton & Ning 1998)."""
import math

from ...infra.jit import compiled
from .thornton import Thornton

NAME = "thornton-ning"
SUMMARY = "incremental dF = 2E* a dd, plastic beyond a_y (Thornton & Ning 1998)"
ADAPTIVE = False
SLOTS = ("E_star", "a_y")
F_MAX, YIELDED, DETACHED_AT = 0, 1, 2       # its history: peak force, yielded (1), overlap where it detached (< 0: no)
HISTORY_RESET = (0.0, 0.0, -1.0)            # history at first touch and after the contact ends


class ThorntonNing(Thornton):
    """Incremental dF = 2E* a dd, a = sqrt(R d) capped at a_y = pi p_y R/(2E*) while
    loading, unloading with R unmodified, no damping; p_y as the paper's Thornton law at the scene speed."""
    name, kernel = "thornton-ning", NAME

    def kernel_values(self, contact, p_y, alpha_y, f_y):
        return {"E_star": contact.E_star, "a_y": math.pi * p_y * contact.radius / (2.0 * contact.E_star)}


@compiled
def increment(E_star, a_y, radius, alpha, alpha_old, f_old, alpha_max, f_max, yielding, detached_at):
    """F += 2E* a (d - d_old) with a = sqrt(R d) at the new overlap, a = a_y once yielded while loading; unloading
    with R unchanged; F < 0 -> 0 and detached until d returns. Returns (F, a, yielding, detached_at, f_max)."""
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


@compiled
def step(E_star, a_y, radius, alpha, alpha_old, f_old, alpha_max, history, new_history):
    """One step of the incremental law: (F, a) and the history after it (new_history)."""
    f, a, new_history[YIELDED], new_history[DETACHED_AT], new_history[F_MAX] = increment(
        E_star, a_y, radius, alpha, alpha_old, f_old, alpha_max, history[F_MAX], history[YIELDED], history[DETACHED_AT])
    return f, a
