"""The small-system integrator's first step from a state already in contact, against Newton: the first half kick
takes the starting state's forces (a sphere placed at Hertz's static overlap stays at rest, |v_z| <= 1e-9 g dt after
a step, where gravity alone in the first half kick leaves g dt/2), with its full sliding friction mu m g from the
start, or, where the variant says (start_friction False, LAMMPS' set-up), none in the first half kick: the sliding
speed then falls by mu g dt/2 in the first step, not mu g dt; a dialect's lever R - alpha/2 (LIGGGHTS') turns the
same friction into the torque (R - delta/2) mu m g."""
import math

import pytest

from harness.laws import compose
from harness.laws.law import replace_submodels
from harness.solver.system_run import Sphere, Variant, simulate_system

G, MU = 9.81, 0.3
E, NU, RHO = 70e9, 0.3, 2650.0
RADIUS = 5e-3
MASS = 4.0 / 3.0 * math.pi * RADIUS ** 3 * RHO
E_STAR = E / (2.0 * (1.0 - NU ** 2))
DT = 2.5e-7
RESTING = (3.0 * MASS * G / (4.0 * E_STAR * math.sqrt(RADIUS))) ** (2.0 / 3.0)     # Hertz: F = m g


def one_step(vx=0.0, start_friction=True, lever=None):
    """The state after one step of a sphere placed at the static overlap with speed vx along the wall."""
    sphere = Sphere(RADIUS, z=RADIUS - RESTING, vx=vx)
    law = compose("hertz-mindlin") if lever is None else replace_submodels(compose("hertz-mindlin"), {"lever": lever})
    variant = Variant((sphere,), law, E=E, nu=NU, rho=RHO, mu=MU, e_n=0.5, speed=1.0, dt=DT,
                      steps=1, gravity=G, **({} if start_friction else {"start_friction": False}))
    result = simulate_system([variant], [0.0, DT])
    return result.trace[0, 1, 0]


def test_a_sphere_placed_at_the_static_overlap_stays_at_rest_in_its_first_step():
    x, z, vx, vz, w = one_step()
    assert abs(vz) <= 1e-9 * G * DT


@pytest.mark.parametrize("start_friction, kicks", [(True, 2), (False, 1)])
def test_sliding_friction_acts_from_the_start_or_from_the_first_step(start_friction, kicks):
    """Sliding at 0.2 m/s: Coulomb's mu m g in each half kick that takes it (the normal force is m g at rest)."""
    x, z, vx, vz, w = one_step(vx=0.2, start_friction=start_friction)
    assert 0.2 - vx == pytest.approx(kicks * 0.5 * MU * G * DT, rel=1e-6)
    assert RADIUS * w == pytest.approx(2.5 * (0.2 - vx), rel=1e-6)       # torque R F_t over I = 2/5 m R^2


def test_a_lever_shortened_by_half_the_overlap_shortens_the_torque_of_the_same_friction():
    x, z, vx, vz, w = one_step(vx=0.2, lever="0.5")
    inertia = 0.4 * MASS * RADIUS ** 2
    assert 0.2 - vx == pytest.approx(MU * G * DT, rel=1e-6)
    assert w == pytest.approx((RADIUS - 0.5 * RESTING) * MU * MASS * G * DT / inertia, rel=1e-6)
