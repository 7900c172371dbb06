"""Linear dashpot c_n = 2 g sqrt(m k_n), g calibrated for the end rule (docs/laws.md#normal-laws)."""
import math

from ...infra.errors import UserError
from .. import calibration as cal
from . import Dashpot


class LinearDashpot:
    """c_n = 2 g sqrt(m k_n); g exact for the end rule (closed form with tension, Schwager-Poeschel inverted without),
    'tension': the convention-A g whatever the end rule (what engines do, clipped or not), or 'half-mass': the
    convention-A g for a reduced mass m/2, i.e. g/sqrt2 (a wall as a body of reduced mass m/2), or 'bisection':
    Schwager-Poeschel's e(g) inverted to a 1e-4 bracket (calibration.lsd_notension_g_bisection)."""
    name = "linear"
    CALIBRATIONS = ("exact", "tension", "half-mass", "bisection")

    def __init__(self, calibration="exact"):
        if calibration not in self.CALIBRATIONS:
            raise UserError(f"the linear dashpot calibration is one of {', '.join(self.CALIBRATIONS)}, "
                            f"got {calibration!r}")
        self.calibration = calibration

    def dashpot(self, normal, contact, e_n, speed, end):
        k = normal.parameters(contact, e_n, speed).values[0]
        if self.calibration == "bisection":
            g = cal.lsd_notension_g_bisection(e_n)
        elif self.calibration == "half-mass":
            g = cal.lsd_tension_g(e_n) / math.sqrt(2.0)
        elif end == "tension" or self.calibration == "tension":
            g = cal.lsd_tension_g(e_n)
        else:
            g = cal.lsd_notension_g(e_n)
        return Dashpot(2.0 * g * math.sqrt(contact.mass * k), 0.0, g)
