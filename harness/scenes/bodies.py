"""A sphere as a body of a collision: radius, material, velocity at first touch and spin, free or fixed."""
import math
from dataclasses import dataclass


@dataclass(frozen=True)
class Sphere:
    """One body: radius, material, and its velocity at first touch (v_n towards the other sphere, v_t along x, omega
    about y); a fixed sphere neither moves nor turns whatever its mass."""
    radius: float
    E: float = 70e9
    nu: float = 0.3
    rho: float = 2650.0
    v_n: float = 0.0
    v_t: float = 0.0
    omega: float = 0.0
    fixed: bool = False

    @property
    def mass(self):
        """m = 4/3 pi R^3 rho."""
        return 4.0 / 3.0 * math.pi * self.radius ** 3 * self.rho

    @property
    def inertia(self):
        """I = 2/5 m R^2, a solid sphere."""
        return 0.4 * self.mass * self.radius ** 2
