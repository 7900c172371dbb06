"""Mindlin k_t = 8 G a on the total displacement xi, xi rescaled by a/a_old while a falls
(docs/laws.md#tangential-laws)."""
from ...infra.jit import compiled
from .mindlin import stiffness  # noqa: F401  (its dispatch point: k_t = 8 G a)
from .mindlin_total import after_cap  # noqa: F401  (xi = -F/k_t after the cap)
from .state import T_AUX1

NAME = "mindlin:total-rescale"
SUMMARY = "F = -8 G a xi, xi rescaled by a/a_old while a falls"
SLOTS = ("G",)


@compiled
def spring(G, f_s, dd, a_mid, a, a_old, mu, n_new, n_old, st, scratch, midpoint):
    """xi <- xi a/a_old while a falls, then xi + dd; F = -8 G a xi."""
    if a < a_old:
        st[T_AUX1] *= a / a_old
    st[T_AUX1] += dd
    return -8.0 * G * a * st[T_AUX1]
