"""End rule 'tension': the normal force may pull; the contact ends when the overlap returns to 0."""
from ...infra.jit import compiled

NAME = "tension"
SUMMARY = "tension allowed: the contact ends when the overlap returns to 0"
SLOTS = ()
PULLS = True               # the normal force may pull


@compiled
def clip(f_n):
    """F_n as it is."""
    return f_n
