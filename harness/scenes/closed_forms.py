"""The scenes' closed forms: what a run of each scene must reproduce, each with its equation and source (SI units)."""
import math


def free_fall_height(z0, v0, g, t):
    """z(t) = z0 + v0 t - g t^2/2: uniform acceleration under constant gravity (Newton's second law)."""
    return z0 + v0 * t - 0.5 * g * t * t


def linear_restitution(mass, k_n, c_n):
    """e_n = exp(-pi zeta/sqrt(1 - zeta^2)), zeta = c_n/(2 sqrt(m k_n)): linear spring-dashpot, contact ending at zero
    overlap, no gravity during contact (Schaefer, Dippel & Wolf 1996)."""
    zeta = c_n / (2.0 * math.sqrt(mass * k_n))
    if zeta >= 1.0:
        return 0.0
    return math.exp(-math.pi * zeta / math.sqrt(1.0 - zeta * zeta))


def apex_height(h0, e_n, k):
    """h_k = e_n^(2k) h0: ballistic flight between instantaneous impacts of restitution e_n (Newton 1687, Principia)."""
    return e_n ** (2 * k) * h0


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
