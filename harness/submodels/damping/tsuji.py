"""Tsuji-type Hertz dashpot eta alpha^1/4 alpha_dot, eta = A sqrt(m k), calibrated by the paper's App. B fit or
exactly for the end rule (docs/laws.md#normal-laws)."""
import math

from ...infra.errors import UserError
from .. import calibration as cal
from . import Dashpot

CALIBRATIONS = ("exact", "appendix-b", "tension", "polynomial")


class TsujiDashpot:
    """eta alpha^1/4 alpha_dot, eta = A sqrt(m k), k = 4/3 E* sqrt(R); A exact for the end rule (sqrt5 beta with
    tension), 'tension' (sqrt5 beta whatever the end rule), 'appendix-b' (the Thornton 2013 fit) or 'polynomial' (a
    polynomial fit in e, with k from the normal model's own modulus)."""
    name = "tsuji"

    def __init__(self, calibration="appendix-b"):
        if calibration not in CALIBRATIONS:
            raise UserError(f"tsuji calibration must be one of {', '.join(CALIBRATIONS)}, got {calibration!r}")
        self.calibration = calibration

    def coefficient_A(self, e_n, end):
        """A for the end rule; 'appendix-b' uses A = sqrt6 g_fit (c_n = 2 g sqrt(m 2E*a), Thornton 2013 App. B)."""
        if self.calibration == "appendix-b":
            return math.sqrt(6.0) * cal.thornton_appendix_b_g(e_n)
        if self.calibration == "polynomial":
            return cal.polynomial_tsuji_A(e_n)
        tension = end == "tension" or self.calibration == "tension"
        return cal.tsuji_tension_A(e_n) if tension else cal.tsuji_notension_A(e_n)

    def dashpot(self, normal, contact, e_n, speed, end):
        a = self.coefficient_A(e_n, end)
        e_star = (normal.parameters(contact, e_n, speed).values[0] if self.calibration == "polynomial" else
                  contact.E_star)
        k = 4.0 / 3.0 * e_star * math.sqrt(contact.radius)
        return Dashpot(a * math.sqrt(contact.mass * k), 0.25, a / math.sqrt(6.0))
