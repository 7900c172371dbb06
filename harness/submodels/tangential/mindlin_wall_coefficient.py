"""Mindlin springs with the wall coefficient of the sphere's own material: k_t = K a with K = E/4 (2 - nu)
(1 + nu), on the total displacement xi ('total', F = -k_t xi) or on the force ('force', F - k_t dd), each also
rescaled by a/a_old while a falls ('total-rescale', 'force-rescale')."""
from .mindlin import Mindlin

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
        return wall_coefficient(contact) / 8.0          # the kernel's k_t = 8 G a


class MindlinPairCoefficient(MindlinWallCoefficient):
    """k_t = 8 G* a, the contact's own G* (the paper's mixing), in the same four forms as the wall coefficient's."""
    name = "mindlin-pair-coefficient"

    def parameter(self, contact, k_n):
        return contact.G_star                           # the kernel's k_t = 8 G a
