"""A solid sphere set sliding on a wall under gravity rolls once friction has spent the slip: with Coulomb mu, slip
V_s = v - R w ends at t_s = 2 (v0 - R w0)/(7 mu g) with v = (5 v0 + 2 R w0)/7 (rigid-body mechanics: dv/dt = -mu g,
dw/dt = 5 mu g/(2 R) while sliding). Two variants in one run: plain sliding and sliding with backspin."""
import math

import numpy as np
import pytest

from harness.laws import LAWS, compose
from harness.solver.system import M_STATUS, STATUS_OK
from harness.solver.system_run import Sphere, Variant, simulate_system

G, MU = 9.81, 0.3
E, NU, RHO = 70e9, 0.3, 2650.0
RADIUS = 5e-3
MASS = 4.0 / 3.0 * math.pi * RADIUS ** 3 * RHO
E_STAR = E / (2.0 * (1.0 - NU ** 2))
DT = 2.5e-6


SLIDING_LAWS = [name for name in LAWS if name != "walton-braun"]   # its explicit spring: see the test below


@pytest.mark.parametrize("law_name", SLIDING_LAWS)
def test_slip_ends_at_2_v0_over_7_mu_g_with_five_sevenths(law_name):
    starts = ((1.0, 0.0), (1.0, -40.0))                                  # (v0, w0): w0 < 0 is backspin
    resting = (3.0 * MASS * G / (4.0 * E_STAR * math.sqrt(RADIUS))) ** (2.0 / 3.0)     # start without a bounce
    ends = [2.0 * (v0 - RADIUS * w0) / (7.0 * MU * G) for v0, w0 in starts]
    steps = int(1.2 * max(ends) / DT)
    variants = [Variant((Sphere(RADIUS, z=RADIUS - resting, vx=v0, w=w0),), compose(law_name), E=E, nu=NU,
                        rho=RHO, mu=MU, e_n=0.5, speed=1.0, dt=DT, steps=steps, gravity=G) for v0, w0 in starts]
    grid = np.arange(steps + 1) * DT
    result = simulate_system(variants, grid)
    for row, ((v0, w0), t_s) in enumerate(zip(starts, ends)):
        assert result.metrics[row, M_STATUS] == STATUS_OK
        vx, w = result.trace[row, :, 0, 2], result.trace[row, :, 0, 4]
        slip = vx - RADIUS * w
        stopped = grid[np.argmax(np.abs(slip) < 1e-4 * v0)]
        assert stopped == pytest.approx(t_s, rel=1e-3)
        assert vx[-1] == pytest.approx((5.0 * v0 + 2.0 * RADIUS * w0) / 7.0, rel=1e-3)
        assert w[-1] * RADIUS == pytest.approx(vx[-1], rel=1e-3)
        sliding = grid < 0.9 * t_s
        assert vx[sliding] == pytest.approx(v0 - MU * G * grid[sliding], rel=1e-3)


def test_walton_braun_explicit_spring_carries_no_friction_at_a_step_beyond_its_mobilisation():
    """Walton & Braun's spring in the Verlet form (predictor-corrector on T, as the impact's velocity-Verlet stepper
    takes it) evaluates k_t = k_t0 x^1/3 at the mid-step T: where one step's increment k_t0 V_s dt (7 N here) is far
    beyond mu N (0.04 N), x is 0 there and the step's force is 0, so the sphere slides on without friction. This
    states the limitation the test above leaves Walton-Braun out for; it fails once the system integrator takes the
    law's implicit form."""
    resting = (3.0 * MASS * G / (4.0 * E_STAR * math.sqrt(RADIUS))) ** (2.0 / 3.0)
    variant = Variant((Sphere(RADIUS, z=RADIUS - resting, vx=1.0),), compose("walton-braun"), E=E, nu=NU, rho=RHO,
                      mu=MU, e_n=0.5, speed=1.0, dt=DT, steps=1000, gravity=G)
    result = simulate_system([variant], [0.0])
    assert result.bodies[0, 0, 2] == 1.0 and result.bodies[0, 0, 4] == 0.0
