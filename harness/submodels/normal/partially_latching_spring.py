"""The paper's partially latching spring [provisional]: Walton & Braun's latching spring with K1 = pi p_y R, p_y of
Thornton's law for the target e_n at V (docs/laws.md#normal-laws)."""
import math

from .thornton import Thornton
from .walton_braun import WaltonBraun


class PartiallyLatchingSpring(WaltonBraun):
    """Provisional PLS: Walton-Braun with K1 = pi p_y R, p_y of Thornton's law for e_n at V; runs on Walton-Braun's
    kernel."""
    name = "partially-latching-spring"

    def loading_stiffness(self, contact, e_n, speed):
        return math.pi * Thornton().yield_pressure(contact, e_n, speed) * contact.radius
