"""Normal springs whose stiffness is a number given in an input, not calibrated from e_n: F = k_n alpha and
F = k_h R^1/2 alpha^3/2 = 4/3 E* R^1/2 alpha^3/2 (docs/laws.md#given-numbers)."""
import math

from .. import calibration as cal
from ..base import NormalParameters
from .hertz import Hertz
from .linear import LinearSpring


class GivenLinear(LinearSpring):
    """F = k_n alpha with k_n given; contact time pi sqrt(m/k_n), the undamped half period."""
    name = "linear-given"

    def __init__(self, k_n):
        super().__init__()
        self.k_n = float(k_n)

    def label(self):
        return f"linear(k_n={self.k_n:.6g})"

    def stiffness(self, contact, speed):
        return self.k_n


class GivenHertz(Hertz):
    """F = 4/3 E* R^1/2 alpha^3/2 with E* given (a stiffness k_h per sqrt(length) is E* = 3/4 k_h)."""
    name = "hertz-given"

    def __init__(self, e_star):
        self.e_star = float(e_star)

    def label(self):
        return f"hertz(E*={self.e_star:.6g})"

    def parameters(self, contact, e_n, speed):
        return NormalParameters.named(cal.hertz_equivalent_stiffness(self.e_star, contact.radius, contact.mass, speed),
                                      cal.hertz_contact_time(self.e_star, contact.radius, contact.mass, speed),
                                      E_star=self.e_star)

    def peak(self, contact, e_n, speed):
        """Elastic Hertz with the given E*: alpha_max = (5 m V^2/(4 k_h))^2/5, dF/dalpha = 2 E* sqrt(R alpha)."""
        k_h = 4.0 / 3.0 * self.e_star * math.sqrt(contact.radius)
        alpha = (1.25 * contact.mass * speed ** 2 / k_h) ** 0.4
        return 2.0 * self.e_star * math.sqrt(contact.radius * alpha), alpha
