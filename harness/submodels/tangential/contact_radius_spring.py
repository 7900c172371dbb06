"""A spring whose coefficient k is applied at the contact radius a = sqrt(R alpha): F = -k a xi on the total
tangential displacement xi; after the Coulomb cap xi = -F/k, the displacement of the spring k alone, so that the
next step scales the capped force by a once more; its dashpot is (c_t/c_n) c_n, not a number without a normal dashpot
(docs/laws.md#tangential-laws)."""
from ...infra.errors import UserError
from ...infra.jit import compiled
from ..base import TangentialModel
from .ratio import parse_ratio, ratio_label, ratio_value
from .state import T_AUX1

NAME = "contact-radius-spring"
SUMMARY = "F = -k a xi on the total displacement, xi = -F/k after the cap"
SLOTS = ("k",)


class ContactRadiusSpring(TangentialModel):
    """F = -k a xi, reset after the cap to xi = -F/k; k = 8 G* ('mindlin') or a ratio of k_n ('kappa', '2/7', a
    number: the linear spring's k_t). The tangential dashpot and the stability limit take k itself; the dashpot is
    taken as the ratio c_t/c_n times the normal dashpot, c_t where c_n is not 0 and 0/0 (NaN) where it is."""
    name, kernel, constant_stiffness = NAME, NAME, True

    def __init__(self, coefficient="kappa"):
        self.coefficient = "mindlin" if coefficient == "mindlin" else parse_ratio(coefficient)
        if self.coefficient == "nu":
            raise UserError("the contact-radius spring takes 'mindlin', 'kappa' or a ratio of k_n, not 'nu'")

    def label(self):
        if self.coefficient == "mindlin":
            return f"{self.name}(k=8G*)"
        return f"{self.name}(k={ratio_label(self.coefficient)} k_n)"

    def undefined(self, dashpot):
        """c_t = (c_t/c_n) c_n divides 0 by 0 without a normal dashpot: the force is NaN from the first contact step
        (NaN times any slip, a zero one included)."""
        if dashpot.c0 != 0.0:
            return ""
        return "the tangential dashpot (c_t/c_n) c_n divides 0 by 0 without a normal dashpot (c_n = 0)"

    def parameter(self, contact, k_n):
        if self.coefficient == "mindlin":
            return 8.0 * contact.G_star
        return ratio_value(self.coefficient, contact) * k_n


@compiled
def stiffness(k, a):
    """k itself (what the tangential dashpot's c_t = g sqrt(k) and the stability limit take)."""
    return k


@compiled
def spring(k, f_s, dd, a_mid, a, a_old, mu, n_new, n_old, st, scratch, midpoint):
    """xi + dd; F = -k a xi."""
    st[T_AUX1] += dd
    return -k * a * st[T_AUX1]


@compiled
def after_cap(k, f_s, a, st):
    """xi = -F/k for a capped force F (not -F/(k a))."""
    st[T_AUX1] = -f_s / k if k > 0.0 else 0.0
