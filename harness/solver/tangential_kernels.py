"""Compiled tangential springs: new spring force on the sphere from a slip increment dd = V_s dt (MODELS 3).

Sign: F_s is the force on the sphere along x; the spring resists slip, dF_s = -k_t dd. All capped by Coulomb
|F_s| <= mu F_n by the caller. `st` holds the history: [xi or T*, T**, mode, direction, a_old].
"""
import math

from numba import njit

from . import codes as C

T_AUX1, T_AUX2, T_MODE, T_DIR, T_AOLD = 0, 1, 2, 3, 4
T_MARGIN = 5          # |trial spring force| - mu F_n of the last step (> 0: capped, sliding); read by event location
T_STEP = 6            # length of the last step, to compare margins of steps of unequal length
T_HELD = 7            # the margin of what holds the contact on the cone: T_MARGIN, or in the paper scheme with a
N_TSTATE = 8          # tangential dashpot the larger of it and |spring + dashpot| - mu F_n


@njit(cache=True)
def cap(force, limit):
    """Coulomb cap |F_t| <= mu F_n."""
    if force > limit:
        return limit
    if force < -limit:
        return -limit
    return force


@njit(cache=True)
def stiffness(code, p1, a):
    """k_t: constant p1 for the linear spring and Walton-Braun (initial), 8 G* a for Mindlin (p1 = G*)."""
    if code == C.TANGENTIAL_LINEAR or code == C.TANGENTIAL_WALTON_BRAUN or code == C.TANGENTIAL_VISCOUS_LINEAR:
        return p1
    return 8.0 * p1 * a


@njit(cache=True)
def viscous(code, p1, a, c_factor, slip, limit):
    """Spring-less friction: F = -sign(V_s) min(c_t |V_s|, mu F_n), c_t = c_factor sqrt(k_t) (LIGGGHTS no_history)."""
    c_t = c_factor * math.sqrt(stiffness(code, p1, a))
    force = c_t * abs(slip)
    if force > limit:
        force = limit
    return -force if slip > 0.0 else force


@njit(cache=True)
def mindlin_deresiewicz(f_s, dd, k_t, mu, n_new, n_old, st, t_eval):
    """Thornton & Yin (1991): dT = k_t theta_k dd + (-1)^k mu dN (1 - theta_k), k = 0/1/2 (MODELS 3).

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


@njit(cache=True)
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


@njit(cache=True)
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


@njit(cache=True)
def mean_radius(a_old, a):
    """Mean of a = sqrt(R alpha) over a step in which alpha changes linearly: 2/3 (a1^3 - a0^3)/(a1^2 - a0^2); exact
    at first touch (a ~ sqrt(t), where the trapezoid's error would sum to O(h^1.5)), second order elsewhere."""
    total = a_old + a
    if total <= 0.0:
        return 0.0
    return (2.0 / 3.0) * (a_old * a_old + a_old * a + a * a) / total


@njit(cache=True)
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


@njit(cache=True)
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


@njit(cache=True)
def spring_force(code, f_s, dd, a, p1, mu, n_new, n_old, st, scratch, midpoint):
    """Trial spring force after the increment dd, before the Coulomb cap; updates the history `st`.

    `a` is the contact radius at the end of the step, st[T_AOLD] the one at its start. With `midpoint` (the paper
    scheme) stiffnesses use their mean over the step, Mindlin-Deresiewicz a predictor-corrector on T and
    Walton-Braun its implicit trapezoid, so that every increment is second order; engines use the current a (and a
    predictor-corrector for Walton-Braun)."""
    a_old = st[T_AOLD]
    a_mid = mean_radius(a_old, a) if midpoint else a
    st[T_AOLD] = a
    if code == C.TANGENTIAL_LINEAR or code == C.TANGENTIAL_MINDLIN_INCREMENTAL:
        return f_s - stiffness(code, p1, a_mid) * dd
    if code == C.TANGENTIAL_MINDLIN_RESCALE:
        if a >= a_old:
            return f_s - 8.0 * p1 * a_mid * dd
        half = math.sqrt(a / a_old)              # paper eq. 18b rescale F a/a_old, split around the increment
        return (f_s * half - 8.0 * p1 * a_mid * dd) * half
    if code == C.TANGENTIAL_MINDLIN_TOTAL:
        st[T_AUX1] += dd                          # xi: total tangential displacement
        return -8.0 * p1 * a * st[T_AUX1]
    if code == C.TANGENTIAL_WALTON_BRAUN and midpoint:
        return walton_braun_implicit(f_s, dd, p1, mu, n_new, n_old, st)
    for k in range(N_TSTATE):
        scratch[k] = st[k]
    if code == C.TANGENTIAL_MINDLIN_DERESIEWICZ:
        predicted = mindlin_deresiewicz(f_s, dd, 8.0 * p1 * a_mid, mu, n_new, n_old, scratch, f_s)
        return mindlin_deresiewicz(f_s, dd, 8.0 * p1 * a_mid, mu, n_new, n_old, st, 0.5 * (f_s + predicted))
    predicted = walton_braun(f_s, dd, p1, mu, n_new, n_old, scratch, f_s)
    return walton_braun(f_s, dd, p1, mu, n_new, n_old, st, 0.5 * (f_s + predicted))


@njit(cache=True)
def after_cap(code, f_s, p1, a, st):
    """Keep the history consistent with a capped force (total form: xi = -F/k_t)."""
    if code == C.TANGENTIAL_MINDLIN_TOTAL:
        k_t = 8.0 * p1 * a
        st[T_AUX1] = -f_s / k_t if k_t > 0.0 else 0.0

