"""A normal dashpot given by an input's numbers, not calibrated from e_n: F_d = -c m^a R^b alpha^power alpha_dot
(docs/laws.md#given-numbers): c the input's coefficient, m and R the contact's mass and radius."""
from . import Dashpot


class FixedDashpot:
    """F_d = -c0 alpha^power alpha_dot with c0 = c m^mass_power R^radius_power."""
    name = "fixed"

    def __init__(self, c, mass_power=0.0, radius_power=0.0, power=0.0):
        self.c, self.mass_power, self.radius_power, self.power = (float(c), float(mass_power), float(radius_power),
                                                                  float(power))

    @property
    def calibration(self):
        return f"c={self.c:.6g}*m^{self.mass_power:g}*R^{self.radius_power:g}*alpha^{self.power:g}"

    def dashpot(self, normal, contact, e_n, speed, end):
        c0 = self.c * contact.mass ** self.mass_power * contact.radius ** self.radius_power
        return Dashpot(c0, self.power, 0.0)
