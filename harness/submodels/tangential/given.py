"""Tangential springs whose stiffness is a number given in an input (docs/laws.md#given-numbers): a linear spring k_t,
a Mindlin-type spring k_t a (k a per contact radius, on the total displacement or the force, rescaled or not), a
spring k a reset to xi = -F/k after the cap, and spring-less friction whose dashpot alone acts."""
from .contact_radius_spring import ContactRadiusSpring
from .linear import LinearTangential
from .mindlin_wall_coefficient import MindlinWallCoefficient
from .viscous import ViscousTangential


class GivenLinearTangential(LinearTangential):
    """dF_t = -k_t V_s dt with k_t given."""
    name = "linear-given"

    def __init__(self, k_t):
        super().__init__()
        self.k_t = float(k_t)

    def label(self):
        return f"linear(k_t={self.k_t:.6g})"

    def parameter(self, contact, k_n):
        return self.k_t


class GivenMindlin(MindlinWallCoefficient):
    """k_t = k a with k given (force per area), in the forms of MindlinWallCoefficient."""
    name = "mindlin-given"

    def __init__(self, form, k):
        super().__init__(form)
        self.k = float(k)

    def label(self):
        return f"mindlin({self.form}, k_t/a={self.k:.6g})"

    def parameter(self, contact, k_n):
        return self.k / 8.0                 # the kernel's k_t = 8 p1 a


class GivenContactRadiusSpring(ContactRadiusSpring):
    """F = -k a xi with k given, reset after the cap to xi = -F/k."""
    name = "contact-radius-spring-given"

    def __init__(self, k, nan_reason=""):
        super().__init__("kappa")
        self.k, self.nan_reason = float(k), nan_reason

    def undefined(self, dashpot):
        """The input's own 0/0 (`nan_reason`) where its dashpot is a share of a normal dashpot that is 0."""
        return self.nan_reason if self.nan_reason and dashpot.c0 == 0.0 else ""

    def label(self):
        return f"contact-radius-spring(k={self.k:.6g})"

    def parameter(self, contact, k_n):
        return self.k


class GivenViscous(ViscousTangential):
    """No spring: F_t = -sign(V_s) min(c_t |V_s|, mu F_n); the dashpot's c_t = prefactor sqrt(k), with k = 1
    ('linear', a constant c_t) or 8 p1 a ('mindlin', c_t growing as a^1/2), p1 given so that the prefactor is the
    input's."""
    name = "viscous-given"

    def __init__(self, form, p1, nan_reason=""):
        super().__init__(form)
        self.p1, self.nan_reason = float(p1), nan_reason

    def parameter(self, contact, k_n):
        return self.p1

    def undefined(self, dashpot):
        """The input's own 0/0 (`nan_reason`) where its dashpot is a share of a normal dashpot that is 0."""
        return self.nan_reason if self.nan_reason and dashpot.c0 == 0.0 else ""
