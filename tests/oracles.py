"""Independent oracles for the normal (and rigid-body tangential) impact of a sphere on a wall.

Written from first principles and the published formulas (docs/laws.md) only; nothing here imports
``harness``.  Only numpy and scipy are used.  All quantities are SI.

Conventions
-----------
* Normal impact of a sphere of effective mass ``m`` on a wall: overlap ``alpha > 0`` in contact, the contact
  starts at ``alpha = 0`` with ``alpha_dot = V > 0`` (approach speed) and the equation of motion is
  ``m alpha'' = -F(alpha, alpha')`` with ``F > 0`` repulsive.
* Restitution ``e = (rebound speed) / V`` where the rebound speed is ``-alpha'`` at the end of contact.
* End of contact: ``end="alpha"`` -- the contact ends when alpha returns to 0 (the force may be attractive at the
  end: "Convention A", tension allowed); ``end="force"`` -- the contact ends when the (unclipped) force first
  returns to 0 after loading ("Convention B", no tension; with the force clipped at 0 the sphere then leaves at
  constant speed, so ``e`` is the same as for an engine that clips the force and keeps the contact until alpha=0).
* Tangential (``rigid_sliding``): slip of the contact point ``V_s = V_t - R*omega``; omega is positive when it
  makes the contact point move with ``V_t`` as in rolling (so rolling is ``V_t = R*omega``).

Numerics: ``scipy.integrate.solve_ivp`` (DOP853, rtol = 1e-12, atol = 1e-15 times the velocity / length scale),
terminal events for the end of contact.  Measured accuracy: ~1e-13 relative on the linear spring-dashpot closed
forms, ~1e-11 on the Hertz-type laws whose force has a fractional power of alpha (non-smooth at alpha = 0).

Run ``python tests/oracles.py`` for the self-checks (closed form vs integration, and every published value that
these oracles can settle).
"""

import math

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import brentq, minimize_scalar
from scipy.special import gamma

__all__ = [
    "hertz_elastic",
    "lsd_tension_g",
    "lsd_tension_closed",
    "lsd_notension_e",
    "lsd_notension_t_c",
    "lsd_notension_g",
    "damped_oscillator",
    "normal_impact",
    "kuwabara_kono_e",
    "thornton_e",
    "thornton_yield",
    "thornton_impact",
    "stronge_e",
    "stronge_impact",
    "walton_braun_closed",
    "walton_braun_impact",
    "tsuji_hertz_e",
    "tsuji_hertz_A",
    "thornton_appendix_b_g",
    "rigid_sliding",
    "tsuji_mindlin_sliding_threshold",
]

RTOL = 1e-12
_ATOL_FACTOR = 1e-3  # atol = RTOL * _ATOL_FACTOR * (velocity or length scale)

# Hertz contact-time constant: t_c = C_TC * alpha_max / V, C_TC = 2 int_0^1 dx / sqrt(1 - x^(5/2))
C_TC = 2.0 * math.sqrt(math.pi) * gamma(1.4) / gamma(0.9)


def _ppow(x, p):
    """Odd continuation sign(x)|x|^p of x^p, so that a force law stays defined (and continuous) at alpha < 0."""
    return math.copysign(abs(x) ** p, x)


# ----------------------------------------------------------------------------------------------------------------
# Generic integrator
# ----------------------------------------------------------------------------------------------------------------


def _run_phase(force, m, t0, y0, stops, vscale, t_max=None, track=None, chunk0=1e-12):
    """Integrate m a'' = -force(a, a') from (t0, y0) to the first terminal event of ``stops`` (DOP853, rtol 1e-12)."""
    # stops: list of (function(a, v) -> float, direction); track: optional (function(a, v), direction) whose
    # crossings are recorded (non-terminal).  Integration in chunks [t, 2t] (the first ``chunk0`` long), so no time
    # scale is needed in advance and atol on alpha can be 1e-15 * V * t_end; restarting a one-step method at a chunk
    # boundary costs no accuracy.  Returns (t_end, y_end, index of the stop that fired, [OdeSolution], crossings).
    if t_max is None:
        t_max = 1e6

    def rhs(t, y):
        return [y[1], -force(y[0], y[1]) / m]

    events = []
    for f, d in stops:
        def ev(t, y, f=f):
            return f(y[0], y[1])
        ev.terminal = True
        ev.direction = d
        events.append(ev)
    if track is not None:
        ftr, dtr = track

        def evt(t, y):
            return ftr(y[0], y[1])
        evt.terminal = False
        evt.direction = dtr
        events.append(evt)

    t = float(t0)
    y = np.array(y0, dtype=float)
    sols = []
    crossings = []
    span = chunk0
    while True:
        t_end = min(t + span, t_max)
        lscale = vscale * max(t_end, span)
        atol = [RTOL * _ATOL_FACTOR * lscale, RTOL * _ATOL_FACTOR * vscale]
        r = solve_ivp(rhs, (t, t_end), y, method="DOP853", rtol=RTOL, atol=atol, events=events,
                      dense_output=True)
        if r.status < 0:
            raise RuntimeError("solve_ivp failed: " + r.message)
        sols.append(r.sol)
        if track is not None:
            for tc, yc in zip(r.t_events[-1], r.y_events[-1]):
                crossings.append((tc, yc))
        if r.status == 1:
            for i in range(len(stops)):
                if len(r.t_events[i]):
                    return r.t_events[i][0], r.y_events[i][0], i, sols, crossings
        t = r.t[-1]
        y = r.y[:, -1]
        if t >= t_max:
            raise RuntimeError("contact did not end before t_max = %g" % t_max)
        span = max(span, t - t0)  # doubling chunks


def _max_force(force, sols):
    """Maximum of force(alpha(t), alpha'(t)) over the dense outputs ``sols`` (sampled, then refined by Brent)."""
    best = (-math.inf, None, None)
    for sol in sols:
        ts = sol.ts
        fine = np.concatenate([np.linspace(ts[i], ts[i + 1], 9)[:-1] for i in range(len(ts) - 1)] + [ts[-1:]])
        ys = sol(fine)
        fs = np.array([force(a, v) for a, v in zip(ys[0], ys[1])])
        j = int(np.argmax(fs))
        if fs[j] > best[0]:
            lo = fine[max(j - 1, 0)]
            hi = fine[min(j + 1, len(fine) - 1)]
            best = (fs[j], sol, (lo, hi))
    fmax, sol, (lo, hi) = best
    if hi > lo:
        def negf(t):
            a, v = sol(t)
            return -force(a, v)
        r = minimize_scalar(negf, bounds=(lo, hi), method="bounded",
                            options={"xatol": 1e-15 * max(abs(hi), 1e-300)})
        fmax = max(fmax, -r.fun)
    return float(fmax)


def normal_impact(force, m, V, end="alpha", t_max=None):
    """Integrate m alpha'' = -F(alpha, alpha_dot), alpha(0)=0, alpha_dot(0)=V; e = -alpha_dot(t_c)/V (docs/laws.md,
    2.1)."""
    # force(alpha, alpha_dot) returns the UNCLIPPED force (repulsive > 0).  It must accept a slightly negative alpha
    # (evaluated inside the last step): use an odd continuation such as _ppow(a, p) = sign(a)|a|^p.
    # end="alpha": contact ends when alpha returns to 0 (tension allowed); end="force": contact ends when the force
    # first returns to 0 after loading (no tension).  Returns dict(e, t_c, f_max, alpha_max).
    if end == "alpha":
        stop = (lambda a, v: a, -1)
    elif end == "force":
        stop = (lambda a, v: force(a, v), -1)
    else:
        raise ValueError("end must be 'alpha' or 'force'")
    t_c, y_end, _, sols, turns = _run_phase(force, m, 0.0, [0.0, V], [stop], abs(V), t_max=t_max,
                                            track=(lambda a, v: v, -1))
    if turns:
        alpha_max = max(yc[0] for _, yc in turns)
    else:  # no turning point (cannot happen for a repulsive law); fall back on the samples
        alpha_max = max(float(np.max(s(np.linspace(s.ts[0], s.ts[-1], 2001))[0])) for s in sols)
    return dict(e=float(-y_end[1] / V), t_c=float(t_c), f_max=_max_force(force, sols), alpha_max=float(alpha_max))


# ----------------------------------------------------------------------------------------------------------------
# Hertz
# ----------------------------------------------------------------------------------------------------------------


def hertz_elastic(m, R, E_star, V):
    """Elastic Hertz impact: alpha_max=(15mV^2/(16E*sqrtR))^(2/5), F_max=4/3E*sqrtR alpha_max^1.5, t_c=2.94328
    alpha_max/V (docs/laws.md)."""
    alpha_max = (15.0 * m * V ** 2 / (16.0 * E_star * math.sqrt(R))) ** 0.4
    f_max = 4.0 / 3.0 * E_star * math.sqrt(R) * alpha_max ** 1.5
    return dict(alpha_max=alpha_max, f_max=f_max, t_c=C_TC * alpha_max / V)


# ----------------------------------------------------------------------------------------------------------------
# Linear spring-dashpot
# ----------------------------------------------------------------------------------------------------------------


def lsd_tension_g(e):
    """Damping ratio for LSD, Convention A (end at alpha=0, tension): g = -ln e / sqrt(pi^2 + ln^2 e) (docs/laws.md)."""
    if e == 1.0:
        return 0.0
    L = math.log(e)
    return -L / math.sqrt(math.pi ** 2 + L * L)


def lsd_tension_closed(e, k, m):
    """LSD Convention A: e = exp(-g pi/sqrt(1-g^2)) (exact), t_c = pi/(w0 sqrt(1-g^2)), w0 = sqrt(k/m)
    (docs/laws.md)."""
    g = lsd_tension_g(e)
    s = math.sqrt(1.0 - g * g)
    w0 = math.sqrt(k / m)
    return dict(e=math.exp(-g * math.pi / s), t_c=math.pi / (w0 * s))


def lsd_notension_e(g):
    """LSD Convention B (F clipped at 0, end when F=0): Schwager & Poeschel (2007) piecewise e(g) (docs/laws.md)."""
    if g < 0:
        raise ValueError("g must be >= 0")
    if g == 0.0:
        return 1.0
    if g < 1.0:
        s = math.sqrt(1.0 - g * g)
        if g < 1.0 / math.sqrt(2.0):
            phase = math.pi - math.atan(2.0 * g * s / (1.0 - 2.0 * g * g))
        elif g > 1.0 / math.sqrt(2.0):
            phase = math.atan(2.0 * g * s / (2.0 * g * g - 1.0))
        else:
            phase = math.pi / 2.0
        return math.exp(-g / s * phase)
    if g == 1.0:
        return math.exp(-2.0)
    q = g / math.sqrt(g * g - 1.0)
    return math.exp(-q * math.log((q + 1.0) / (q - 1.0)))


def lsd_notension_t_c(g, w0):
    """LSD Conv. B t_c (own derivation): 2 arccos g/(w0 sqrt(1-g^2)); 2/w0 at g=1; 2 arccosh g/(w0 sqrt(g^2-1)) for
    g>1."""
    # Derivation: x = V/w e^{-g w0 t} sin(w t), w = w0 sqrt(1-g^2); w0^2 x + 2 g w0 x' = 0 gives
    # tan(w t) = -2 g sqrt(1-g^2)/(1-2g^2) = -tan(2 arcsin g), i.e. w t_c = pi - 2 arcsin g = 2 arccos g.
    # g = 1: x = V t e^{-w0 t}, force zero at w0 t = 2.  g > 1 (h = sqrt(g^2-1)): e^{2 w0 h t} = ((g+h)/(g-h))^2,
    # w0 h t_c = ln((g+h)/(g-h)) = 2 arccosh g.  In all cases e = exp(-g w0 t_c) (Schwager & Poeschel's e).
    if g < 0:
        raise ValueError("g must be >= 0")
    if g < 1.0:
        return 2.0 * math.acos(g) / (w0 * math.sqrt(1.0 - g * g))
    if g == 1.0:
        return 2.0 / w0
    return 2.0 * math.acosh(g) / (w0 * math.sqrt(g * g - 1.0))


def lsd_notension_g(e):
    """Damping ratio g giving restitution e for LSD Convention B: root of lsd_notension_e(g) = e by brentq
    (docs/laws.md)."""
    if not 0.0 < e <= 1.0:
        raise ValueError("e must be in (0, 1]")
    if e == 1.0:
        return 0.0
    hi = 1.0
    while lsd_notension_e(hi) > e:
        hi *= 2.0
    return brentq(lambda g: lsd_notension_e(g) - e, 0.0, hi, xtol=1e-16, rtol=1e-15, maxiter=500)


def damped_oscillator(V, w0, g, t):
    """Underdamped m x'' + c x' + k x = 0 from x(0) = 0, x'(0) = V (w0 = sqrt(k/m), g = c/(2 m w0) < 1):
    x = V/w_d exp(-g w0 t) sin(w_d t), w_d = w0 sqrt(1 - g^2), and x' (any textbook, e.g. Meirovitch 2001 eq. 2.38)."""
    t = np.asarray(t, dtype=float)
    w_d = w0 * math.sqrt(1.0 - g * g)
    decay = np.exp(-g * w0 * t)
    x = V / w_d * decay * np.sin(w_d * t)
    x_dot = V * decay * (np.cos(w_d * t) - g * w0 / w_d * np.sin(w_d * t))
    return x, x_dot


# ----------------------------------------------------------------------------------------------------------------
# Hertz + viscous damping (normalised problems: m = k = V = 1)
# ----------------------------------------------------------------------------------------------------------------


def kuwabara_kono_e(y, end="alpha"):
    """e of F = k[alpha^1.5 + 1.5 A alpha^0.5 alpha_dot] vs y = A (k/m)^(2/5) V^(1/5): x'' = -x^1.5 - 1.5 y x^0.5 x'
    (docs/laws.md)."""
    # Scaling alpha = alpha0 x, t = (alpha0/V) tau, alpha0 = (m V^2/k)^(2/5) leaves the single parameter y.
    # The docs/laws.md table (y 0.01..1 -> e 0.98288..0.18412) is reproduced with end="alpha" (tension allowed),
    # which is therefore the default; see the self-checks.
    def f(a, v):
        return _ppow(a, 1.5) + 1.5 * y * _ppow(a, 0.5) * v
    return normal_impact(f, 1.0, 1.0, end=end)["e"]


def tsuji_hertz_e(A, end="alpha"):
    """e of F = k alpha^1.5 + A sqrt(m k) alpha^0.25 alpha_dot, velocity independent: x'' = -x^1.5 - A x^0.25 x'
    (docs/laws.md)."""
    # Same scaling as kuwabara_kono_e; the damping coefficient becomes exactly A.
    def f(a, v):
        return _ppow(a, 1.5) + A * _ppow(a, 0.25) * v
    return normal_impact(f, 1.0, 1.0, end=end)["e"]


def tsuji_hertz_A(e, end="alpha"):
    """Inverse of tsuji_hertz_e by brentq: A such that F = k alpha^1.5 + A sqrt(mk) alpha^0.25 alpha_dot gives e
    (docs/laws.md)."""
    if e == 1.0:
        return 0.0
    hi = 1.0
    while tsuji_hertz_e(hi, end) > e:
        hi *= 2.0
    return brentq(lambda A: tsuji_hertz_e(A, end) - e, 0.0, hi, xtol=1e-13, rtol=1e-13)


_APP_B_H = (-6.918798, -16.41105, 146.8049, -796.4559, 2928.711, -7206.864, 11494.29, -11342.18, 6276.757,
            -1489.915)


def thornton_appendix_b_g(e):
    """Thornton et al. (2013) App. B fit: x = sum h_i e^i, g = sqrt(1/[1-(1+e)^2 exp(x)] - 1), c = 2g sqrt(m 2E*a)
    (docs/laws.md)."""
    if e >= 1.0:
        return 0.0
    x = sum(h * e ** (i + 1) for i, h in enumerate(_APP_B_H))
    return math.sqrt(1.0 / (1.0 - (1.0 + e) ** 2 * math.exp(x)) - 1.0)


# ----------------------------------------------------------------------------------------------------------------
# Elastoplastic laws
# ----------------------------------------------------------------------------------------------------------------


def thornton_e(V, V_y):
    """Thornton (1997): e = (6sqrt3/5)^1/2 [1-r^2/6]^1/2 {r/[r+2sqrt(6/5-r^2/5)]}^1/4, r = V_y/V; 1 for V <= V_y
    (docs/laws.md)."""
    if V <= V_y:
        return 1.0
    r = V_y / V
    return (math.sqrt(6.0 * math.sqrt(3.0) / 5.0) * math.sqrt(1.0 - r * r / 6.0)
            * (r / (r + 2.0 * math.sqrt(6.0 / 5.0 - r * r / 5.0))) ** 0.25)


def thornton_yield(p_y, E_star, R, rho):
    """Yield: a_y=pi p_y R/(2E*), alpha_y=(pi p_y/(2E*))^2 R, F_y=pi^3 p_y^3 R^2/(6E*^2), 1/2 m V_y^2 = 2/5 F_y alpha_y
    (docs/laws.md)."""
    a_y = math.pi * p_y * R / (2.0 * E_star)
    alpha_y = (math.pi * p_y / (2.0 * E_star)) ** 2 * R
    F_y = math.pi ** 3 * p_y ** 3 * R ** 2 / (6.0 * E_star ** 2)
    m = 4.0 / 3.0 * math.pi * R ** 3 * rho
    V_y = math.sqrt(2.0 * (0.4 * F_y * alpha_y) / m)
    return dict(alpha_y=alpha_y, F_y=F_y, a_y=a_y, V_y=V_y)


def _yield_from_mass(p_y, E_star, R, m):
    """alpha_y, F_y (docs/laws.md) and V_y from 1/2 m V_y^2 = 2/5 F_y alpha_y for a given mass m."""
    alpha_y = (math.pi * p_y / (2.0 * E_star)) ** 2 * R
    F_y = math.pi ** 3 * p_y ** 3 * R ** 2 / (6.0 * E_star ** 2)
    V_y = math.sqrt(0.8 * F_y * alpha_y / m)
    return alpha_y, F_y, V_y


def _elastoplastic_impact(E_star, R, m, V, alpha_y, plastic_force, unload_params):
    """Hertz loading to alpha_y, plastic_force beyond, turn at alpha'=0, Hertz unloading to F=0 (docs/laws.md, 2.6)."""
    # unload_params(alpha_star, F_star) -> (R_p, alpha_p), only called after yield.  Loading and unloading are
    # separate solve_ivp phases; the yield point is a phase boundary too, so that no kink sits inside a step.
    k = 4.0 / 3.0 * E_star * math.sqrt(R)

    def hertz(a, v):
        return k * _ppow(a, 1.5)

    turn = (lambda a, v: v, -1)
    # phase 1: elastic loading until yield or turning point
    t1, y1, which, _, _ = _run_phase(hertz, m, 0.0, [0.0, V], [(lambda a, v: a - alpha_y, +1), turn], V)
    yielded = which == 0
    if yielded:
        # phase 2: plastic loading until the turning point
        t2, y2, _, _, _ = _run_phase(plastic_force, m, t1, y1, [turn], V, chunk0=t1)
        alpha_star = y2[0]
        F_star = plastic_force(alpha_star, 0.0)
        R_p, alpha_p = unload_params(alpha_star, F_star)
    else:
        t2, y2 = t1, y1
        alpha_star = y2[0]
        F_star = hertz(alpha_star, 0.0)
        R_p, alpha_p = R, 0.0
    kp = 4.0 / 3.0 * E_star * math.sqrt(R_p)

    def unload(a, v):
        return kp * _ppow(a - alpha_p, 1.5)

    # phase 3: unloading until F = 0, i.e. alpha = alpha_p (same event, better conditioned)
    t3, y3, _, _, _ = _run_phase(unload, m, t2, [y2[0], 0.0], [(lambda a, v: a - alpha_p, -1)], V, chunk0=t2)
    return dict(e=float(-y3[1] / V), t_c=float(t3), f_max=float(F_star), alpha_max=float(alpha_star))


def thornton_impact(p_y, E_star, R, m, V):
    """Thornton (1997) law integrated: Hertz, then F=F_y+pi p_y R(alpha-alpha_y), unload
    4/3E*sqrt(R_p)(alpha-alpha_p)^1.5 (docs/laws.md)."""
    alpha_y, F_y, _ = _yield_from_mass(p_y, E_star, R, m)
    kpl = math.pi * p_y * R

    def plastic(a, v):
        return F_y + kpl * (a - alpha_y)

    def unload_params(alpha_star, F_star):
        a2 = R * alpha_star  # = (2F* + F_y)/(2 pi p_y)
        a_star = math.sqrt(a2)
        R_p = 4.0 * E_star * a_star ** 3 / (3.0 * F_star)
        return R_p, alpha_star - a2 / R_p

    return _elastoplastic_impact(E_star, R, m, V, alpha_y, plastic, unload_params)


def stronge_e(V, V_y):
    """Stronge reconstruction: x = sqrt(1 + 1.6 (V^2/V_y^2 - 1)), e = x^(3/4) V_y/V; 1 for V <= V_y (docs/laws.md)."""
    if V <= V_y:
        return 1.0
    x = math.sqrt(1.0 + 1.6 * (V * V / (V_y * V_y) - 1.0))
    return x ** 0.75 * V_y / V


def stronge_impact(p_y, E_star, R, m, V):
    """Stronge reconstruction integrated: Hertz to alpha_y, F=F_y(2alpha/alpha_y-1), Hertz unload with R_c=R
    sqrt(F_c/F_y) (docs/laws.md)."""
    alpha_y, F_y, _ = _yield_from_mass(p_y, E_star, R, m)

    def plastic(a, v):
        return F_y * (2.0 * a / alpha_y - 1.0)

    def unload_params(alpha_c, F_c):
        R_c = R * math.sqrt(F_c / F_y)  # = 4 E* a_c^3/(3 F_c), a_c = a_y sqrt(F_c/F_y)
        delta_c = (F_c / (4.0 / 3.0 * E_star * math.sqrt(R_c))) ** (2.0 / 3.0)
        return R_c, alpha_c - delta_c

    return _elastoplastic_impact(E_star, R, m, V, alpha_y, plastic, unload_params)


def walton_braun_closed(K1, e, m, V):
    """Walton-Braun: e = sqrt(K1/K2) (K2 = K1/e^2), F_max = V sqrt(m K1), t_c = (pi/2) sqrt(m/K1)(1+e)
    (docs/laws.md)."""
    return dict(e=e, f_max=V * math.sqrt(m * K1), t_c=0.5 * math.pi * math.sqrt(m / K1) * (1.0 + e))


def walton_braun_impact(K1, e, m, V):
    """Walton-Braun integrated: load F=K1 alpha to alpha'=0, unload F=K2(alpha-alpha0), alpha0=alpha_max(1-K1/K2),
    K2=K1/e^2 (docs/laws.md)."""
    K2 = K1 / e ** 2
    t1, y1, _, _, _ = _run_phase(lambda a, v: K1 * a, m, 0.0, [0.0, V], [(lambda a, v: v, -1)], V)
    amax = y1[0]
    a0 = amax * (1.0 - K1 / K2)
    t2, y2, _, _, _ = _run_phase(lambda a, v: K2 * (a - a0), m, t1, [amax, 0.0], [(lambda a, v: a - a0, -1)], V,
                                 chunk0=t1)
    return dict(e=float(-y2[1] / V), t_c=float(t2), f_max=float(K1 * amax), alpha_max=float(amax))


# ----------------------------------------------------------------------------------------------------------------
# Rigid-body tangential oracle
# ----------------------------------------------------------------------------------------------------------------


def rigid_sliding(mu, e, V_n, V_t, R, omega0=0.0):
    """Rigid sphere sliding throughout: v_t1 = V_t - mu(1+e)V_n, R omega1 = R omega0 + 5/2 mu(1+e)V_n (docs/laws.md)."""
    # Normal impulse m(1+e)V_n; friction impulse mu m (1+e) V_n opposing the slip V_s = V_t - R omega; its moment
    # about the centre changes R omega by (m R^2/I) = 5/2 times the same amount in the direction that reduces slip.
    # Raises ValueError when the slip would reverse during the impact (sliding is then not "throughout").
    V_s0 = V_t - R * omega0
    if V_s0 == 0.0:
        raise ValueError("no initial slip: the sphere does not slide")
    sgn = math.copysign(1.0, V_s0)
    dv = mu * (1.0 + e) * V_n
    V_s1 = V_s0 - sgn * 3.5 * dv
    if sgn * V_s1 < 0.0:
        raise ValueError("slip reverses: tan(theta) below 3.5 mu (1+e), not sliding throughout")
    v_t1 = V_t - sgn * dv
    omega1 = omega0 + sgn * 2.5 * dv / R
    return dict(v_t1=v_t1, omega1=omega1)


def rigid_sliding_pair(mu, e, V_n, V_s, m1, R1, m2, R2):
    """Two free solid spheres sliding throughout: J_n = m*(1+e)V_n, 1/m* = 1/m1 + 1/m2; J = -mu J_n sgn(V_s) on the
    projectile (dv1 = J/m1, d omega1 = -R1 J/I1) and -J on the target (dv2 = -J/m2, d omega2 = -R2 J/I2), I = 2/5 m
    R^2."""
    # Frame: the projectile above the target, the line of centres along z; V_s = (v1_t - v2_t) - (R1 w1 + R2 w2) is
    # the slip of the projectile's contact point (at -R1 z) over the target's (at +R2 z); an impulse J x on the
    # projectile there has the moment (-R1 z) x (J x) = -R1 J y, and -J x on the target at +R2 z has -R2 J y.
    # Raises ValueError when the slip would reverse during the impact (sliding is then not "throughout").
    if V_s == 0.0:
        raise ValueError("no initial slip: the spheres do not slide")
    I1, I2 = 0.4 * m1 * R1 ** 2, 0.4 * m2 * R2 ** 2
    J_n = (1.0 + e) * V_n / (1.0 / m1 + 1.0 / m2)
    J = -mu * J_n * math.copysign(1.0, V_s)
    V_s1 = V_s + J * (1.0 / m1 + 1.0 / m2 + R1 ** 2 / I1 + R2 ** 2 / I2)
    if V_s1 * V_s < 0.0:
        raise ValueError("slip reverses: not sliding throughout")
    return dict(dv1=J / m1, domega1=-R1 * J / I1, dv2=-J / m2, domega2=-R2 * J / I2)


def tsuji_mindlin_sliding_threshold(A, kappa):
    """Psi1* from which Hertz + Tsuji dashpot (no tension) under Mindlin's 8G*a with the eq. 18b rescale slides
    throughout when only the spring's Coulomb test counts: max over unloading of [7 J + 2 (F' - F a'/a)/k_t]/(1 + e)."""
    # Rigid sliding throughout leaves the normal motion alone: x'' = -F, F = x^1.5 + A x^0.25 x' (tsuji_hertz_e's
    # scaling, x(0) = 0, x'(0) = 1, impulse J = int F), and the slip V_s = V_si - 7/2 mu J. A spring on the cone
    # (|F_s| = mu F) stays there while it shrinks no faster than the cone: k_t V_s + mu F a'/a >= mu F' (the rescale
    # F_s a'/a while a shrinks), k_t = 8 G* a = 3/2 kappa x^0.5 in these units. Returns (threshold, achieved e).
    def force(x, v):
        return _ppow(x, 1.5) + A * _ppow(x, 0.25) * v

    def rhs(_, y):
        f = force(y[0], y[1])
        return [y[1], -f, f]

    def release(_, y):
        return force(y[0], y[1]) if y[1] < 0.0 else 1.0
    release.terminal, release.direction = True, -1
    sol = solve_ivp(rhs, (0.0, 50.0), [0.0, 1.0, 0.0], method="DOP853", rtol=RTOL, atol=1e-15, events=release,
                    dense_output=True, first_step=1e-9)
    t_end, e = sol.t_events[0][0], -sol.y_events[0][0][1]

    def needed(t):
        x, v, impulse = sol.sol(t)
        f = force(x, v)
        rate = 1.5 * x ** 0.5 * v + A * (0.25 * x ** -0.75 * v * v - x ** 0.25 * f)
        return (7.0 * impulse + 2.0 * (rate - f * v / (2.0 * x)) / (1.5 * kappa * math.sqrt(x))) / (1.0 + e)

    ts = np.linspace(0.0, t_end, 20001)
    grid = ts[sol.sol(ts)[1] < 0.0]
    values = np.array([needed(t) for t in grid])
    i = int(np.argmax(values))
    lo, hi = grid[max(i - 1, 0)], grid[min(i + 1, len(grid) - 1)]
    best = minimize_scalar(lambda t: -needed(t), bounds=(lo, hi), method="bounded", options={"xatol": 1e-14})
    return float(max(values[i], -best.fun)), float(e)


# ----------------------------------------------------------------------------------------------------------------
# Self-checks
# ----------------------------------------------------------------------------------------------------------------

if __name__ == "__main__":
    import sys

    failures = []
    discrepancies = []

    def check(label, got, want, tol, rel=True):
        """Hard check of an oracle (closed form vs integration, identity): counted as a failure if it misses."""
        err = abs(got - want) / (abs(want) if rel and want != 0 else 1.0)
        ok = err <= tol
        print("  [%s] %-62s got %-.10g want %-.10g  (%s err %.1e, tol %.0e)"
              % ("ok" if ok else "FAIL", label, got, want, "rel" if rel else "abs", err, tol))
        if not ok:
            failures.append(label)
        return ok

    def claim(label, got, stated, tol, rel=False):
        """A number stated in the literature (as docs/laws.md quotes it) compared with the oracle: a miss is reported as
        a discrepancy."""
        err = abs(got - stated) / (abs(stated) if rel else 1.0)
        ok = err <= tol
        print("  [%s] %-62s oracle %-.6g stated %-.6g  (%s diff %.1e, tol %.0e)"
              % ("ok" if ok else "DISCREPANCY", label, got, stated, "rel" if rel else "abs", err, tol))
        if not ok:
            discrepancies.append("%s: oracle %.6g, stated %.6g" % (label, got, stated))
        return ok

    # sample material: glass-like sphere, same-material wall
    R, E, nu, rho = 5e-3, 70e9, 0.3, 2650.0
    E_star = E / (2.0 * (1.0 - nu ** 2))
    m = 4.0 / 3.0 * math.pi * R ** 3 * rho
    k_h = 4.0 / 3.0 * E_star * math.sqrt(R)

    def hertz_force(a, v):
        return k_h * _ppow(a, 1.5)

    print("docs/laws.md: kappa, chi")
    claim("kappa = 2(1-nu)/(2-nu) at nu=0.3", 2 * (1 - nu) / (2 - nu), 0.8235, 5e-5)
    claim("chi = 3.5(1-nu)/(2-nu) at nu=0.3", 3.5 * (1 - nu) / (2 - nu), 1.4412, 5e-5)
    chi = 3.5 * (1 - nu) / (2 - nu)
    claim("Maw 4 chi - 1", 4 * chi - 1, 4.765, 5e-4)

    print("docs/laws.md: Hertz elastic impact")
    claim("t_c constant 2 sqrt(pi) G(7/5)/G(9/10)", C_TC, 2.94328, 5e-6)
    claim("2.94328 (15/16)^(2/5) = 2.86827", C_TC * (15.0 / 16.0) ** 0.4, 2.86827, 5e-6)
    for V in (0.1, 1.0, 10.0):
        h = hertz_elastic(m, R, E_star, V)
        n = normal_impact(hertz_force, m, V, end="alpha")
        check("hertz V=%g alpha_max closed vs ODE" % V, n["alpha_max"], h["alpha_max"], 1e-10)
        check("hertz V=%g f_max closed vs ODE" % V, n["f_max"], h["f_max"], 1e-10)
        check("hertz V=%g t_c closed vs ODE" % V, n["t_c"], h["t_c"], 1e-10)
        check("hertz V=%g e = 1" % V, n["e"], 1.0, 1e-10)
        check("hertz V=%g t_c = 2.86827 (m^2/(R E*^2 V))^(1/5)" % V,
              2.86827 * (m * m / (R * E_star ** 2 * V)) ** 0.2, h["t_c"], 2e-6)
        nf = normal_impact(hertz_force, m, V, end="force")
        check("hertz V=%g end=force same t_c" % V, nf["t_c"], h["t_c"], 1e-10)

    print("docs/laws.md: LSD Convention A (tension, end at alpha=0)")
    k_l, m_l = 2.0e5, 1.3e-3
    w0 = math.sqrt(k_l / m_l)
    for e in (0.95, 0.9, 0.7, 0.5, 0.3, 0.1, 0.01):
        g = lsd_tension_g(e)
        c = 2.0 * g * math.sqrt(m_l * k_l)
        cl = lsd_tension_closed(e, k_l, m_l)
        check("LSD-A e=%g: closed e equals target" % e, cl["e"], e, 1e-13)
        n = normal_impact(lambda a, v: k_l * a + c * v, m_l, 0.7, end="alpha")
        check("LSD-A e=%g: ODE e" % e, n["e"], cl["e"], 1e-9)
        check("LSD-A e=%g: ODE t_c" % e, n["t_c"], cl["t_c"], 1e-9)
        # f_max: force k x + c x' is maximal where x'' ... compare with a brute-force dense maximum
        s = math.sqrt(1 - g * g)
        w = w0 * s
        ts = np.linspace(0.0, cl["t_c"], 200001)
        xs = 0.7 / w * np.exp(-g * w0 * ts) * np.sin(w * ts)
        vs = 0.7 * np.exp(-g * w0 * ts) * (np.cos(w * ts) - g * w0 / w * np.sin(w * ts))
        check("LSD-A e=%g: ODE f_max vs analytic sampling" % e, n["f_max"], float(np.max(k_l * xs + c * vs)), 1e-8)

    print("docs/laws.md: LSD Convention B (no tension), Schwager & Poeschel")
    for g in (0.0, 0.05, 0.2, 0.5, 0.7, 1 / math.sqrt(2), 0.72, 0.9, 0.99, 1.0, 1.01, 1.5, 3.0, 10.0):
        c = 2.0 * g * math.sqrt(m_l * k_l)
        n = normal_impact(lambda a, v: k_l * a + c * v, m_l, 0.7, end="force")
        eB = lsd_notension_e(g)
        tB = lsd_notension_t_c(g, w0)
        check("LSD-B g=%.6g: S&P e vs ODE" % g, n["e"], eB, 1e-9)
        check("LSD-B g=%.6g: t_c (own closed form) vs ODE" % g, n["t_c"], tB, 1e-9)
        check("LSD-B g=%.6g: e = exp(-g w0 t_c)" % g, math.exp(-g * w0 * tB), eB, 1e-12)
    # continuity of the piecewise forms
    for g0 in (1 / math.sqrt(2), 1.0):
        check("LSD-B e continuous at g=%.6g" % g0, lsd_notension_e(g0 * (1 + 1e-7)), lsd_notension_e(g0 * (1 - 1e-7)),
              1e-6)
    for e in (0.99, 0.9, 0.5, 0.2, 0.1, 0.05, 0.01):
        check("LSD-B g(e) round trip e=%g" % e, lsd_notension_e(lsd_notension_g(e)), e, 1e-12)
    for target, stated in zip((0.9, 0.7, 0.5, 0.3, 0.1), (0.902, 0.718, 0.550, 0.397, 0.253)):
        claim("LSD Conv-A g with clipping, target %g" % target, lsd_notension_e(lsd_tension_g(target)), stated, 5e-4)

    print("docs/laws.md: Hertz + Tsuji damping")
    # velocity independence, physical units vs normalised
    A_test = 0.4
    for V in (0.05, 1.0, 20.0):
        for end in ("alpha", "force"):
            n = normal_impact(lambda a, v: k_h * _ppow(a, 1.5) + A_test * math.sqrt(m * k_h) * _ppow(a, 0.25) * v,
                              m, V, end=end)
            check("Tsuji A=%g V=%g end=%s: physical = normalised" % (A_test, V, end), n["e"],
                  tsuji_hertz_e(A_test, end), 1e-9)
    tsuji_A_exact = {}
    for e, A_stated in zip((0.9, 0.7, 0.5, 0.3, 0.1), (0.07495, 0.25225, 0.48177, 0.80019, 1.32186)):
        beta = lsd_tension_g(e)
        A5 = math.sqrt(5.0) * beta
        check("Tsuji end=alpha, A = sqrt5 beta reproduces e=%g" % e, tsuji_hertz_e(A5, "alpha"), e, 1e-9)
        A_ex = tsuji_hertz_A(e, "alpha")
        tsuji_A_exact[e] = A_ex
        claim("Tsuji exact A (end=alpha) for e=%g" % e, A_ex, A_stated, 5e-6)
    for e, stated in zip((0.1, 0.3, 0.5, 0.7, 0.9), (0.2527, 0.3971, 0.5503, 0.7182, 0.9020)):
        claim("LIGGGHTS hertz limitForce (sqrt5 beta, no tension) e=%g" % e,
              tsuji_hertz_e(math.sqrt(5.0) * lsd_tension_g(e), "force"), stated, 5e-5)
    # observation (not in the literature quoted): Hertz + alpha^(1/4) damping with A = sqrt5 g has exactly the e of the
    # LSD with damping ratio g, under BOTH end conventions (hence "sqrt5 beta is exact" and LIGGGHTS limitForce = LSD
    # clipped)
    for A in (0.05, 0.3, 1.0, 2.0, 3.0, 6.0):
        g = A / math.sqrt(5.0)
        if g < 1.0:
            check("Tsuji(A) end=alpha = LSD-A e(g=A/sqrt5), A=%g" % A, tsuji_hertz_e(A, "alpha"),
                  math.exp(-g * math.pi / math.sqrt(1.0 - g * g)), 1e-9)
        check("Tsuji(A) end=force = LSD-B e(g=A/sqrt5), A=%g" % A, tsuji_hertz_e(A, "force"), lsd_notension_e(g), 1e-9)
    print("docs/laws.md: Thornton Appendix B (no tension), A = sqrt(6) g")
    for e, g_stated in zip((0.9, 0.7, 0.5, 0.3, 0.1), (0.03131, 0.11168, 0.23302, 0.45362, 1.13425)):
        claim("App. B g(%g)" % e, thornton_appendix_b_g(e), g_stated, 5e-6)
    worst = 0.0
    for e in np.round(np.arange(0.05, 0.951, 0.05), 2):
        got = tsuji_hertz_e(math.sqrt(6.0) * thornton_appendix_b_g(e), "force")
        worst = max(worst, abs(got - e)) if e <= 0.9 + 1e-9 else worst
        print("    App. B target e=%.2f -> achieved (no tension) %.6f  diff %+.2e" % (e, got, got - e))
    claim("App. B max |achieved - target| for e in 0.05..0.9 (<= 3e-4)", worst, 0.0, 3.5e-4)
    claim("App. B input 0.99 achieved (YADE: 0.979)",
          tsuji_hertz_e(math.sqrt(6.0) * thornton_appendix_b_g(0.99), "force"), 0.979, 5e-4)
    # the engine form c_n = 2 sqrt(5/6) beta sqrt(S_n m), S_n = 2E*a = 1.5 k sqrt(alpha)
    # -> A = 2 sqrt(5/6) sqrt(1.5) beta
    check("engine form 2 sqrt(5/6) sqrt(3/2) = sqrt5", 2.0 * math.sqrt(5.0 / 6.0) * math.sqrt(1.5), math.sqrt(5.0),
          1e-15)

    print("docs/laws.md: Hertz + Kuwabara-Kono")
    ys = (0.01, 0.05, 0.1, 0.2, 0.3, 0.5, 0.75, 1.0)
    es = (0.98288, 0.91777, 0.84334, 0.71404, 0.60595, 0.43690, 0.28739, 0.18412)
    kk = {}
    for end in ("alpha", "force"):
        kk[end] = [kuwabara_kono_e(y, end) for y in ys]
        dmax = max(abs(a - b) for a, b in zip(kk[end], es))
        print("    end=%-5s e(y) = %s   max |diff| vs table = %.2e"
              % (end, " ".join("%.5f" % v for v in kk[end]), dmax))
    for y, e_stated, e_a in zip(ys, es, kk["alpha"]):
        claim("KK table (end=alpha) y=%g" % y, e_a, e_stated, 5e-6)
    # physical units: e depends only on y
    A_kk = 2e-6
    for V in (0.3, 3.0):
        y = A_kk * (k_h / m) ** 0.4 * V ** 0.2
        n = normal_impact(lambda a, v: k_h * (_ppow(a, 1.5) + 1.5 * A_kk * _ppow(a, 0.5) * v), m, V, end="alpha")
        check("KK physical V=%g (y=%.4f) = normalised" % (V, y), n["e"], kuwabara_kono_e(y), 1e-9)
    # small-x series e = 1 - 1.15344 x + 0.79826 x^2, x = 1.5 y.  First order exactly: 1 - e = Delta E / (m V^2)
    # with Delta E = int c v^2 dt on the elastic path -> coefficient of x = 2 int_0^xm x^0.5 sqrt(1 - 0.8 x^2.5) dx
    from scipy.integrate import quad
    c1 = 2.0 * quad(lambda x: x ** 0.5 * math.sqrt(max(1.0 - 0.8 * x ** 2.5, 0.0)), 0.0, 1.25 ** 0.4,
                    epsabs=1e-14, epsrel=1e-14)[0]
    claim("KK small-x series coefficient of x (exact quadrature)", c1, 1.15344, 5e-6)
    # then the x^2 coefficient from a fit on small y
    for end in ("alpha", "force"):
        yy = np.array([1e-4, 2e-4, 4e-4, 8e-4, 1.6e-3, 3.2e-3])
        xx = 1.5 * yy
        ee = np.array([kuwabara_kono_e(y, end) for y in yy])
        coef = np.polyfit(xx, (1.0 - ee) / xx, 2)  # (1-e)/x = c1 - c2 x + ...
        print("    KK small-x fit end=%s: e = 1 - %.5f x + %.5f x^2" % (end, coef[2], -coef[1]))
        if end == "alpha":
            check("KK small-x fitted coefficient of x = quadrature", coef[2], c1, 2e-5)
            claim("KK small-x series coefficient of x^2", -coef[1], 0.79826, 5e-3)

    print("docs/laws.md: Walton-Braun")
    K1 = 3.0e5
    for e in (0.9, 0.5, 0.1):
        cl = walton_braun_closed(K1, e, m, 1.3)
        n = walton_braun_impact(K1, e, m, 1.3)
        check("WB e=%g: e" % e, n["e"], cl["e"], 1e-10)
        check("WB e=%g: f_max" % e, n["f_max"], cl["f_max"], 1e-10)
        check("WB e=%g: t_c" % e, n["t_c"], cl["t_c"], 1e-10)

    print("docs/laws.md: Thornton elastoplastic")
    p_y = 1.0e9
    ty = thornton_yield(p_y, E_star, R, rho)
    check("V_y energy balance = 1.5605 sqrt(p_y^5/(E*^4 rho))", ty["V_y"],
          1.5605 * math.sqrt(p_y ** 5 / (E_star ** 4 * rho)), 5e-5)
    check("pi^2/sqrt40 = 1.5605", math.pi ** 2 / math.sqrt(40.0), 1.5605, 5e-5)
    check("a_y^2 = R alpha_y", ty["a_y"] ** 2, R * ty["alpha_y"], 1e-14)
    check("F_y = Hertz force at alpha_y", ty["F_y"], k_h * ty["alpha_y"] ** 1.5, 1e-14)
    check("pi p_y R = Hertz tangent stiffness at yield (no kink)", math.pi * p_y * R,
          1.5 * k_h * math.sqrt(ty["alpha_y"]), 1e-14)
    V_y = ty["V_y"]
    for ratio in (0.5, 1.0 + 1e-9, 1.2, 2.0, 5.0, 20.0, 100.0, 1000.0):
        V = ratio * V_y
        n = thornton_impact(p_y, E_star, R, m, V)
        check("Thornton V/V_y=%g: ODE e vs closed form" % ratio, n["e"], thornton_e(V, V_y), 1e-9)
    check("Thornton large-V limit 1.185 r^(1/4) (r=1e-8)", thornton_e(1e8, 1.0) / 1e-2,
          math.sqrt(6 * math.sqrt(3) / 5) * (1 / (2 * math.sqrt(1.2))) ** 0.25, 1e-7)
    claim("Thornton prefactor (6sqrt3/5)^1/2 (1/(2sqrt(6/5)))^1/4",
          math.sqrt(6 * math.sqrt(3) / 5) * (1 / (2 * math.sqrt(1.2))) ** 0.25, 1.185, 5e-4)
    for e, r_stated in zip((0.9, 0.7, 0.5, 0.3, 0.1), (0.41421, 0.12952, 0.032171, 4.1157e-3, 5.0716e-5)):
        r = brentq(lambda r: thornton_e(1.0, r) - e, 1e-14, 1.0 - 1e-15, xtol=1e-18, rtol=1e-14)
        claim("Thornton r = V_y/V for e=%g" % e, r, r_stated, 5e-5, rel=True)
        Vs = 1.0
        p = (r * r * Vs * Vs * E_star ** 4 * rho * 40.0 / math.pi ** 4) ** 0.2
        check("Thornton p_y formula e=%g gives V_y/V = r" % e, thornton_yield(p, E_star, R, rho)["V_y"] / Vs, r,
              1e-12)

    print("docs/laws.md: Stronge reconstruction")
    for ratio in (0.5, 1.2, 2.0, 5.0, 20.0, 100.0, 1000.0):
        V = ratio * V_y
        n = stronge_impact(p_y, E_star, R, m, V)
        check("Stronge V/V_y=%g: ODE e vs closed form" % ratio, n["e"], stronge_e(V, V_y), 1e-9)
        if ratio > 1:
            x = math.sqrt(1 + 1.6 * (ratio ** 2 - 1))
            check("Stronge V/V_y=%g: f_max = x F_y" % ratio, n["f_max"], x * ty["F_y"], 1e-9)

    print("docs/laws.md: ratios to elastic Hertz at the same speed (R=5mm, E=70GPa, nu=0.3, rho=2650, V=1)")
    V = 1.0
    hz = hertz_elastic(m, R, E_star, V)
    table = {0.9: ((1.018, 0.905), (0.971, 0.941), (1.011, 0.942)),
             0.5: ((1.236, 0.551), (0.877, 0.737), (1.093, 0.756)),
             0.1: ((3.147, 0.152), (0.676, 1.245), (1.511, 0.785))}
    for e, (th_s, hnt_s, ts_s) in table.items():
        r = brentq(lambda r: thornton_e(1.0, r) - e, 1e-14, 1.0 - 1e-15, xtol=1e-18, rtol=1e-14)
        p = (r * r * V * V * E_star ** 4 * rho * 40.0 / math.pi ** 4) ** 0.2
        th = thornton_impact(p, E_star, R, m, V)
        check("ratio table: Thornton calibrated e=%g achieved" % e, th["e"], e, 1e-8)
        claim("Thornton e=%g t_c/t_H" % e, th["t_c"] / hz["t_c"], th_s[0], 1e-3)
        claim("Thornton e=%g F/F_H" % e, th["f_max"] / hz["f_max"], th_s[1], 1e-3)
        A_nt = tsuji_hertz_A(e, "force")
        hn = normal_impact(lambda a, v: k_h * _ppow(a, 1.5) + A_nt * math.sqrt(m * k_h) * _ppow(a, 0.25) * v,
                           m, V, end="force")
        claim("Hertz no-tension (exact A) e=%g t_c/t_H" % e, hn["t_c"] / hz["t_c"], hnt_s[0], 1e-3)
        claim("Hertz no-tension (exact A) e=%g F/F_H" % e, hn["f_max"] / hz["f_max"], hnt_s[1], 1e-3)
        A_t = math.sqrt(5.0) * lsd_tension_g(e)
        tt = normal_impact(lambda a, v: k_h * _ppow(a, 1.5) + A_t * math.sqrt(m * k_h) * _ppow(a, 0.25) * v,
                           m, V, end="alpha")
        claim("Tsuji end=alpha e=%g t_c/t_H" % e, tt["t_c"] / hz["t_c"], ts_s[0], 1e-3)
        claim("Tsuji end=alpha e=%g F/F_H" % e, tt["f_max"] / hz["f_max"], ts_s[1], 1e-3)
        # provisional PLS: Walton-Braun with K1 = pi p_y R, K2 = K1/e^2 vs Thornton
        wb = walton_braun_closed(math.pi * p * R, e, m, V)
        dF = wb["f_max"] / th["f_max"] - 1
        dt = wb["t_c"] / th["t_c"] - 1
        print("    PLS(WB, K1=pi p_y R) e=%g: F/F_Thornton-1 = %+.3f, t_c/t_Thornton-1 = %+.3f" % (e, dF, dt))
        claim("PLS within 2-13%% of Thornton F, e=%g (|diff| < 0.135)" % e, max(abs(dF) - 0.135, 0.0), 0.0, 1e-12)
        claim("PLS within 2-13%% of Thornton t_c, e=%g (|diff| < 0.135)" % e, max(abs(dt) - 0.135, 0.0), 0.0, 1e-12)

    print("docs/laws.md: rigid sliding throughout")
    mu, e, Vn, Vt = 0.3, 0.5, 1.0, 3.0
    kappa = 2 * (1 - nu) / (2 - nu)
    rs = rigid_sliding(mu, e, Vn, Vt, R)
    check("v_t1 = V_t - mu(1+e)V_n", rs["v_t1"], Vt - mu * (1 + e) * Vn, 1e-15)
    Omega_star = R * rs["omega1"] / (mu * (1 + e) * Vn)
    check("Omega* = 5/2", Omega_star, 2.5, 1e-14)
    Psi1s = kappa * Vt / (mu * Vn) / (1 + e)
    Vsr = rs["v_t1"] - R * rs["omega1"]
    Psi2s = kappa * Vsr / (mu * Vn) / (1 + e)
    check("Psi2* = Psi1* - 2 chi", Psi2s, Psi1s - 2 * chi, 1e-13)
    check("e_t = 5/7 + 2/7 Psi2*/Psi1*", rs["v_t1"] / Vt, 5 / 7 + 2 / 7 * Psi2s / Psi1s, 1e-14)
    check("R omega_r = 5/2 (V_ti - V_tr)", R * rs["omega1"], 2.5 * (Vt - rs["v_t1"]), 1e-14)
    # onset: at tan(theta) = 3.5 mu (1+e) the final slip is exactly zero
    rs0 = rigid_sliding(mu, e, Vn, 3.5 * mu * (1 + e) * Vn, R)
    check("onset tan(theta) = 3.5 mu(1+e): final slip 0", rs0["v_t1"] - R * rs0["omega1"], 0.0, 1e-14, rel=False)
    try:
        rigid_sliding(mu, e, Vn, 0.9 * 3.5 * mu * (1 + e) * Vn, R)
        check("below onset raises ValueError", 0.0, 1.0, 0.0)
    except ValueError:
        check("below onset raises ValueError", 1.0, 1.0, 0.0)
    rsw = rigid_sliding(mu, e, Vn, Vt, R, omega0=-50.0)
    check("with initial spin: R omega1 = R omega0 + 5/2 mu(1+e)V_n", R * rsw["omega1"],
          R * -50.0 + 2.5 * mu * (1 + e) * Vn, 1e-14)
    E0 = 0.5 * m * Vt ** 2
    E1 = 0.5 * m * rs["v_t1"] ** 2 + 0.5 * 0.4 * m * R ** 2 * rs["omega1"] ** 2
    check("tangential kinetic energy does not increase", min(E0 - E1, 0.0), 0.0, 0.0, rel=False)

    print()
    print("hard-check failures: %d" % len(failures))
    for f in failures:
        print("  FAIL:", f)
    print("discrepancies with stated values: %d" % len(discrepancies))
    for d in discrepancies:
        print("  ", d)
    sys.exit(1 if failures else 0)
