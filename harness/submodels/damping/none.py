"""No normal dashpot: plastic laws dissipate by hysteresis."""
from . import Dashpot


class NoDamping:
    """No normal dashpot: plastic laws dissipate by hysteresis."""
    name = "none"
    calibration = None

    def dashpot(self, normal, contact, e_n, speed, end):
        return Dashpot(0.0, 0.0, 0.0)
