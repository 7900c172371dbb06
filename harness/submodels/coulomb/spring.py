"""Coulomb rule 'spring': the spring capped at mu |F_n|; the tangential dashpot added only below the cap."""
import math

from ...infra.jit import compiled
from . import clip

NAME = "spring"
SUMMARY = "the spring capped at mu |F_n|; the tangential dashpot added only below the cap, the sum not clipped"
SLOTS = ()
BRIEF = "tangential dashpot unclipped"


@compiled
def cap(f_s, damping, k_t, slip, limit):
    """A spring beyond mu |F_n| is cut to it and is the whole force; below it, F_s - c_t V_s."""
    if abs(f_s) > limit:
        f_s = clip(f_s, limit)
        return f_s, f_s, True
    if damping == 0.0:
        return f_s, f_s, False
    return f_s - damping * math.sqrt(k_t) * slip, f_s, False
