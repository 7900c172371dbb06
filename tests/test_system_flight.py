"""The small-system integrator in free flight and bouncing on a wall, against closed forms: z(t) = z0 + v0 t - g t^2/2
(velocity Verlet is exact for a constant force) and each bounce's rebound speed ratio e_n (the linear spring-dashpot
law, whose restitution is e_n at any impact speed)."""
import math

import numpy as np
import pytest

from harness.laws import compose
from harness.solver.system import E_KIND, E_VN, M_GAIN, M_STATUS, PART, STATUS_OK, TOUCH
from harness.solver.system_run import Sphere, Variant, simulate_system

GLASS = dict(E=70e9, nu=0.3, rho=2650.0)


def test_free_flight_is_the_parabola_to_1e_9():
    """Two variants (two throws) in one run, far from the wall: x, z and their velocities at 50 stated times."""
    g, dt, steps = 9.81, 1e-4, 5000
    throws = ((0.3, 2.0, 0.7, 1.5), (-0.2, 5.0, 0.0, -3.0))          # (vx, z0, ... vz)
    variants = [Variant((Sphere(0.01, x=0.1, z=z0, vx=vx, vz=vz, w=w),), compose("hertz-mindlin"), mu=0.3,
                        e_n=0.5, speed=1.0, dt=dt, steps=steps, gravity=g, **GLASS) for vx, z0, w, vz in throws]
    grid = np.linspace(0.0, dt * steps, 51)
    result = simulate_system(variants, grid)
    for row, (vx, z0, w, vz) in enumerate(throws):
        t = grid
        z, x = z0 + vz * t - 0.5 * g * t ** 2, 0.1 + vx * t
        trace = result.trace[row, :, 0]
        assert trace[:, 1] == pytest.approx(z, rel=1e-9)
        assert trace[:, 0] == pytest.approx(x, rel=1e-9)
        assert trace[:, 3] == pytest.approx(vz - g * t, rel=1e-9, abs=1e-9 * g * t[-1])
        assert trace[:, 4] == pytest.approx(np.full_like(t, w), rel=1e-12)
        assert result.n_events[row] == 0
        assert result.metrics[row, M_STATUS] == STATUS_OK


@pytest.mark.parametrize("e_n", [0.5, 0.9])
def test_each_bounce_rebounds_at_e_n(e_n):
    """A glass sphere (R 1 mm) arriving at 1 m/s bounces twice under g: each parting speed over its touching speed is
    e_n to 1e-3 at dt = t_c/1000 (g t_c/V ~ 1e-4 keeps gravity's share of the contact below that)."""
    g, radius, speed = 9.81, 1e-3, 1.0
    law = compose("linear-spring-dashpot")
    mass = 4.0 / 3.0 * math.pi * radius ** 3 * GLASS["rho"]
    t_c = contact_time(law, radius, e_n, speed)
    dt = t_c / 1000
    steps = int((2.02 * e_n * speed / g + 3.0 * t_c) / dt)        # two contacts and the flight between
    variant = Variant((Sphere(radius, z=radius, vz=-speed),), law, mu=0.0, e_n=e_n, speed=speed, dt=dt, steps=steps,
                      gravity=g, **GLASS)
    result = simulate_system([variant], [0.0])
    events = result.events[0, :result.n_events[0]]
    assert list(events[:, E_KIND]) == [TOUCH, PART, TOUCH, PART]
    v_n = events[:, E_VN]
    assert -v_n[0] == pytest.approx(speed, rel=1e-6)
    for bounce in range(2):
        assert v_n[2 * bounce + 1] / -v_n[2 * bounce] == pytest.approx(e_n, abs=1e-3)
    assert v_n[2] == pytest.approx(-v_n[1], rel=1e-6)            # free flight gives back the parting speed
    assert result.metrics[0, M_GAIN] <= 1e-12 * mass * speed ** 2


def contact_time(law, radius, e_n, speed):
    """The linear spring's undamped half period pi sqrt(m/k_n), k_n from the law (an input, not an output)."""
    from harness.solver import layout as L
    from harness.solver.system_rows import contact_properties, contact_row
    contact = contact_properties(radius, None, **GLASS)
    params, _ = contact_row(law, contact, e_n, speed, 0.0, 9.81, 1.0)
    return math.pi * math.sqrt(contact.mass / params[L.NORMAL_LINEAR_K_N])


def test_a_contact_starts_afresh_at_each_touch():
    """A plastic law keeps its largest overlap while in contact: Thornton's second bounce on the wall must rebound as
    a first impact at the same speed would (a second variant starting there), not on the first bounce's unloading
    curve (a history not cleared at parting would make it nearly elastic)."""
    g, radius, speed = 9.81, 1e-3, 1.0
    law = compose("thornton")
    t_c = contact_time_of(law, radius, 0.5, speed)
    dt = t_c / 1000
    first = Variant((Sphere(radius, z=radius, vz=-speed),), law, mu=0.0, e_n=0.5, speed=speed, dt=dt,
                    steps=int((2.02 * speed / g + 3.0 * t_c) / dt), gravity=g, **GLASS)
    bounced = simulate_system([first], [0.0])
    events = bounced.events[0, :bounced.n_events[0]]
    assert list(events[:4, E_KIND]) == [TOUCH, PART, TOUCH, PART]
    again = Variant((Sphere(radius, z=radius, vz=events[2, E_VN]),), law, mu=0.0, e_n=0.5, speed=speed, dt=dt,
                    steps=int(3.0 * t_c / dt), gravity=g, **GLASS)
    fresh = simulate_system([again], [0.0])
    assert events[3, E_VN] == pytest.approx(fresh.events[0, 1, E_VN], rel=1e-3)
    assert events[3, E_VN] / -events[2, E_VN] < 0.9


def contact_time_of(law, radius, e_n, speed):
    """The law's contact-time estimate (its normal parameters, an input)."""
    from harness.solver.system_rows import contact_properties
    return law.normal.parameters(contact_properties(radius, None, **GLASS), e_n, speed).contact_time


@pytest.mark.parametrize("name", ["linear-spring-dashpot", "hertz-mindlin"])
def test_an_elastic_bounce_keeps_its_energy_to_second_order(name):
    """Without damping (e_n 1) or friction, two bounces under g: velocity Verlet's energy error is O(h^2), so the
    largest gain falls a hundredfold from t_c/100 to t_c/1000 (two variants of one run, 80 to 125 allowed), stays
    below 1e-5 of the energy at t_c/1000, and the energy after the bounces is the energy before to 1e-6."""
    g, radius, speed = 9.81, 1e-3, 1.0
    law = compose(name)
    t_c = contact_time_of(law, radius, 1.0, speed)
    variants = [Variant((Sphere(radius, z=radius, vz=-speed, vx=0.3),), law, mu=0.0, e_n=1.0, speed=speed,
                        dt=t_c / n, steps=int(n * (2.02 * speed / g + 3.0 * t_c) / t_c), gravity=g, **GLASS)
                for n in (100, 1000)]
    result = simulate_system(variants, [0.0])
    start = 0.5 * variants[0].spheres[0].vz ** 2 + 0.5 * 0.3 ** 2 + g * radius      # per unit mass
    mass = 4.0 / 3.0 * math.pi * radius ** 3 * GLASS["rho"]
    energy = start * mass
    assert result.energy[:, 0] == pytest.approx([energy, energy], rel=1e-12)
    coarse, fine = result.metrics[:, M_GAIN]
    assert 80.0 <= coarse / fine <= 125.0
    assert fine <= 1e-5 * energy
    for row in range(2):
        assert list(result.events[row, :4, E_KIND]) == [TOUCH, PART, TOUCH, PART]
    body = result.bodies[1, 0]
    after = mass * (0.5 * (body[2] ** 2 + body[3] ** 2) + g * body[1])
    assert after == pytest.approx(energy, rel=1e-6)
