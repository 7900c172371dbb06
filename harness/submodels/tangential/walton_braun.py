"""Walton & Braun's (1986) tangential spring: k_t = k_t0 [1 - (T - T*)/(mu N - T*)]^1/3 while T rises,
k_t0 [1 - (T* - T)/(mu N + T*)]^1/3 while it falls, T* set at each reversal and scaled with N
(docs/laws.md#tangential-laws). Stiff at full mobilisation: the converged mode integrates it implicitly in
w = x^1/3, x = (mu N - d T)/(mu N - d T*), where F_s = -d mu N (1 - (1 - d sigma*) w^3) and F_s' = -k_t0 w V_s."""
import numpy as np

from ...infra.jit import compiled
from .linear import LinearTangential
from .ratio import ratio_label
from .state import N_TSTATE, T_AUX1, T_DIR

NAME = "walton-braun"
SUMMARY = "k_t = k_t0 x^1/3, x the spring's mobilisation from its last reversal, T* scaled with N (Walton & Braun 1986)"
SLOTS = ("k_t0",)
ADAPTIVE = True
IMPLICIT = True             # stiff at full mobilisation: integrated implicitly in w = x^1/3, with reversal events


class WaltonBraunTangential(LinearTangential):
    """Walton & Braun (1986): k_t = k_t0 [1 - (T - T*)/(mu N - T*)]^1/3, k_t0 = ratio k_n (2/7 default)."""
    name, kernel, constant_stiffness = "walton-braun", NAME, False

    def label(self):
        return f"walton-braun(k_t0/k_n={ratio_label(self.kt_kn)})"


@compiled
def stiffness(k_t0, a):
    """k_t0 (the initial stiffness; the kernel's spring lowers it towards full mobilisation)."""
    return k_t0


@compiled
def walton_braun_history(t, dd, n_new, n_old, st):
    """Walton & Braun's turning-point force T*: scaled with the normal force, reset to T at a reversal of the
    displacement; returns the direction of this increment (+1, -1)."""
    direction = 1.0 if dd >= 0.0 else -1.0
    if n_old > 0.0:
        st[T_AUX1] *= n_new / n_old
    if st[T_DIR] != 0.0 and direction != st[T_DIR]:
        st[T_AUX1] = t
    st[T_DIR] = direction
    return direction


@compiled
def walton_braun(f_s, dd, k_t0, mu, n_new, n_old, st, t_eval):
    """Walton & Braun (1986): k_t = k_t0 [1 - (T - T*)/(mu N - T*)]^1/3 rising, [1 - (T* - T)/(mu N + T*)]^1/3 falling.

    k_t is evaluated at T = t_eval and the mean normal force (midpoint rule when t_eval is the mid-step T).
    """
    t = -f_s
    te = -t_eval
    direction = walton_braun_history(t, dd, n_new, n_old, st)
    t_star, mu_n = st[T_AUX1], 0.5 * mu * (n_new + n_old)
    if direction > 0.0:
        ratio = 1.0 - (te - t_star) / (mu_n - t_star) if mu_n > t_star else 0.0
    else:
        ratio = 1.0 - (t_star - te) / (mu_n + t_star) if mu_n > -t_star else 0.0
    k_t = k_t0 * max(0.0, ratio) ** (1.0 / 3.0)
    return -(t + k_t * dd)


@compiled
def cubic_root(c, rest):
    """The root z >= 0 of z^3 + c z = rest (c >= 0; 0 if rest <= 0): Newton from z = rest^(1/3), where
    f(z) = z^3 + c z - rest >= 0; f is increasing and convex there, so the iterates fall monotonically onto it."""
    z = 0.0
    if rest > 0.0:
        z = rest ** (1.0 / 3.0)
        for _ in range(60):
            step = (z * z * z + c * z - rest) / (3.0 * z * z + c)
            z -= step
            if step <= 1e-15 * z:
                break
    return z


@compiled
def walton_braun_implicit(f_s, dd, k_t0, mu, n_new, n_old, st):
    """Walton & Braun's rate form dT = k_t0 x^1/3 dd, x = (mu N - T)/(mu N - T*) rising ((mu N + T)/(mu N + T*)
    falling), by the trapezoidal rule in x at the mean normal force: x1 = x0 - c (x0^1/3 + x1^1/3), c = k_t0 |dd| /
    (2 (mu N -+ T*)), solved for z = x1^1/3 (z^3 + c z = x0 - c x0^1/3, increasing: Newton from the right). Implicit,
    so x ~ 0 (the spring at full mobilisation under a rising mu N, where x^1/3 makes the explicit rule stiff) is
    stable and second order; x1 = 0 when the step reaches full mobilisation. Away from the cone (x0 > 1/2) the new
    T is T plus the trapezoid's increment, not mu N - span x1: under a tangential load 1e-8 of mu N that difference
    of near-equal numbers lost 1e-8 of T per step, 1e-4 of e_t at 2^19 steps per contact."""
    t = -f_s
    direction = walton_braun_history(t, dd, n_new, n_old, st)
    mu_n = 0.5 * mu * (n_new + n_old)
    span = mu_n - direction * st[T_AUX1]
    if span <= 0.0:
        return f_s
    x0 = (mu_n - direction * t) / span
    if x0 <= 0.0:                                 # at or beyond mobilisation: k_t = 0
        return f_s
    c = 0.5 * k_t0 * abs(dd) / span
    root0 = x0 ** (1.0 / 3.0)
    rest = x0 - c * root0
    z = cubic_root(c, rest)
    if x0 > 0.5 and z > 0.0:                      # far from the cone: the increment k_t0 |dd| (x0^1/3 + x1^1/3)/2,
        return f_s - direction * 0.5 * k_t0 * abs(dd) * (root0 + z)   # exact, without mu N - span x1's cancellation
    return -direction * (mu_n - span * z * z * z)


@compiled
def spring(k_t0, f_s, dd, a_mid, a, a_old, mu, n_new, n_old, st, scratch, midpoint):
    """The paper scheme's implicit trapezoid in x (midpoint), or the engines' predictor-corrector on T."""
    if midpoint:
        return walton_braun_implicit(f_s, dd, k_t0, mu, n_new, n_old, st)
    for k in range(N_TSTATE):
        scratch[k] = st[k]
    predicted = walton_braun(f_s, dd, k_t0, mu, n_new, n_old, scratch, f_s)
    return walton_braun(f_s, dd, k_t0, mu, n_new, n_old, st, 0.5 * (f_s + predicted))


@compiled
def force_from_w(d, star, cone, w):
    """F_s of the sticking spring at w: -d mu N (1 - (1 - d sigma*) w^3)."""
    return -d * cone * (1.0 - (1.0 - d * star) * w * w * w)


@compiled
def w_from_force(d, star, cone, f_s):
    """w = x^(1/3) of the sticking spring from F_s: x = (mu N + d F_s)/((1 - d sigma*) mu N); 1 where mu N = 0."""
    share = 1.0 - d * star
    if cone > 0.0 and share > 0.0:
        return np.cbrt((cone + d * f_s) / (share * cone))
    return 1.0


@compiled
def edge_w(d, star, sign):
    """w of the spring held on the cone's edge F_s = sigma mu N: x = (1 + d sigma)/(1 - d sigma*), 0 on the loading
    side; 0 too where T* itself is at full mobilisation."""
    share = 1.0 - d * star
    return np.cbrt((1.0 + d * sign) / share) if share > 0.0 else 0.0


@compiled
def onset_w(k_t0, v_s, rise):
    """w at first touch where mu N rises from 0 at the rate `rise`: 1 - x = beta x^(1/3), beta = k_t0 |V_s|/rise,
    i.e. w^3 + beta w = 1 (0 where mu N does not rise: the spring rides the cone)."""
    return cubic_root(k_t0 * abs(v_s) / rise, 1.0) if rise > 0.0 else 0.0
