"""Linear spring F = k_n alpha with k_n = beta E* pi 0.31225 R* from the moduli and the radius: a stiffness taken at
the contact radius of a 5% sagitta, beta 1 against a wall and 1.432 between two spheres."""
import math

from .linear import LinearSpring

MODIFIED_RADIUS = 0.31225   # sqrt(s (2 - s)) for a sagitta ratio s = 0.05: the contact radius k_n is taken at, over R*
BETAS = {"wall": 1.0, "pair": 1.432}


def modulus_stiffness(E_star, radius, beta):
    """k_n = beta E* pi (0.31225 R*)."""
    return beta * E_star * math.pi * (radius * MODIFIED_RADIUS)


class LinearModulus(LinearSpring):
    """F = k_n alpha, k_n = beta E* pi 0.31225 R*: beta 1 against a wall ('wall'), 1.432 between two spheres ('pair');
    the linear kernel."""
    name = "linear-modulus"
    CALIBRATIONS = tuple(BETAS)

    def __init__(self, calibration="wall"):
        super().__init__(calibration)

    def stiffness(self, contact, speed):
        return modulus_stiffness(contact.E_star, contact.radius, BETAS[self.calibration])
