"""Kuwabara-Kono damping F = k[alpha^3/2 + 3/2 A alpha^1/2 alpha_dot] (Zhou et al. 1999 form), A calibrated at the
scene speed (docs/laws.md#normal-laws)."""
import math

from .. import calibration as cal
from . import Dashpot


class KuwabaraKonoDashpot:
    """F = k[alpha^3/2 + 3/2 A alpha^1/2 alpha_dot]; A from y = A (k/m)^2/5 V^1/5 solving e(y) = e_n at V
    (docs/laws.md)."""
    name = "kuwabara-kono"
    calibration = "exact"

    def dashpot(self, normal, contact, e_n, speed, end):
        k = 4.0 / 3.0 * contact.E_star * math.sqrt(contact.radius)
        y = cal.kuwabara_kono_y(e_n, end)
        a_time = y * (contact.mass / k) ** 0.4 * speed ** -0.2
        return Dashpot(1.5 * k * a_time, 0.5, 0.0)
