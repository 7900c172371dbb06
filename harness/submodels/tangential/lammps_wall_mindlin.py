"""LAMMPS' wall Mindlin spring (fix wall/gran granular, tangential mindlin NULL): F = -K a xi on the total tangential
displacement xi, with K = E/4 (2 - nu)(1 + nu) the wall's own stiffness coefficient from the sphere's E and nu
(docs/lammps-dialect.md); the total-displacement Mindlin kernel."""
from .mindlin import Mindlin


def wall_coefficient(contact):
    """K = E/4 (2 - nu)(1 + nu), LAMMPS' k_t/a for `mindlin NULL` against a wall."""
    return contact.E / 4.0 * (2.0 - contact.nu) * (1.0 + contact.nu)


class LammpsWallMindlin(Mindlin):
    """k_t = K a, K = E/4 (2 - nu)(1 + nu) (LAMMPS' wall), on the total displacement."""
    name = "lammps-wall-mindlin"

    def __init__(self, form="total"):
        super().__init__(form)

    def label(self):
        return f"lammps-wall-mindlin({self.form})"

    def parameter(self, contact, k_n):
        return wall_coefficient(contact) / 8.0          # the kernel's k_t = 8 p1 a
