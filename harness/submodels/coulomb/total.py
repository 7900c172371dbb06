"""Coulomb rule 'total': spring and tangential dashpot capped together at mu |F_n|."""
import math

from ...infra.jit import compiled
from . import clip

NAME = "total"
SUMMARY = "spring plus dashpot capped together at mu |F_n|; a capped total leaves the spring F_t + c_t V_s"
SLOTS = ()
BRIEF = "spring + dashpot clipped together"


@compiled
def cap(f_s, damping, k_t, slip, limit):
    """F_s - c_t V_s capped at mu |F_n|; when capped, the spring is set to what the capped total leaves it,
    F_t + c_t V_s."""
    c_t = damping * math.sqrt(k_t) if damping != 0.0 else 0.0
    total = f_s - c_t * slip
    if abs(total) <= limit:
        return total, f_s, False
    f_t = clip(total, limit)
    return f_t, f_t + c_t * slip, True


@compiled
def first_touch(f_d, limit):
    """At first touch the spring is empty: a dashpot force beyond mu |F_n| is dropped, not capped."""
    return 0.0 if abs(f_d) > limit else f_d
