"""Kratos' dialects (harness/engines/kratos/dialect.py) and the sub-models they add, against closed forms and an
independent step-by-step calculation of Kratos DEMApplication 10.4.4's formulas (docs/kratos-dialect.md)."""
import math

import numpy as np
import pytest

from harness.scenes.bodies import Sphere
from harness.engines.kratos.dialect import DIALECTS, PAIR_DIALECTS
from harness.infra.jit import python_twin
from harness.laws import compose
from harness.laws.law import replace_submodels
from harness.scenes.scene import Scene
from harness.solver.resolution import FixedTimeStep, run_spec
from harness.solver.simulate import simulate
from harness.submodels import calibration as cal
from harness.submodels.coulomb import total_cases
from harness.submodels.normal.linear_modulus import LinearModulus
from harness.submodels.tangential import mindlin_unloading
from harness.submodels.tangential.state import N_TSTATE
from harness.solver.two_spheres import reduce

LAST_HALF_BRACKET = 16.0 / 2 ** 19      # [0, 16] halved until at most 1e-4 wide (18 halvings), then its midpoint


def kratos(law_name, target="wall"):
    return replace_submodels(compose(law_name), (PAIR_DIALECTS if target == "sphere" else DIALECTS)[law_name], "kratos")


@pytest.mark.parametrize("e", [0.25, 0.5, 0.75, 0.9])
def test_bisection_is_a_midpoint_of_the_last_bracket_around_the_exact_root(e):
    """Kratos' g: the midpoint of a bracket 16/2^18 wide holding the root of Schwager & Poeschel's e(g) = e (found
    apart to 1e-15): within 16/2^19 of it, a multiple of 16/2^19, and not the root itself."""
    g = cal.lsd_notension_g_bisection(e)
    exact = cal.lsd_notension_g(e)
    assert abs(g - exact) <= LAST_HALF_BRACKET
    assert (g / LAST_HALF_BRACKET) == int(g / LAST_HALF_BRACKET)
    assert g != exact and abs(cal.lsd_notension_e(g) - e) > 1e-9


def test_bisection_clamps_the_target_as_kratos():
    """e above 0.999 gives g = 0 (no dashpot); below 0.001 it is taken as 0.001."""
    assert cal.lsd_notension_g_bisection(0.9995) == 0.0
    assert cal.lsd_notension_g_bisection(1e-5) == cal.lsd_notension_g_bisection(0.001)


def test_linear_modulus_stiffness_from_e_star_and_radius():
    """k_n = E* pi 0.31225 R against a wall of the sphere's material (E* = E/(2(1 - nu^2))), 1.432 times that
    between two spheres of R* = R/2."""
    scene = Scene()
    e_star = scene.E / (2.0 * (1.0 - scene.nu ** 2))
    wall = LinearModulus("wall").parameters(scene.contact, 0.5, 5.0)["k_n"]
    assert wall == pytest.approx(e_star * math.pi * 0.31225 * scene.radius, rel=1e-15)
    pair = reduce(scene, Sphere(scene.radius))
    assert LinearModulus("pair").parameters(pair.contact, 0.5, 5.0)["k_n"] == pytest.approx(
        1.432 * e_star * math.pi * 0.31225 * scene.radius / 2.0, rel=1e-15)


def test_unloading_rescale_only_while_the_overlap_falls():
    """F_s - 8 G* a dd while the overlap grows or holds; F_s sqrt(delta/delta_old) - 8 G* a dd while it falls."""
    spring = python_twin(mindlin_unloading.spring)
    g_star, radius, dd, f_s = 1.3e10, 0.025, 2e-7, 40.0
    a_old = math.sqrt(radius * 1e-4)
    for delta, scale in ((1.2e-4, 1.0), (1e-4, 1.0), (0.81e-4, 0.9)):
        a = math.sqrt(radius * delta)
        got = spring(g_star, f_s, dd, a, a, a_old, 0.1, 0.0, 0.0, np.zeros(N_TSTATE), np.zeros(4), False)
        assert got == pytest.approx(f_s * scale - 8.0 * g_star * a * dd, rel=1e-14)


@pytest.mark.parametrize("f_s, f_d, total, spring", [
    (0.3, 0.5, 0.8, 0.3),          # within the cap: untouched
    (1.5, 0.2, 1.0, 1.0),          # one side, spring beyond: spring cut to the cap, no dashpot
    (0.6, 0.7, 1.0, 0.6),          # one side, spring within: the dashpot shortened, the spring kept
    (2.0, -4.0, -1.0, 2.0),        # opposed, dashpot stronger: scaled to mu F_n + |F_s|, the spring kept beyond
    (3.0, -1.0, 1.0, 1.0),         # opposed, spring stronger: spring cut to the cap, no dashpot
])
def test_total_cases_four_cases(f_s, f_d, total, spring):
    """Kratos' cap on spring plus dashpot at mu F_n = 1 (k_t = c_t = 1, so F_d = -V_s)."""
    got = python_twin(total_cases.cap)(f_s, 1.0, 1.0, -f_d, 1.0)[:2]
    assert got == pytest.approx((total, spring), rel=1e-15, abs=1e-15)


def symplectic_euler_wall(law_name, scene, e_n, dt, theta, omega0):
    """Kratos' formulas step by step for a sphere placed touching a wall: forces from x and v, then v += dt F/m,
    x += dt v; no force at overlap 0; App. B (Hertz: k_n = 2E*sqrt(R d), k_t = 8G*sqrt(R d)) or bisected (linear:
    k_n = E* pi 0.31225 R, k_t = 4G*/E* k_n) gamma on the current stiffness; the normal force clipped at 0;
    F_s sqrt(d/d_old) on unloading (Hertz); the four-case cap; lever R - d."""
    c = scene.contact
    radius, m, inertia, mu = c.radius, c.mass, c.inertia, scene.mu
    hertz = law_name == "hertz-mindlin"
    g = cal.thornton_appendix_b_g(e_n) if hertz else cal.lsd_notension_g_bisection(e_n)
    vz, vx, w = -scene.speed * math.cos(math.radians(theta)), scene.speed * math.sin(math.radians(theta)), omega0
    gap, f_s, d_old = 0.0, 0.0, 0.0
    while True:
        d = -gap
        if d < 0.0:
            return vz, vx, w
        f_n = f_t = 0.0
        arm = radius - d
        if d > 0.0:
            k_n = 2.0 * c.E_star * math.sqrt(radius * d) if hertz else c.E_star * math.pi * 0.31225 * radius
            k_t = 4.0 * c.G_star * k_n / c.E_star
            f_n = max((2.0 / 3.0 * d if hertz else d) * k_n - 2.0 * g * math.sqrt(m * k_n) * vz, 0.0)
            slip = vx - arm * w
            f_s = (f_s * math.sqrt(d / d_old) if hertz and d_old > d else f_s) - k_t * slip * dt
            f_d, limit = -2.0 * g * math.sqrt(m * k_t) * slip, mu * f_n
            if abs(f_s + f_d) > limit:
                if (f_s * f_d >= 0.0 and abs(f_s) > limit) or (f_s * f_d < 0.0 and abs(f_d) < abs(f_s)):
                    f_s, f_d = f_s * limit / abs(f_s), 0.0
                else:
                    f_d *= (limit + (abs(f_s) if f_s * f_d < 0.0 else -abs(f_s))) / abs(f_d)
            f_t, d_old = f_s + f_d, d
        vz, vx, w = vz + dt * f_n / m, vx + dt * f_t / m, w - dt * arm * f_t / inertia
        gap += dt * vz


@pytest.mark.parametrize("law_name", list(DIALECTS))
@pytest.mark.parametrize("theta, omega0", [(20.0, 0.0), (5.0, 100.0), (49.0, 100.0)])
def test_wall_dialect_is_kratos_step_by_step(law_name, theta, omega0):
    """The wall dialect against Kratos' formulas stepped apart in plain Python, at e_n 0.5 and t_c/200: the same
    rebound to round-off."""
    scene = Scene(e_n=(0.5,), angles_deg=(theta,), omega0=omega0)
    law = kratos(law_name)
    dt = run_spec(law, scene, 0.5, 200).dt
    row = simulate(law, scene, steps_per_contact=FixedTimeStep(dt))[0].iloc[0]
    vz, vx, w = symplectic_euler_wall(law_name, scene, 0.5, dt, theta, omega0)
    assert np.abs(np.array([row.v_n1 - vz, row.v_t1 - vx, scene.radius * (row.omega1 - w)])).max() < 1e-12 * 5.0


@pytest.mark.parametrize("law_name", list(PAIR_DIALECTS))
def test_pair_leapfrog_head_on_is_the_wall_impact_of_the_relative_motion(law_name):
    """Head on, two equal spheres in the pair stepper rebound as the leapfrog wall impact of R* = R/2, m* = m/2 with
    the same k_n (the wall stepper is separate code), to the round-off of the centres' positions."""
    scene = reduce(Scene(e_n=(0.5,), angles_deg=(0.0,)), Sphere(0.025))
    pair = kratos(law_name, "sphere")
    wall = replace_submodels(pair, {"geometry": "wall"}, "kratos")
    dt = run_spec(pair, scene, 0.5, 200).dt
    a, b = (simulate(law, scene, steps_per_contact=FixedTimeStep(dt))[0].iloc[0] for law in (pair, wall))
    assert abs(a.v_n1 - b.v_n1) < 1e-11 * 5.0 and a.v_n1 > 0.0      # positions of 0.05 m round off at 1e-17 m
