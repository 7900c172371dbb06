"""LAMMPS' wall Mindlin springs (fix wall/gran granular, tangential mindlin* NULL): k_t = K a with K = E/4 (2 - nu)
(1 + nu), the wall's own stiffness coefficient from the sphere's E and nu, on the total displacement xi (`mindlin`,
F = -k_t xi) or on the force (`mindlin/force`, F - k_t dd), each rescaled by a/a_old while a falls in its `_rescale`
form (docs/lammps-dialect.md)."""
from ...jit import compiled
from .mindlin import Mindlin, stiffness, total_after_cap  # noqa: F401  (the dispatch points its kernels share)
from .state import T_AUX1

FORMS = {"total": "mindlin:total", "force": "mindlin:incremental", "total-rescale": "lammps-mindlin:total-rescale",
         "force-rescale": "lammps-mindlin:force-rescale"}


def wall_coefficient(contact):
    """K = E/4 (2 - nu)(1 + nu), LAMMPS' k_t/a for `mindlin NULL` against a wall."""
    return contact.E / 4.0 * (2.0 - contact.nu) * (1.0 + contact.nu)


class LammpsWallMindlin(Mindlin):
    """k_t = K a, K = E/4 (2 - nu)(1 + nu) (LAMMPS' wall), on the total displacement or the force."""
    name = "lammps-wall-mindlin"
    FORMS, DEFAULT_FORM = FORMS, "total"

    def parameter(self, contact, k_n):
        return wall_coefficient(contact) / 8.0          # the kernel's k_t = 8 p1 a


@compiled
def total_rescale(f_s, dd, a_mid, a, a_old, p1, mu, n_new, n_old, st, scratch, midpoint):
    """mindlin_rescale: xi <- xi a/a_old while a falls, then xi + dd; F = -8 p1 a xi (LAMMPS)."""
    if a < a_old:
        st[T_AUX1] *= a / a_old
    st[T_AUX1] += dd
    return -8.0 * p1 * a * st[T_AUX1]


@compiled
def force_rescale(f_s, dd, a_mid, a, a_old, p1, mu, n_new, n_old, st, scratch, midpoint):
    """mindlin_rescale/force: F <- F a/a_old while a falls, then F - 8 p1 a dd (LAMMPS)."""
    if a < a_old:
        f_s *= a / a_old
    return f_s - 8.0 * p1 * a * dd
