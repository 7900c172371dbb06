"""Mindlin k_t = 8 G a on the force, the force rescaled by a/a_old while a falls (docs/laws.md#tangential-laws)."""
from ...infra.jit import compiled
from .mindlin import stiffness  # noqa: F401  (its dispatch point: k_t = 8 G a)

NAME = "mindlin:force-rescale"
SUMMARY = "F <- F a/a_old while a falls, then F - 8 G a dd"
SLOTS = ("G",)


@compiled
def spring(G, f_s, dd, a_mid, a, a_old, mu, n_new, n_old, st, scratch, midpoint):
    """F <- F a/a_old while a falls, then F - 8 G a dd."""
    if a < a_old:
        f_s *= a / a_old
    return f_s - 8.0 * G * a * dd
