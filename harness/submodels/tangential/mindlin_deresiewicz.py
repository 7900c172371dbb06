"""Mindlin-Deresiewicz as Thornton & Yin (1991): dT = 8 G* a theta_k dd + (-1)^k mu dN (1 - theta_k)
(docs/laws.md#tangential-laws)."""

from ...infra.jit import compiled
from .mindlin import Mindlin, stiffness
from .state import N_TSTATE, T_AUX1, T_AUX2, T_DIR, T_MODE

NAME = "mindlin-deresiewicz"
SUMMARY = "Thornton & Yin (1991): dT = 8 G a theta_k dd + (-1)^k mu dN (1 - theta_k)"
SLOTS = ("G",)


class MindlinDeresiewicz(Mindlin):
    """Mindlin-Deresiewicz as Thornton & Yin (1991): dT = 8G*a theta_k dd + (-1)^k mu dN (1 - theta_k)."""
    name, kernel, form = "mindlin-deresiewicz", NAME, "deresiewicz"

    def __init__(self):
        pass

    def label(self):
        return self.name


@compiled
def mindlin_deresiewicz(f_s, dd, k_t, mu, n_new, n_old, st, t_eval):
    """Thornton & Yin (1991): dT = k_t theta_k dd + (-1)^k mu dN (1 - theta_k), k = 0/1/2 (docs/laws.md).

    theta_k^3 = 1 - T/(mu N) etc. at T = t_eval and the mean N: the midpoint rule of the rate form, i.e. Thornton &
    Yin's increments without their O(dN) look-ahead terms (T + mu dN), which vanish as dt -> 0.
    """
    t = -f_s                      # T resists the displacement: T = k_t * displacement for small loads
    if st[T_DIR] == 0.0:
        st[T_DIR] = 1.0 if dd >= 0.0 else -1.0
    sgn = st[T_DIR]
    t, t_star, t_ss, d = t * sgn, st[T_AUX1] * sgn, st[T_AUX2] * sgn, dd * sgn
    te = -t_eval * sgn
    mode = int(st[T_MODE])
    if mode == 0 and d < 0.0:
        mode, t_star = 1, t
    elif mode == 1 and d > 0.0:
        mode, t_ss = 2, t
    elif mode == 2 and d < 0.0:
        mode, t_star = 1, t
    if mode == 2 and t >= t_star:
        mode = 0
    dn = n_new - n_old
    mu_n = 0.5 * mu * (n_new + n_old)
    if mu_n <= 0.0:
        theta3 = 0.0
    elif mode == 0:
        theta3 = 1.0 - te / mu_n
    elif mode == 1:
        theta3 = 1.0 - (t_star - te) / (2.0 * mu_n)
    else:
        theta3 = 1.0 - (te - t_ss) / (2.0 * mu_n)
    theta3 = min(1.0, max(0.0, theta3))
    theta = theta3 ** (1.0 / 3.0)
    if abs(k_t * d) < mu * dn:
        theta = 1.0               # the slip limit grows faster than the load: elastic increment
    sign_k = -1.0 if mode == 1 else 1.0
    t += k_t * theta * d + sign_k * mu * dn * (1.0 - theta)
    st[T_AUX1], st[T_AUX2], st[T_MODE] = t_star * sgn, t_ss * sgn, mode
    return -t * sgn


@compiled
def spring(G, f_s, dd, a_mid, a, a_old, mu, n_new, n_old, st, scratch, midpoint):
    """A predictor-corrector on T: the increment at the mid-step T."""
    for k in range(N_TSTATE):
        scratch[k] = st[k]
    predicted = mindlin_deresiewicz(f_s, dd, stiffness(G, a_mid), mu, n_new, n_old, scratch, f_s)
    return mindlin_deresiewicz(f_s, dd, stiffness(G, a_mid), mu, n_new, n_old, st, 0.5 * (f_s + predicted))
