"""Coulomb rule 'total-cases': spring F_s and dashpot F_d = -c_t V_s capped together at mu |F_n| by four cases."""
import math

from ...infra.jit import compiled
from . import clip

NAME = "total-cases"
SUMMARY = ("spring plus dashpot capped together at mu |F_n|; a spring beyond mu |F_n| on the total's side is cut to "
           "it (the dashpot dropped), else the dashpot alone is shortened and the spring kept")
SLOTS = ()
BRIEF = "spring + dashpot clipped by four cases"


@compiled
def cap(f_s, damping, k_t, slip, limit):
    """On one side, a spring beyond the cap is cut to it and the dashpot dropped, else the dashpot is shortened to
    the cap's rest; opposed, a dashpot at least as strong as the spring is scaled to mu |F_n| + |F_s|, else the
    spring is cut to the cap and the dashpot dropped."""
    c_t = damping * math.sqrt(k_t) if damping != 0.0 else 0.0
    f_d = -c_t * slip
    if abs(f_s + f_d) <= limit:
        return f_s + f_d, f_s, False
    if (f_s * f_d >= 0.0 and abs(f_s) > limit) or (f_s * f_d < 0.0 and abs(f_d) < abs(f_s)):
        f_s = f_s * (limit / abs(f_s))
        return f_s, f_s, True
    if f_s * f_d >= 0.0:
        return f_s + f_d * ((limit - abs(f_s)) / abs(f_d)), f_s, False
    return f_s + f_d * ((limit + abs(f_s)) / abs(f_d)), f_s, False


@compiled
def first_touch(f_d, limit):
    """At first touch the spring is empty: the dashpot is shortened to mu |F_n|."""
    return clip(f_d, limit)
