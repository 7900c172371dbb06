"""Every named law runs in the small-system integrator through the impact kernel's dispatch: a sphere arriving
normally at the law's calibration speed, without gravity, rebounds at the law's target e_n (each law is calibrated
to give e_n at that speed: docs/laws.md), to 1e-2 at dt = t_c/500; and a sphere-sphere contact of equal spheres
head on gives each back e_n times the relative speed, equal and opposite (momentum kept)."""

import pytest

from harness.laws import LAWS, compose
from harness.solver.system import E_KIND, E_VN, M_STATUS, PART, STATUS_OK, TOUCH
from harness.solver.system_run import Sphere, Variant, simulate_system
from harness.solver.system_rows import contact_properties

E, NU, RHO = 70e9, 0.3, 2650.0
RADIUS, SPEED, E_N = 5e-3, 1.0, 0.7


def contact_time(law, radius, other=None):
    """The law's contact-time estimate (its normal parameters, an input) for the step."""
    contact = contact_properties(radius, other, E, NU, RHO)
    return law.normal.parameters(contact, E_N, SPEED).contact_time


@pytest.mark.parametrize("name", list(LAWS))
def test_every_law_rebounds_from_the_wall_at_its_e_n(name):
    law = compose(name)
    dt = contact_time(law, RADIUS) / 500
    variant = Variant((Sphere(RADIUS, z=RADIUS, vz=-SPEED),), law, E=E, nu=NU, rho=RHO, mu=0.3, e_n=E_N,
                      speed=SPEED, dt=dt, steps=2000, gravity=0.0)
    result = simulate_system([variant], [0.0])
    events = result.events[0, :result.n_events[0]]
    assert result.metrics[0, M_STATUS] == STATUS_OK
    assert list(events[:, E_KIND]) == [TOUCH, PART]
    assert events[1, E_VN] / -events[0, E_VN] == pytest.approx(E_N, abs=1e-2)


@pytest.mark.parametrize("name", ["linear-spring-dashpot", "hertz-mindlin"])
def test_head_on_pair_parts_at_e_n_of_the_relative_speed(name):
    law = compose(name)
    dt = contact_time(law, RADIUS, RADIUS) / 1000
    spheres = (Sphere(RADIUS, x=0.0, z=0.5, vx=SPEED / 2), Sphere(RADIUS, x=2 * RADIUS, z=0.5, vx=-SPEED / 2))
    variant = Variant(spheres, law, E=E, nu=NU, rho=RHO, mu=0.3, e_n=E_N, speed=SPEED, dt=dt, steps=4000,
                      gravity=0.0)
    result = simulate_system([variant], [0.0])
    events = result.events[0, :result.n_events[0]]
    assert list(events[:, E_KIND]) == [TOUCH, PART]
    assert events[0, E_VN] == pytest.approx(-SPEED, rel=1e-12)
    assert events[1, E_VN] == pytest.approx(E_N * SPEED, rel=1e-3)
    vx = result.bodies[0, :, 2]
    assert vx[0] == pytest.approx(-vx[1], rel=1e-12)
    assert vx[1] - vx[0] == pytest.approx(E_N * SPEED, rel=1e-3)
