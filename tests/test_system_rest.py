"""Spheres at rest under gravity in the small-system integrator, against statics: the overlap of one sphere on a
wall, Hertz (3 m g/(4 E* sqrt(R)))^(2/3) or linear m g/k_n; no energy gained while it is held; a column of three on
a wall, where the contact below the i-th sphere from the top carries i m g; two between walls pressed by a ceiling,
where the preload P solves the overlaps' sum (scipy brentq)."""
import math

import numpy as np
import pytest
from scipy.optimize import brentq

from harness.laws import compose
from harness.solver import layout as L
from harness.solver.system import F_ALPHA, F_FN, M_GAIN, M_STATUS, STATUS_OK
from harness.solver.system_run import Sphere, Variant, simulate_system
from harness.solver.system_rows import contact_properties, contact_row

G = 9.81
E, NU, RHO = 70e9, 0.3, 2650.0
RADIUS = 5e-3
MASS = 4.0 / 3.0 * math.pi * RADIUS ** 3 * RHO
E_STAR = E / (2.0 * (1.0 - NU ** 2))               # glass on glass
DT = 2.5e-6                                        # ~ 1/100 of the resting oscillation's period (2.5e-4 s)
SETTLE = 20_000                                    # steps: the dashpot at e_n 0.5 damps it below 1e-12 in ~3000


def hertz_overlap(force, radius):
    """delta = (3 F/(4 E* sqrt(R)))^(2/3) (Hertz)."""
    return (3.0 * force / (4.0 * E_STAR * math.sqrt(radius))) ** (2.0 / 3.0)


def at_rest(law_name, spheres, steps, ceiling=None, gain_from=0.0):
    variant = Variant(tuple(spheres), compose(law_name), E=E, nu=NU, rho=RHO, mu=0.3, e_n=0.5, speed=1.0, dt=DT,
                      steps=steps, gravity=G, ceiling=ceiling)
    result = simulate_system([variant], [0.0], gain_from=gain_from)
    assert result.metrics[0, M_STATUS] == STATUS_OK
    return result


def test_hertz_sphere_rests_at_the_static_overlap_and_gains_no_energy_while_held():
    """Dropped from touching at rest, settled, then held 1e5 steps: overlap to 1e-6 of Hertz's; energy never above
    what it was when the hold began."""
    result = at_rest("hertz-mindlin", [Sphere(RADIUS, z=RADIUS)], SETTLE + 100_000, gain_from=SETTLE * DT)
    assert result.final[0, 0, F_ALPHA] == pytest.approx(hertz_overlap(MASS * G, RADIUS), rel=1e-6)
    assert result.final[0, 0, F_FN] == pytest.approx(MASS * G, rel=1e-9)
    assert result.metrics[0, M_GAIN] <= 1e-15 * MASS * G * RADIUS


def test_linear_sphere_rests_at_m_g_over_k_n_and_gains_no_energy_while_held():
    law = compose("linear-spring-dashpot")
    contact = contact_properties(RADIUS, None, E, NU, RHO)
    k_n = contact_row(law, contact, 0.5, 1.0, 0.3, G, DT)[0][L.NORMAL_LINEAR_K_N]     # the law's input
    period = 2.0 * math.pi * math.sqrt(MASS / k_n)
    dt = period / 100
    variant = Variant((Sphere(RADIUS, z=RADIUS),), law, E=E, nu=NU, rho=RHO, mu=0.3, e_n=0.5, speed=1.0, dt=dt,
                      steps=SETTLE + 100_000, gravity=G)
    result = simulate_system([variant], [0.0], gain_from=SETTLE * dt)
    assert result.final[0, 0, F_ALPHA] == pytest.approx(MASS * G / k_n, rel=1e-6)
    assert result.metrics[0, M_GAIN] <= 1e-15 * MASS * G * RADIUS


def test_column_of_three_carries_i_m_g_below_the_ith_from_the_top():
    spheres = [Sphere(RADIUS, z=RADIUS * (1 + 2 * k)) for k in range(3)]
    result = at_rest("hertz-mindlin", spheres, 4 * SETTLE)
    pairs = [tuple(p) for p in result.pairs]
    force = {pair: result.final[0, k, F_FN] for k, pair in enumerate(pairs)}
    assert force[(0, -1)] == pytest.approx(3 * MASS * G, rel=1e-6)      # below the bottom sphere: the wall
    assert force[(0, 1)] == pytest.approx(2 * MASS * G, rel=1e-6)
    assert force[(1, 2)] == pytest.approx(MASS * G, rel=1e-6)
    assert force[(0, 2)] == 0.0


def test_two_between_walls_carry_the_preload_plus_their_weight():
    """Two spheres in a gap 4R - 1e-6 m: the ceiling presses with P, the spheres' contact carries P + m g, the floor
    P + 2 m g, P from delta(P) + delta_pair(P + m g) + delta(P + 2 m g) = 1e-6 m (pair: R* = R/2)."""
    squeeze = 1e-6
    ceiling = 4 * RADIUS - squeeze
    preload = brentq(lambda p: hertz_overlap(p, RADIUS) + hertz_overlap(p + MASS * G, RADIUS / 2)
                     + hertz_overlap(p + 2 * MASS * G, RADIUS) - squeeze, 0.0, 1e6)
    spheres = [Sphere(RADIUS, z=RADIUS - squeeze / 4), Sphere(RADIUS, z=3 * RADIUS - 3 * squeeze / 4)]
    result = at_rest("hertz-mindlin", spheres, 4 * SETTLE, ceiling=ceiling)
    force = {tuple(p): result.final[0, k, F_FN] for k, p in enumerate(result.pairs)}
    assert force[(1, -2)] == pytest.approx(preload, rel=1e-6)
    assert force[(0, 1)] == pytest.approx(preload + MASS * G, rel=1e-6)
    assert force[(0, -1)] == pytest.approx(preload + 2 * MASS * G, rel=1e-6)
    assert np.all(result.final[0, [1, 2], F_FN] == 0.0)     # sphere 0 never reaches the ceiling, 1 never the floor
