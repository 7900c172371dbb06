"""Calibrations: the model parameter that gives a target normal restitution e_n (docs/laws.md). scipy is imported
where a calibration needs it (it takes 0.3 s to load)."""
import math
from functools import lru_cache

from ..infra.errors import UserError

APPENDIX_B = (-6.918798, -16.41105, 146.8049, -796.4559, 2928.711,
              -7206.864, 11494.29, -11342.18, 6276.757, -1489.915)


def lsd_tension_g(e):
    """g = -ln e / sqrt(pi^2 + ln^2 e): LSD, contact ends at alpha = 0 (docs/laws.md)."""
    return -math.log(e) / math.sqrt(math.pi ** 2 + math.log(e) ** 2)


def lsd_notension_e(g):
    """Schwager & Poeschel (2007) restitution of the LSD with the force clipped at 0 (docs/laws.md)."""
    if g <= 0.0:
        return 1.0
    if g < 1.0 / math.sqrt(2.0):
        w = math.sqrt(1.0 - g * g)
        return math.exp(-g / w * (math.pi - math.atan(2.0 * g * w / (1.0 - 2.0 * g * g))))
    if g < 1.0:
        w = math.sqrt(1.0 - g * g)
        return math.exp(-g / w * math.atan(2.0 * g * w / (2.0 * g * g - 1.0)))
    if g == 1.0:
        return math.exp(-2.0)
    q = g / math.sqrt(g * g - 1.0)
    return math.exp(-q * math.log((q + 1.0) / (q - 1.0)))


@lru_cache(maxsize=None)
def lsd_notension_g(e):
    """Invert Schwager & Poeschel's e(g) numerically (docs/laws.md)."""
    from scipy.optimize import brentq
    if e >= 1.0:
        return 0.0
    return brentq(lambda g: lsd_notension_e(g) - e, 0.0, 50.0, xtol=1e-15, rtol=1e-15)


def lsd_notension_g_bisection(e, low=0.0, high=16.0, tolerance=1e-4, iterations=300):
    """Schwager & Poeschel's e(g) inverted by bisection on [0, 16] until the bracket is at most 1e-4, returning its
    midpoint (g to about 3e-5); e clamped to 0.001, and g = 0 above e = 0.999."""
    e = max(e, 0.001)
    if e > 0.999:
        return 0.0
    g, k = 0.5 * (low + high), 0
    while high - low > tolerance and k <= iterations:
        trial = lsd_notension_e(g) - e
        if (lsd_notension_e(low) - e) * trial < 0.0:
            high = g
        elif trial == 0.0:
            return g
        else:
            low = g
        g, k = 0.5 * (low + high), k + 1
    return g


def thornton_appendix_b_g(e):
    """Thornton et al. (2013) Appendix B: g = sqrt(1/[1 - (1+e)^2 exp(x)] - 1), x = sum h_i e^i (docs/laws.md)."""
    if e >= 1.0:
        return 0.0
    x = sum(h * e ** (i + 1) for i, h in enumerate(APPENDIX_B))
    return math.sqrt(1.0 / (1.0 - (1.0 + e) ** 2 * math.exp(x)) - 1.0)


TSUJI_POLYNOMIAL = (1.2728, -4.2783, 11.087, -22.348, 27.467, -18.022, 4.8218)


def polynomial_tsuji_A(e):
    """A = 1.2728 - 4.2783 e + 11.087 e^2 - 22.348 e^3 + 27.467 e^4 - 18.022 e^5 + 4.8218 e^6, a polynomial fit of A
    against e for Hertz with its dashpot."""
    return sum(c * e ** i for i, c in enumerate(TSUJI_POLYNOMIAL))


def tsuji_tension_A(e):
    """A = sqrt5 beta, beta = -ln e / sqrt(ln^2 e + pi^2): exact for F = k a^3/2 + A sqrt(mk) a^1/4 a' ending at a =
    0."""
    return math.sqrt(5.0) * lsd_tension_g(e)


def _normalised_restitution(rhs_damping, param, end):
    """e of X'' = -X^3/2 - param D(X) X', X(0) = 0, X'(0) = 1, ending at X = 0 or at zero force (no tension)."""
    from scipy.integrate import solve_ivp
    def force(x, v):
        xp = max(x, 0.0)
        return xp ** 1.5 + param * rhs_damping(xp) * v

    def rhs(_, y):
        return (y[1], -force(y[0], y[1]))

    def left(_, y):
        return y[0] if end == "tension" else force(y[0], y[1])
    left.terminal, left.direction = True, -1
    sol = solve_ivp(rhs, (0.0, 50.0), (0.0, 1.0), method="DOP853", events=left, rtol=1e-11, atol=1e-13,
                    first_step=1e-6)
    if len(sol.y_events[0]) == 0:
        return 0.0                # over-damped: it never leaves within the window, e -> 0
    return -sol.y_events[0][0][1]


def _invert(fun, e, lo, hi):
    """The parameter in [lo, hi] with fun(parameter) = e; a target within the ODE tolerance of 1 (e above fun(lo))
    needs no more damping than lo."""
    from scipy.optimize import brentq
    if fun(lo) <= e:
        return lo
    lowest = fun(hi)
    if lowest > e:
        raise UserError(f"e_n {e:g} is below the lowest this damping calibration reaches ({lowest:.3g})")
    return brentq(lambda p: fun(p) - e, lo, hi, xtol=1e-13, rtol=1e-12)


@lru_cache(maxsize=None)
def tsuji_notension_A(e):
    """Exact A for the Tsuji-type Hertz dashpot with the force clipped at 0 (numerical inversion)."""
    if e >= 1.0:
        return 0.0
    return _invert(lambda a: _normalised_restitution(lambda x: x ** 0.25, a, "no-tension"), e, 1e-6, 50.0)


@lru_cache(maxsize=None)
def kuwabara_kono_y(e, end):
    """y = A (k/m)^2/5 V^1/5 that gives e for F = k[a^3/2 + 3/2 A a^1/2 a'] (Zhou et al. 1999; docs/laws.md)."""
    if e >= 1.0:
        return 0.0
    return _invert(lambda y: _normalised_restitution(lambda x: 1.5 * math.sqrt(x), y, end), e, 1e-8, 20.0)


def thornton_restitution(r):
    """Thornton (1997) e(r), r = V_y/V <= 1 (docs/laws.md)."""
    if r >= 1.0:
        return 1.0
    return (math.sqrt(6.0 * math.sqrt(3.0) / 5.0) * math.sqrt(1.0 - r * r / 6.0)
            * (r / (r + 2.0 * math.sqrt(6.0 / 5.0 - r * r / 5.0))) ** 0.25)


def stronge_restitution(r):
    """Provisional Stronge e = x^3/4 V_y/V, x = sqrt(1 + 1.6 (V^2/V_y^2 - 1)), r = V_y/V (docs/laws.md)."""
    if r >= 1.0:
        return 1.0
    x = math.sqrt(1.0 + 1.6 * (1.0 / (r * r) - 1.0))
    return x ** 0.75 * r


@lru_cache(maxsize=None)
def yield_velocity_ratio(e, law):
    """r = V_y/V that gives e for the 'thornton' or 'stronge' plastic law."""
    from scipy.optimize import brentq
    if e >= 1.0:
        return 1.0
    fun = thornton_restitution if law == "thornton" else stronge_restitution
    if fun(math.exp(-100.0)) > e:
        raise UserError(f"e_n {e:g} is below the lowest the {law} law reaches ({fun(math.exp(-100.0)):.3g})")
    log_r = brentq(lambda x: fun(math.exp(x)) - e, -100.0, 0.0, xtol=1e-14, rtol=1e-15)
    return math.exp(log_r)


def yield_pressure(r, speed, E_star, rho):
    """p_y = (r^2 V^2 E*^4 rho 40/pi^4)^1/5, from V_y = pi^2/sqrt40 sqrt(p_y^5/(E*^4 rho)) (docs/laws.md)."""
    return (r * r * speed * speed * E_star ** 4 * rho * 40.0 / math.pi ** 4) ** 0.2


def hertz_equivalent_stiffness(E_star, radius, mass, speed):
    """k_n = 16/15 sqrt(R) E* [15 m V^2/(16 sqrt(R) E*)]^1/5: linear spring with Hertz's peak overlap at V."""
    return (16.0 / 15.0 * math.sqrt(radius) * E_star
            * (15.0 * mass * speed ** 2 / (16.0 * math.sqrt(radius) * E_star)) ** 0.2)


HERTZ_DURATION = 2.0 * math.sqrt(math.pi) * math.gamma(1.4) / math.gamma(0.9) * (15.0 / 16.0) ** 0.4   # 2.868...


def hertz_contact_time(E_star, radius, mass, speed):
    """t_H = 2 sqrt(pi) G(7/5)/G(9/10) (15/16)^2/5 (m^2/(R E*^2 V))^1/5 = 2.8683 (...)^1/5: elastic Hertz (Johnson
    1985)."""
    return HERTZ_DURATION * (mass ** 2 / (radius * E_star ** 2 * speed)) ** 0.2


def hertz_duration_stiffness(E_star, radius, mass, speed):
    """k_n = m (pi/t_H)^2: a linear spring whose undamped contact lasts as long as an elastic Hertz impact at V
    (the paper's equal-collision-time calibration of the linear spring-dashpot)."""
    return mass * (math.pi / hertz_contact_time(E_star, radius, mass, speed)) ** 2

