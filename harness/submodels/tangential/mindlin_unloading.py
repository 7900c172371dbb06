"""Mindlin k_t = 8 G* a with the stored force rescaled on unloading only: F_s sqrt(delta/delta_old) - k_t dd while
the overlap falls, F_s - k_t dd otherwise (docs/laws.md#tangential-laws)."""
from ...infra.jit import compiled
from ..base import TangentialModel
from .mindlin import stiffness  # noqa: F401  (its dispatch point: k_t = 8 G* a)

NAME = "mindlin-unloading"
SUMMARY = "F_s a/a_old - 8 G a dd while a falls, F_s - 8 G a dd otherwise"
SLOTS = ("G",)


class MindlinUnloading(TangentialModel):
    """k_t = 8 G* a, the stored force times a/a_old = sqrt(delta/delta_old) where the overlap falls, the increment
    at the current k_t (paper eq. 18b's rescale without its loading half)."""
    name = kernel = NAME

    def parameter(self, contact, k_n):
        return contact.G_star


@compiled
def spring(G, f_s, dd, a_mid, a, a_old, mu, n_new, n_old, st, scratch, midpoint):
    """F_s a/a_old - 8 G* a dd while a falls (a/a_old = sqrt(delta/delta_old)), F_s - 8 G* a dd otherwise."""
    if a < a_old:
        return f_s * (a / a_old) - 8.0 * G * a * dd
    return f_s - 8.0 * G * a * dd
