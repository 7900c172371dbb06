"""Mindlin k_t = 8 G* a on the total tangential displacement: F = -k_t xi (docs/laws.md#tangential-laws)."""
from ...infra.jit import compiled
from .mindlin import stiffness  # noqa: F401  (its dispatch point: k_t = 8 G a)
from .state import T_AUX1

NAME = "mindlin:total"
SUMMARY = "F = -8 G a xi on the total tangential displacement xi"
SLOTS = ("G",)
ADAPTIVE = True
LOG_RATE = 2                # F_s a'/a in the ODE always


@compiled
def spring(G, f_s, dd, a_mid, a, a_old, mu, n_new, n_old, st, scratch, midpoint):
    """F = -8 G a xi, xi the total tangential displacement."""
    st[T_AUX1] += dd
    return -8.0 * G * a * st[T_AUX1]


@compiled
def after_cap(G, f_s, a, st):
    """Keep the total displacement consistent with a capped force: xi = -F/k_t."""
    k_t = 8.0 * G * a
    st[T_AUX1] = -f_s / k_t if k_t > 0.0 else 0.0
