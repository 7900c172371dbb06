"""Integrator 'paper': second-order splitting on u = m alpha_dot + D(alpha)."""
from ...infra.jit import compiled

NAME = "paper"
SUMMARY = "second-order splitting on u = m alpha_dot + D(alpha), release and regime changes located in the step"
SLOTS = ()
EXPLICIT = False
EVENTS = True
ADAPTIVE = True


@compiled
def drift(alpha, rate0, c_alpha, h):
    """Linearised implicit midpoint for alpha' = (u_half - D(alpha))/m, u frozen: D(mid) = D(alpha_n) +
    c_n (x - alpha)/2 gives x = alpha + h rate0 / (1 + h c_n/(2m)); c_alpha = h c_n/(2m). Unconditionally stable,
    O(h^3) locally."""
    return alpha + h * rate0 / (1.0 + c_alpha)
