"""Linear spring F = k_n alpha (Walton), k_n from elastic Hertz's contact duration at V (the paper's) or its peak
overlap (docs/laws.md#normal-laws)."""
import math

from ...infra.errors import UserError
from ...infra.jit import compiled
from .. import calibration as cal
from ..base import NormalModel, NormalParameters

NAME = "linear"
SUMMARY = "F = k_n alpha, a = sqrt(R alpha)"
ADAPTIVE = True
SLOTS = ("k_n",)


class LinearSpring(NormalModel):
    """F = k_n alpha; k_n = m (pi/t_H)^2, the elastic Hertz contact duration at V ('duration', the paper's), or
    16/15 sqrt(R) E* (15 m V^2/(16 sqrt(R) E*))^1/5, Hertz's peak overlap at V ('peak-overlap')."""
    name, kernel, plastic = "linear", NAME, False
    CALIBRATIONS = ("duration", "peak-overlap")

    def __init__(self, calibration="duration"):
        if calibration not in self.CALIBRATIONS:
            raise UserError(f"the linear spring's calibration is one of {', '.join(self.CALIBRATIONS)}, "
                            f"got {calibration!r}")
        self.calibration = calibration

    def label(self):
        return f"{self.name}:{self.calibration}"

    def stiffness(self, contact, speed):
        if self.calibration == "duration":
            return cal.hertz_duration_stiffness(contact.E_star, contact.radius, contact.mass, speed)
        return cal.hertz_equivalent_stiffness(contact.E_star, contact.radius, contact.mass, speed)

    def parameters(self, contact, e_n, speed):
        k = self.stiffness(contact, speed)
        return NormalParameters.named(k, math.pi * math.sqrt(contact.mass / k), k_n=k)

    def peak(self, contact, e_n, speed):
        """(stiffest dF/dalpha, deepest overlap) of an impact at normal speed <= V: k, V sqrt(m/k)."""
        k = self.parameters(contact, e_n, speed)["k_n"]
        return k, speed * math.sqrt(contact.mass / k)


@compiled
def force(k_n, radius, alpha, alpha_max):
    """F = k_n alpha, a = sqrt(R alpha)."""
    return k_n * alpha, math.sqrt(radius * alpha)


@compiled
def below(k_n, alpha):
    """At alpha <= 0 the spring pulls: F = k_n alpha (the force that ends a contact with tension)."""
    return k_n * alpha


@compiled
def slope(k_n, radius, alpha, loading, f, a):
    """dF/dalpha = k_n; a = sqrt(R alpha): d(ln a)/dalpha = 1/(2 alpha)."""
    return k_n, 0.5 / alpha
