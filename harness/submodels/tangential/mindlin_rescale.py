"""Mindlin k_t = 8 G* a with the paper's eq. 18b: the stored force rescaled by a/a_old on unloading
(docs/laws.md#tangential-laws)."""
import math

from ...infra.jit import compiled
from .mindlin import stiffness  # noqa: F401  (its dispatch point: k_t = 8 G a)

NAME = "mindlin:rescale"
SUMMARY = "paper eq. 18b: F_s - 8 G a dd, F_s rescaled by a/a_old on unloading"
SLOTS = ("G",)
ADAPTIVE = True
LOG_RATE = 1                # F_s a'/a in the ODE while a shrinks (eq. 18b)


@compiled
def spring(G, f_s, dd, a_mid, a, a_old, mu, n_new, n_old, st, scratch, midpoint):
    """Paper eq. 18b: on unloading (a < a_old) F_s <- F_s a/a_old, split around the increment -8 G a dd."""
    if a >= a_old:
        return f_s - 8.0 * G * a_mid * dd
    half = math.sqrt(a / a_old)
    return (f_s * half - 8.0 * G * a_mid * dd) * half
