"""Touch rule 'overlap': contact from overlap > 0."""
from ...infra.jit import compiled

NAME = "overlap"
SUMMARY = "contact from overlap > 0: no force before the first step; the first kick is force-free"
SLOTS = ()


@compiled
def contact(alpha):
    """In contact at overlap > 0 only."""
    return alpha > 0.0
