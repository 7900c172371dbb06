"""Spring-less friction with the tangential dashpot's c_t from k_t = 8 G* a (viscous.py)."""
from ...infra.jit import compiled

NAME = "viscous:mindlin"
SUMMARY = "no spring: F_t = -sign(V_s) min(c_t |V_s|, mu F_n), c_t from k_t = 8 G a"
SLOTS = ("G",)
VISCOUS = True


@compiled
def stiffness(G, a):
    """k_t = 8 G a (what c_t = g sqrt(k_t) takes)."""
    return 8.0 * G * a
