"""The scenes' closed forms against independent calculations: scipy integration and root finding, numpy."""
import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

from harness.scenes import closed_forms as cf

G = 9.81


@pytest.mark.parametrize("z0, v0", [(0.1, 0.0), (2.0, 3.5), (-0.3, -1.2)])
def test_free_fall_matches_twice_integrated_gravity(z0, v0):
    """z(t) from integrating the constant acceleration -g twice (numpy polynomials), within 1e-9."""
    z = np.polynomial.Polynomial([-G]).integ(k=v0).integ(k=z0)
    for t in np.linspace(0.0, 1.5, 16):
        assert cf.free_fall_height(z0, v0, G, t) == pytest.approx(z(t), rel=1e-9, abs=1e-12)


def linear_contact_under_gravity(mass, k_n, c_n, g, speed, tension):
    """Rebound over approach speed of m d'' = m g - k d - c d' from d = 0, d' = speed: left where d returns to 0
    (tension) or where k d + c d' falls to 0, then in free flight m d'' = m g until d = 0 (scipy, events)."""
    def contact(t, y):
        return [y[1], g - (k_n * y[0] + c_n * y[1]) / mass]

    def leaves(t, y):
        return y[0] if tension else k_n * y[0] + c_n * y[1]
    leaves.terminal, leaves.direction = True, -1
    period = 2.0 * math.pi * math.sqrt(mass / k_n)
    done = solve_ivp(contact, (0.0, 3.0 * period), [0.0, speed], events=leaves, first_step=period * 1e-6,
                     rtol=1e-12, atol=1e-18, method="DOP853")
    if not done.t_events[0].size:
        return 0.0
    d, rate = done.y_events[0][0]
    if tension:
        return -rate / speed

    def lands(t, y):
        return y[0]
    lands.terminal, lands.direction = True, -1
    flight = solve_ivp(lambda t, y: [y[1], g], (0.0, 10.0 * period), [d, rate], events=lands, rtol=1e-12,
                       atol=1e-18, method="DOP853")
    return -flight.y_events[0][0][1] / speed if flight.t_events[0].size else 0.0


@pytest.mark.parametrize("tension", [True, False])
@pytest.mark.parametrize("mass, k_n, c_n, g, speed", [(1.0, 1e4, 0.0, 0.0, 1.0), (0.0034, 2.3e5, 3.1, 9.81, 0.5),
                                                      (0.2, 5e6, 400.0, 9.81, 0.05), (1.0, 1e4, 150.0, 9.81, 0.3),
                                                      (0.173, 6.5e7, 4010.0, 9.81, 0.006)])
def test_linear_bounce_restitution_matches_the_integrated_contact(mass, k_n, c_n, g, speed, tension):
    expected = linear_contact_under_gravity(mass, k_n, c_n, g, speed, tension)
    assert cf.linear_bounce_restitution(mass, k_n, c_n, g, speed, tension) == pytest.approx(expected, rel=1e-8,
                                                                                           abs=1e-10)


def test_gravity_during_contact_lowers_the_linear_restitution_by_about_g_t_c_over_v():
    """Without gravity the ratio is exp(-pi zeta/sqrt(1 - zeta^2)) at any speed (Schaefer, Dippel & Wolf 1996); with
    it, slower impacts lose more: the change is of the order g t_c / v."""
    mass, k_n, zeta, g = 0.17, 6.5e7, 0.4, 9.81
    c_n = 2.0 * zeta * math.sqrt(mass * k_n)
    e = math.exp(-math.pi * zeta / math.sqrt(1.0 - zeta * zeta))
    t_c = math.pi / math.sqrt(k_n / mass * (1.0 - zeta * zeta))
    assert cf.linear_bounce_restitution(mass, k_n, c_n, 0.0, 1.0) == pytest.approx(e, rel=1e-12)
    for speed in (1.0, 0.1, 0.02):
        drop = e - cf.linear_bounce_restitution(mass, k_n, c_n, g, speed)
        assert 0.1 * g * t_c / speed < drop < 10.0 * g * t_c / speed


def apex_heights_of_linear_bounces(h0, mass, k_n, c_n, g, bounces, tension):
    """The apexes of a sphere dropped from h0 whose contacts are the integrated linear contact under gravity
    (linear_contact_under_gravity) between ballistic flights: v^2/(2 g) after each contact."""
    speed, apexes = math.sqrt(2.0 * g * h0), []
    for _ in range(bounces):
        speed *= linear_contact_under_gravity(mass, k_n, c_n, g, speed, tension)
        apexes.append(speed * speed / (2.0 * g))
    return apexes


@pytest.mark.parametrize("tension", [True, False])
def test_apex_heights_match_the_integrated_bounces(tension):
    h0, mass, k_n, c_n, g = 0.05, 0.0034, 2.3e5, 3.1, 9.81
    for k, height in enumerate(apex_heights_of_linear_bounces(h0, mass, k_n, c_n, g, 4, tension), start=1):
        assert cf.linear_bounce_apex(h0, mass, k_n, c_n, g, k, tension) == pytest.approx(height, rel=1e-7)


def sliding_sphere(v0, w0, radius, mu):
    """(t_s, v at t_s) of a solid sphere on a plane, m v' = -mu m g sgn(s), I w' = mu m g R sgn(s), slip s = v - R w,
    I = 2/5 m R^2: integrated with an event at zero slip."""
    inertia_per_mass = 0.4 * radius ** 2

    def slip(t, y):
        return y[0] - radius * y[1]
    slip.terminal = True
    sign = math.copysign(1.0, v0 - radius * w0)
    done = solve_ivp(lambda t, y: [-mu * G * sign, mu * G * radius * sign / inertia_per_mass], (0.0, 100.0),
                     [v0, w0], events=slip, rtol=1e-12, atol=1e-15)
    return done.t_events[0][0], done.y_events[0][0][0]


@pytest.mark.parametrize("v0, w0, radius, mu", [(1.0, 0.0, 0.025, 0.3), (2.0, 30.0, 0.01, 0.1),
                                                (0.5, 80.0, 0.025, 0.5), (1.0, -40.0, 0.005, 0.2)])
def test_slide_to_roll_matches_the_integrated_sphere(v0, w0, radius, mu):
    """Both signs of the starting slip: forward (v0 > R w0) and backspin-free overspin (v0 < R w0)."""
    t_s, v_f = sliding_sphere(v0, w0, radius, mu)
    assert cf.slip_end_time(v0, w0, radius, mu, G) == pytest.approx(t_s, rel=1e-9)
    assert cf.rolling_speed(v0, w0, radius) == pytest.approx(v_f, rel=1e-9)


def test_slide_to_roll_without_spin_is_two_sevenths_and_five_sevenths():
    assert cf.slip_end_time(3.0, 0.0, 0.02, 0.25, G) == pytest.approx(2 * 3.0 / (7 * 0.25 * G), rel=1e-15)
    assert cf.rolling_speed(3.0, 0.0, 0.02) == pytest.approx(5 / 7 * 3.0, rel=1e-15)


@pytest.mark.parametrize("mass, E_star, R_star", [(0.18, 38.5e9, 0.025), (1e-3, 1e8, 0.002), (50.0, 2e11, 0.5)])
def test_hertz_static_overlap_balances_the_weight(mass, E_star, R_star):
    """brentq of 4/3 E* sqrt(R*) delta^3/2 = m g (Hertz's force, Johnson 1985)."""
    weight_carried = lambda delta: 4.0 / 3.0 * E_star * math.sqrt(R_star) * delta ** 1.5 - mass * G  # noqa: E731
    delta = brentq(weight_carried, 0.0, R_star, xtol=1e-30, rtol=1e-14)
    assert cf.hertz_static_overlap(mass, G, E_star, R_star) == pytest.approx(delta, rel=1e-10)


def test_linear_static_overlap_balances_the_weight():
    mass, k_n = 0.18, 3.3e6
    delta = brentq(lambda d: k_n * d - mass * G, 0.0, 1.0, xtol=1e-30, rtol=1e-14)
    assert cf.linear_static_overlap(mass, G, k_n) == pytest.approx(delta, rel=1e-12)


def column_contact_forces(spheres, mass, k_n, top=None):
    """The contact forces of a column of equal spheres on linear springs at rest (numpy.linalg.solve of every
    sphere's force balance for its displacement), from the top contact down; `top` fixes a top wall this far
    above the unloaded top sphere's place (negative: pressing down)."""
    n = spheres
    stiffness = np.zeros((n, n))
    load = np.full(n, -mass * G)                # each sphere's weight; u_i is its downward-negative displacement
    for i in range(n):                          # the spring below sphere i: the wall (i = 0) or sphere i - 1
        stiffness[i, i] += k_n
        if i:
            stiffness[i, i - 1] -= k_n
            stiffness[i - 1, i - 1] += k_n
            stiffness[i - 1, i] -= k_n
    if top is not None:
        stiffness[n - 1, n - 1] += k_n
        load[n - 1] += k_n * top
    u = np.linalg.solve(stiffness, load)
    below = [-k_n * (u[i] - (u[i - 1] if i else 0.0)) for i in range(n)]   # compression of the spring below i
    return below[::-1], (k_n * (u[-1] - top) if top is not None else 0.0)


@pytest.mark.parametrize("spheres", [2, 3, 7])
def test_stack_contact_forces_match_the_solved_column(spheres):
    mass = 0.05
    forces, _ = column_contact_forces(spheres, mass, 1e5)
    for i, force in enumerate(forces, start=1):
        assert cf.stack_contact_force(i, mass, G) == pytest.approx(force, rel=1e-9)


def test_stack_between_two_walls_adds_the_top_walls_preload():
    mass = 0.05
    forces, preload = column_contact_forces(4, mass, 1e5, top=-2e-4)
    assert preload > 0.5
    for i, force in enumerate(forces, start=1):
        assert cf.stack_contact_force(i, mass, G, preload) == pytest.approx(force, rel=1e-9)
