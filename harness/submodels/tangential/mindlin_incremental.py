"""Mindlin k_t = 8 G* a, incremental: the stored force not reduced as a falls (docs/laws.md#tangential-laws)."""
from ...infra.jit import compiled
from .mindlin import stiffness  # noqa: F401  (its dispatch point: k_t = 8 G a)

NAME = "mindlin:incremental"
SUMMARY = "F_s - 8 G a dd, not reduced as a falls"
SLOTS = ("G",)
ADAPTIVE = True


@compiled
def spring(G, f_s, dd, a_mid, a, a_old, mu, n_new, n_old, st, scratch, midpoint):
    """F_s - 8 G a dd, not reduced as a falls."""
    return f_s - stiffness(G, a_mid) * dd
