"""Touch rule 'gap': contact from gap 0."""
from ...infra.jit import compiled

NAME = "gap"
SUMMARY = ("contact from gap 0: a sphere placed touching feels the force of zero overlap before its first step (a "
           "constant normal dashpot's -c_n v_n; the velocity-Verlet wall's tangential dashpot, -c_t V_s)")
SLOTS = ()


@compiled
def contact(alpha):
    """In contact at overlap >= 0."""
    return alpha >= 0.0
