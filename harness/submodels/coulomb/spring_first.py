"""Coulomb rule 'spring-first' (the paper's): the spring tested alone against mu |F_n|, then spring plus dashpot
clipped."""
import math

from ...infra.jit import compiled
from . import clip

NAME = "spring-first"
SUMMARY = ("the spring tested alone: beyond mu |F_n| it is capped and is the whole force; below it the tangential "
           "dashpot is added and the sum clipped to mu |F_n| (the paper's; its scheme's dashpot option 'total' holds "
           "the spring within the cone first)")
SLOTS = ()
BRIEF = "spring first, then spring + dashpot clipped"


@compiled
def cap(f_s, damping, k_t, slip, limit):
    """A spring beyond mu |F_n| is cut to it and is the whole force; below it, F_s - c_t V_s clipped to mu |F_n|."""
    if abs(f_s) > limit:
        f_s = clip(f_s, limit)
        return f_s, f_s, True
    if damping == 0.0:
        return f_s, f_s, False
    return clip(f_s - damping * math.sqrt(k_t) * slip, limit), f_s, False


@compiled
def first_touch(f_d, limit):
    """At first touch the spring is empty: the dashpot is clipped to mu |F_n|."""
    return clip(f_d, limit)
