"""Spring-less friction with the tangential dashpot's c_t from k_t = k_n (viscous.py)."""
from ...infra.jit import compiled

NAME = "viscous:linear"
SUMMARY = "no spring: F_t = -sign(V_s) min(c_t |V_s|, mu F_n), c_t from a constant k_t"
SLOTS = ("k_t",)
VISCOUS = True


@compiled
def stiffness(k_t, a):
    """k_t: constant (what c_t = g sqrt(k_t) takes)."""
    return k_t
