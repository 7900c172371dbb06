"""Normal damping sub-models: c(alpha) = c0 alpha^power, with c0 calibrated from the target e_n (MODELS 2.1-2.3)."""
import math
from dataclasses import dataclass

from ..errors import UserError
from . import calibration as cal

CALIBRATIONS = ("exact", "appendix-b", "tension")


@dataclass(frozen=True)
class Dashpot:
    """Kernel coefficients c0, power and the equivalent damping ratio g (0 where none is defined)."""
    c0: float
    power: float
    g: float


class NoDamping:
    """No normal dashpot: plastic laws dissipate by hysteresis."""
    name = "none"
    calibration = None

    def dashpot(self, normal, contact, e_n, speed, end):
        return Dashpot(0.0, 0.0, 0.0)


class LinearDashpot:
    """c_n = 2 g sqrt(m k_n); g exact for the end rule (convention A closed form, or Schwager-Poeschel inverted),
    'tension': the convention-A g whatever the end rule (what engines do, clipped or not), or 'half-mass': the
    convention-A g for a reduced mass m/2, i.e. g/sqrt2 (YADE ViscEl against a wall, MODELS 5)."""
    name = "linear"
    CALIBRATIONS = ("exact", "tension", "half-mass")

    def __init__(self, calibration="exact"):
        if calibration not in self.CALIBRATIONS:
            raise UserError(f"the linear dashpot calibration is one of {', '.join(self.CALIBRATIONS)}, "
                            f"got {calibration!r}")
        self.calibration = calibration

    def dashpot(self, normal, contact, e_n, speed, end):
        k = normal.parameters(contact, e_n, speed).values[0]
        if self.calibration == "half-mass":
            g = cal.lsd_tension_g(e_n) / math.sqrt(2.0)
        elif end == "tension" or self.calibration == "tension":
            g = cal.lsd_tension_g(e_n)
        else:
            g = cal.lsd_notension_g(e_n)
        return Dashpot(2.0 * g * math.sqrt(contact.mass * k), 0.0, g)


class TsujiDashpot:
    """eta alpha^1/4 alpha_dot, eta = A sqrt(m k), k = 4/3 E* sqrt(R); A exact for the end rule (sqrt5 beta with
    tension), 'tension' (sqrt5 beta whatever the end rule) or 'appendix-b' (the Thornton 2013 fit)."""
    name = "tsuji"

    def __init__(self, calibration="appendix-b"):
        if calibration not in CALIBRATIONS:
            raise UserError(f"tsuji calibration must be one of {', '.join(CALIBRATIONS)}, got {calibration!r}")
        self.calibration = calibration

    def coefficient_A(self, e_n, end):
        """A for the end rule; 'appendix-b' uses A = sqrt6 g_fit (c_n = 2 g sqrt(m 2E*a), Thornton 2013 App. B)."""
        if self.calibration == "appendix-b":
            return math.sqrt(6.0) * cal.thornton_appendix_b_g(e_n)
        tension = end == "tension" or self.calibration == "tension"
        return cal.tsuji_tension_A(e_n) if tension else cal.tsuji_notension_A(e_n)

    def dashpot(self, normal, contact, e_n, speed, end):
        a = self.coefficient_A(e_n, end)
        k = 4.0 / 3.0 * contact.E_star * math.sqrt(contact.radius)
        return Dashpot(a * math.sqrt(contact.mass * k), 0.25, a / math.sqrt(6.0))


class KuwabaraKonoDashpot:
    """F = k[alpha^3/2 + 3/2 A alpha^1/2 alpha_dot]; A from y = A (k/m)^2/5 V^1/5 solving e(y) = e_n at V (MODELS 2.3)."""
    name = "kuwabara-kono"
    calibration = "exact"

    def dashpot(self, normal, contact, e_n, speed, end):
        k = 4.0 / 3.0 * contact.E_star * math.sqrt(contact.radius)
        y = cal.kuwabara_kono_y(e_n, end)
        a_time = y * (contact.mass / k) ** 0.4 * speed ** -0.2
        return Dashpot(1.5 * k * a_time, 0.5, 0.0)


DAMPING_MODELS = {cls.name: cls for cls in (NoDamping, LinearDashpot, TsujiDashpot, KuwabaraKonoDashpot)}
