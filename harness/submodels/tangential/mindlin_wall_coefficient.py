"""Mindlin springs with the wall coefficient of the sphere's own material: k_t = K a with K = E/4 (2 - nu)
(1 + nu), on the total displacement xi ('total', F = -k_t xi) or on the force ('force', F - k_t dd), each also
rescaled by a/a_old while a falls ('total-rescale', 'force-rescale')."""
from ...jit import compiled
from .mindlin import Mindlin, stiffness, total_after_cap  # noqa: F401  (the dispatch points its kernels share)
from .state import T_AUX1

FORMS = {"total": "mindlin:total", "force": "mindlin:incremental", "total-rescale": "mindlin:total-rescale",
         "force-rescale": "mindlin:force-rescale"}


def wall_coefficient(contact):
    """K = E/4 (2 - nu)(1 + nu): k_t/a against a wall of the sphere's own E and nu."""
    return contact.E / 4.0 * (2.0 - contact.nu) * (1.0 + contact.nu)


class MindlinWallCoefficient(Mindlin):
    """k_t = K a, K = E/4 (2 - nu)(1 + nu), on the total displacement or the force, rescaled or not."""
    name = "mindlin-wall-coefficient"
    FORMS, DEFAULT_FORM = FORMS, "total"

    def parameter(self, contact, k_n):
        return wall_coefficient(contact) / 8.0          # the kernel's k_t = 8 p1 a


@compiled
def total_rescale(f_s, dd, a_mid, a, a_old, p1, mu, n_new, n_old, st, scratch, midpoint):
    """xi <- xi a/a_old while a falls, then xi + dd; F = -8 p1 a xi."""
    if a < a_old:
        st[T_AUX1] *= a / a_old
    st[T_AUX1] += dd
    return -8.0 * p1 * a * st[T_AUX1]


@compiled
def force_rescale(f_s, dd, a_mid, a, a_old, p1, mu, n_new, n_old, st, scratch, midpoint):
    """F <- F a/a_old while a falls, then F - 8 p1 a dd."""
    if a < a_old:
        f_s *= a / a_old
    return f_s - 8.0 * p1 * a * dd


class MindlinPairCoefficient(MindlinWallCoefficient):
    """k_t = 8 G* a, the contact's own G* (the paper's mixing), in the same four forms as the wall coefficient's."""
    name = "mindlin-pair-coefficient"

    def parameter(self, contact, k_n):
        return contact.G_star                           # the kernel's k_t = 8 p1 a
