"""Shared Hertzian pieces of the normal kernels: F = 4/3 E* R^1/2 alpha^3/2 and its slope (paper eq. 1-2)."""
import math
from ...infra.jit import compiled


FOUR_THIRDS = 4.0 / 3.0


@compiled
def hertz(E_star, radius, alpha):
    """Hertz F = 4/3 E* R^1/2 alpha^3/2, a = sqrt(R alpha) (paper eqs. 1-2)."""
    a = math.sqrt(radius * alpha)
    return FOUR_THIRDS * E_star * a * alpha, a


@compiled
def hertz_slope(E_star, f, a):
    """dF/dalpha = 2 E* a on a Hertzian branch, and d(ln a)/dalpha = dF/dalpha/(3F) (a ~ F^1/3)."""
    slope = 2.0 * E_star * a
    return slope, slope / (3.0 * f)
