"""End rule 'no-tension': the normal force never pulls; the contact ends when it returns to 0."""
from ...infra.jit import compiled

NAME = "no-tension"
SUMMARY = "no tension: F_n clipped at 0, the contact ends when the force returns to 0"
SLOTS = ()
PULLS = False


@compiled
def clip(f_n):
    """max(F_n, 0)."""
    return 0.0 if f_n < 0.0 else f_n
