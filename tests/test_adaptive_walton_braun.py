"""Walton-Braun's tangential spring in the converged mode: the implicit SDIRK4(3) stepper (harness/solver/steppers.py)
against the second-order kernel's graded Richardson ladder taken deep (2^18 and 2^19 graded steps per contact), an
independent discretisation of the same scheme, accurate there to ~1e-8, and to ~2e-7 where the kernel's error is
first order (Thornton's yield kink under this spring at e_n 0.05: 1.6e-6, 8e-7, ... from 2^15 steps on)."""
import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from harness.laws import compose
from harness.scenes.scene import Scene
from harness.solver import codes as C
from harness.solver.simulate import adaptive_batch, run_adaptive, simulate, simulate_extrapolated

WALTON_BRAUN_SPRINGS = [("walton-braun", None),
                        ("hertz-mindlin", {"tangential": "walton-braun:2/7", "tangential-damping": "none"}),
                        ("thornton", {"tangential": "walton-braun:2/7"}),
                        ("linear-spring-dashpot", {"tangential": "walton-braun:2/7", "tangential-damping": "none"})]
OBLIQUE = (5.0, 15.0, 30.0, 45.0, 60.0, 75.0, 85.0, 89.5)
DEEP = 19


def deep_ladder(law, scene, k=DEEP):
    """Results table of R = f_n + (f_n - f_n/2)/3 on n = 2^k graded steps per contact, for every impact."""
    return simulate_extrapolated(law, scene, 2 ** k)


def assert_close(adaptive, ladder, scene, bound):
    """e_n, e_t and R omega/V within `bound` (absolute), t_c and F_max within it relative. (Omega* divides the spin
    by mu (1 + e) V_n: at 89.5 deg that amplifies an error in e_t 640x, and the ladder's 2^-18 of a contact leaves
    ~1e-8 there.)"""
    def spin(frame):
        return frame.omega1 * scene.radius / scene.speed

    for col in ("e_n", "e_t", "spin", "t_contact", "f_n_max"):
        ours, theirs = (spin(adaptive), spin(ladder)) if col == "spin" else (adaptive[col], ladder[col])
        scale = theirs.abs() if col in ("t_contact", "f_n_max") else 1.0
        error = ((ours - theirs).abs() / scale).fillna(0.0)
        assert error.max() < bound, (col, error.max(), adaptive.theta_deg[error.idxmax()])


@pytest.mark.parametrize("name, overrides", WALTON_BRAUN_SPRINGS)
def test_converged_mode_agrees_with_the_deep_ladder(name, overrides):
    """Four normal laws under Walton-Braun's spring, e_n 0.5 and 0.05 (K2 = 400 K1 for Walton-Braun's own normal
    law), 5 to 89.5 deg: every oblique row converges on the implicit stepper and is within 5e-7 of the deep ladder
    (the converged mode claims 1e-6; the ladder's own error reaches 2e-7 in e_t, 4e-7 in R omega/V)."""
    law = compose(name, overrides)
    for e_n in (0.5, 0.05):
        scene = Scene(e_n=(e_n,), angles_deg=OBLIQUE)
        adaptive = simulate(law, scene, converged=True)[0]
        assert adaptive.message.str.startswith("converged: adaptive SDIRK4(3)").all(), list(adaptive.message)
        assert_close(adaptive, deep_ladder(law, scene), scene, 5e-7)


def test_error_follows_the_tolerance_at_a_fraction_of_brute_force(count_kernel_steps):
    """Walton-Braun, 10 to 85 deg (brute force does not converge by 2^20 steps per contact at 89.5): against the deep
    ladder the worst error of v_n and v_t (over V) falls at least
    10x from tol 1e-5 to 1e-7 and is below 1e-8 at tol 1e-9; the converged mode, both its tolerances counted, takes at
    most a fifth of the force
    evaluations of brute-force refinement with the same stopping rule (benchmarks/bench_converged.py times both)."""
    law = compose("walton-braun")
    scene = Scene(e_n=(0.5,), angles_deg=(10.0, 30.0, 60.0, 85.0))
    truth = deep_ladder(law, scene)
    batch = adaptive_batch(law, scene, 0.5)[0]
    errors = []
    for tol in (1e-5, 1e-7, 1e-9):
        out = run_adaptive(batch, np.arange(len(truth)), tol)[0]
        assert (out[:, C.O_STATUS] == C.STATUS_OK).all()
        errors.append(max(np.abs(out[:, C.O_VZ] - truth.v_n1).max(), np.abs(out[:, C.O_VX] - truth.v_t1).max())
                      / scene.speed)
    assert errors[1] < errors[0] / 10, errors
    assert errors[2] < 1e-8, errors                 # (the deep ladder's own error is ~3e-9 here)
    brute, brute_steps = count_kernel_steps(law, scene, converged=True, extrapolate=False)
    adaptive = simulate(law, scene, converged=True)[0]
    assert brute.message.str.contains("steps/contact agree").all(), list(brute.message)
    assert adaptive.steps_per_contact.sum() * 5 <= brute_steps, (adaptive.steps_per_contact.sum(), brute_steps)


def test_the_spring_that_rides_the_cone_is_resolved_at_grazing_incidence():
    """89.5 deg, where brute force and the ladder stall near 1e-6 (the spring rides just under a rising mu N, a
    relaxation ~1000x faster than the contact): the implicit stepper's results at tol 1e-9 and 1e-11 agree within
    1e-8, in a few thousand force evaluations."""
    law = compose("walton-braun")
    scene = Scene(e_n=(0.9, 0.5, 0.05), angles_deg=(89.5,))
    for e_n in scene.e_n:
        batch = adaptive_batch(law, scene, e_n)[0]
        coarse, fine = (run_adaptive(batch, np.arange(1), tol)[0][0] for tol in (1e-9, 1e-11))
        for col in (C.O_VZ, C.O_VX):
            assert abs(coarse[col] - fine[col]) / scene.speed < 1e-8, (e_n, col, coarse[col], fine[col])
        assert coarse[C.O_STEPS] < 2e4, coarse[C.O_STEPS]


@pytest.mark.xfail(strict=True, reason="known defect found by hypothesis: the graded Richardson ladder of the "
                   "converged mode misses e_t by 1.3e-6 for thornton with Walton-Braun's spring at 0.125 deg, mu "
                   "0.0547, e_n 0.25 (the same before this session's changes)")
def test_the_converged_mode_at_a_near_normal_low_friction_impact():
    scene = Scene(e_n=(0.25,), angles_deg=(0.125,), mu=0.0546875)
    law = compose("thornton", {"tangential": "walton-braun:2/7"})
    assert_close(simulate(law, scene, converged=True)[0], deep_ladder(law, scene), scene, 5e-7)


@settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.sampled_from(WALTON_BRAUN_SPRINGS), st.floats(0.05, 0.95), st.one_of(st.just(0.0), st.floats(1e-6, 89.5)),
       st.floats(0.05, 1.5))
def test_agrees_with_the_deep_ladder_anywhere(spring, e_n, angle, mu):
    """Random law, e_n, angle and friction: the converged mode and the deep ladder agree within 5e-7, and the
    converged mode ends with a release."""
    scene = Scene(e_n=(e_n,), angles_deg=(angle,), mu=mu)
    law = compose(*spring)
    adaptive = simulate(law, scene, converged=True)[0]
    assert adaptive.status.iloc[0] == "ok", adaptive.message.iloc[0]
    assert_close(adaptive, deep_ladder(law, scene), scene, 5e-7)


def test_the_kernel_keeps_a_tiny_tangential_load_to_round_off():
    """A tangential speed 1.7e-8 of the normal one (1e-6 deg, mu 1): the kernel's Walton-Braun step adds the
    trapezoid's increment to T instead of taking mu N - span x1, a difference of near-equal numbers that lost 1e-8
    of T per step (e_t 1.4e-4 off at 2^19 steps per contact). The graded ladder at 2^16 and 2^19 steps and the
    adaptive integrator now agree within 1e-7 in e_t."""
    law = compose("walton-braun")
    scene = Scene(e_n=(0.5,), angles_deg=(1e-6,), mu=1.0)
    adaptive = simulate(law, scene, converged=True)[0].e_t.iloc[0]
    for k in (16, 19):
        assert abs(deep_ladder(law, scene, k).e_t.iloc[0] - adaptive) < 1e-7, k


def test_a_stalled_row_whose_ladder_is_refused_says_both():
    """Found by a random search: Thornton under this spring, e_n 0.0117, a normal impact with a little spin. At tol
    1e-9 Newton converges only on steps ~1e-13 of the contact; such a creeping run is stopped (not run to the time
    limit, ~1 min), and the ladder it falls back to refuses 64 steps per contact there (stability). The row is
    non-finite, its message names both, and nothing is raised."""
    scene = Scene(e_n=(0.01171875,), angles_deg=(0.0,), mu=1.0, omega0=0.015625 / 0.005)
    row = simulate(compose("thornton", {"tangential": "walton-braun:2/7"}), scene, converged=True)[0].iloc[0]
    assert row.status == "non-finite"
    assert row.message.startswith("non-finite: the adaptive step underflowed or stalled, and the ladder is refused")
    assert "stability limit" in row.message
