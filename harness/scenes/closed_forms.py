"""The scenes' closed forms: what a run of each scene must reproduce, each with its equation and source (SI units)."""
import math


def free_fall_height(z0, v0, g, t):
    """z(t) = z0 + v0 t - g t^2/2: uniform acceleration under constant gravity (Newton's second law)."""
    return z0 + v0 * t - 0.5 * g * t * t


def linear_bounce_restitution(mass, k_n, c_n, g, v, tension=True):
    """e(v) = v_out/v, m d'' = m g - k_n d - c_n d' from d = 0, d' = v until d = 0: the under-damped linear
    contact with gravity, the ODE's exact solution (Schaefer, Dippel & Wolf 1996 without gravity); without tension it
    ends at k_n d + c_n d' = 0 and the sphere flies to d = 0, v_out^2 = v_1^2 - 2 g d_1 (Schwager & Poeschel 2007)."""
    zeta = c_n / (2.0 * math.sqrt(mass * k_n))
    if zeta >= 1.0:
        return 0.0
    w0 = math.sqrt(k_n / mass)
    a, w_d, d_p = zeta * w0, w0 * math.sqrt(1.0 - zeta * zeta), mass * g / k_n
    b = (v - a * d_p) / w_d

    def overlap(t):
        return d_p + math.exp(-a * t) * (-d_p * math.cos(w_d * t) + b * math.sin(w_d * t))

    def rate(t):
        return math.exp(-a * t) * ((a * d_p + w_d * b) * math.cos(w_d * t) + (w_d * d_p - a * b) * math.sin(w_d * t))

    def leaving(t):
        return overlap(t) if tension else k_n * overlap(t) + c_n * rate(t)
    t_s = first_fall_through_zero(leaving, 2.0 * math.pi / w_d)
    if t_s is None:
        return 0.0
    if tension:
        return -rate(t_s) / v
    out_squared = rate(t_s) ** 2 - 2.0 * g * overlap(t_s)
    return math.sqrt(out_squared) / v if out_squared > 0.0 else 0.0


def first_fall_through_zero(f, span, samples=4096):
    """The first t in (0, span] where f falls through zero (scanned, then bisected to round-off), or None."""
    from scipy.optimize import brentq
    times = [span * (k + 1) / samples for k in range(samples)]
    previous = times[0]
    for t in times[1:]:
        if f(previous) > 0.0 >= f(t):
            return brentq(f, previous, t, xtol=1e-300, rtol=1e-15, maxiter=200)
        previous = t
    return None


def linear_bounce_apex(h0, mass, k_n, c_n, g, k, tension=True):
    """h_k = v_k^2/(2 g), v_k = e(v_(k-1)) v_(k-1), v_0 = sqrt(2 g h0): ballistic flights (Newton 1687) between the
    linear spring-dashpot's contacts under gravity (linear_bounce_restitution)."""
    speed = math.sqrt(2.0 * g * h0)
    for _ in range(k):
        speed *= linear_bounce_restitution(mass, k_n, c_n, g, speed, tension)
    return speed * speed / (2.0 * g)


def slip_end_time(v0, w0, radius, mu, g):
    """t_s = 2 |v0 - R w0|/(7 mu g): solid sphere (I = 2/5 m R^2) sliding under Coulomb friction (Routh 1905)."""
    return 2.0 * abs(v0 - radius * w0) / (7.0 * mu * g)


def rolling_speed(v0, w0, radius):
    """v_f = (5 v0 + 2 R w0)/7: solid sphere (I = 2/5 m R^2) once Coulomb friction has ended its slip (Routh 1905)."""
    return (5.0 * v0 + 2.0 * radius * w0) / 7.0


def hertz_static_overlap(mass, g, E_star, R_star):
    """delta = (3 m g/(4 E* sqrt(R*)))^(2/3): Hertz's F = 4/3 E* R*^1/2 delta^3/2 bearing m g (Johnson 1985)."""
    return (3.0 * mass * g / (4.0 * E_star * math.sqrt(R_star))) ** (2.0 / 3.0)


def linear_static_overlap(mass, g, k_n):
    """delta = m g/k_n: a linear spring F = k_n delta bearing m g (Hooke's law)."""
    return mass * g / k_n


def stack_contact_force(i, mass, g, preload=0.0):
    """F_i = i m g + P: the contact below the i-th of equal spheres from the top of a column at rest, a top wall
    pressing with P (static equilibrium, Newton's first law)."""
    return i * mass * g + preload
