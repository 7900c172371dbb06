"""The converged mode's adaptive integrator (harness/solver/adaptive.py): closed forms and independent integrations
(tests/oracles.py), the independent graded Richardson ladder of the second-order kernel, tolerance proportionality
and its cost."""
import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import oracles
from harness.laws import compose
from harness.scenes.scene import Scene
from harness.solver import codes as C
from harness.solver import layout as L
from harness.solver.simulate import adaptive_batch, run_adaptive, simulate

ADAPTIVE_LAWS = ["linear-spring-dashpot", "hertz-mindlin", "hertz-kuwabara-kono", "stronge", "thornton",
                 "partially-latching-spring"]


def adaptive_law(name):
    """The law as the adaptive integrator covers it: without the paper's tangential dashpot (those rows stay on the
    graded ladder)."""
    law = compose(name)
    return compose(name, {"tangential-damping": "none"}) if law.tangential_damping.rule != "none" else law
SWEEP = Scene(e_n=(0.9, 0.5, 0.1), angles_deg=(1.0, 9.0, 17.0, 21.0, 23.0, 25.0, 33.0, 41.0, 57.0, 73.0, 79.0, 89.0))


def normal_run(law, scene, tol):
    """Outcome rows of the adaptive integrator on every impact of the scene at its first e_n."""
    batch, covered = adaptive_batch(law, scene, scene.e_n[0])
    assert covered.all()
    return batch, run_adaptive(batch, np.arange(len(covered)), tol)[0]


@pytest.mark.parametrize("end", ["no-tension", "tension"])
def test_elastic_hertz_matches_the_closed_form_to_its_tolerance(end):
    """Undamped Hertz: e = 1, alpha_max, F_max and t_c = 2.94 alpha_max/V in closed form (docs/laws.md); the error falls
    with the tolerance and is within 10 tol at each."""
    scene = Scene(e_n=(0.5,), angles_deg=(0.0,))
    law = compose("hertz-mindlin", {"damping": "none", "end": end})
    exact = oracles.hertz_elastic(scene.contact.mass, scene.radius, scene.contact.E_star, scene.speed)
    errors = []
    for tol in (1e-6, 1e-8, 1e-10):
        out = normal_run(law, scene, tol)[1][0]
        assert out[C.O_STATUS] == C.STATUS_OK
        error = max(abs(out[C.O_VZ] / scene.speed - 1.0), abs(out[C.O_AMAX] / exact["alpha_max"] - 1.0),
                    abs(out[C.O_FMAX] / exact["f_max"] - 1.0), abs(out[C.O_TC] / exact["t_c"] - 1.0))
        assert error < 10 * tol, (tol, error)
        errors.append(error)
    assert errors[2] < errors[0] / 100, errors


@pytest.mark.parametrize("name", ["thornton", "stronge"])
def test_plastic_impacts_match_an_independent_integration(name):
    """Thornton and Stronge normal impacts at three speeds: e, t_c and F_max of the converged mode within 1e-8 of
    scipy's DOP853 integration of the same force law (oracles.thornton_impact, stronge_impact)."""
    impact = oracles.thornton_impact if name == "thornton" else oracles.stronge_impact
    for e_n in (0.9, 0.5, 0.1):
        scene = Scene(e_n=(e_n,), angles_deg=(0.0,))
        law = adaptive_law(name)
        p_y = law.normal.yield_pressure(scene.contact, e_n, scene.speed)
        exact = impact(p_y, scene.contact.E_star, scene.radius, scene.contact.mass, scene.speed)
        row = simulate(law, scene, converged=True)[0].iloc[0]
        assert row.e_n == pytest.approx(exact["e"], abs=1e-8)
        assert row.t_contact == pytest.approx(exact["t_c"], rel=1e-8)
        assert row.f_n_max == pytest.approx(exact["f_max"], rel=1e-8)


@pytest.mark.parametrize("name", ["hertz-mindlin", "hertz-kuwabara-kono", "linear-spring-dashpot"])
def test_damped_impacts_match_an_independent_integration(name):
    """Damped normal impacts (Tsuji alpha^1/4, Kuwabara-Kono alpha^1/2, constant dashpot; no tension): e within 1e-8,
    t_c and F_max within 1e-7 of scipy's DOP853 on m alpha'' = -(F_el + c0 alpha^p alpha')."""
    for e_n in (0.9, 0.5, 0.1):
        scene = Scene(e_n=(e_n,), angles_deg=(0.0,))
        law = adaptive_law(name)
        batch = normal_run(law, scene, 1e-3)[0]
        p = batch.params[0]
        k, c0, power = p[L.NORMAL_BLOCK], p[L.DAMPING_C0], p[L.DAMPING_POWER]   # k: the kernel's first slot
        hertz = name != "linear-spring-dashpot"
        radius = scene.radius

        def force(a, a_dot):
            elastic = 4.0 / 3.0 * k * np.sqrt(radius) * oracles._ppow(a, 1.5) if hertz else k * a
            return elastic + c0 * (oracles._ppow(a, power) if power else 1.0) * a_dot
        exact = oracles.normal_impact(force, scene.contact.mass, scene.speed, end="force")
        row = simulate(law, scene, converged=True)[0].iloc[0]
        assert row.e_n == pytest.approx(exact["e"], abs=1e-8)
        assert row.t_contact == pytest.approx(exact["t_c"], rel=1e-7)
        assert row.f_n_max == pytest.approx(exact["f_max"], rel=1e-7)


@pytest.mark.parametrize("name", ADAPTIVE_LAWS)
def test_agrees_with_the_graded_richardson_ladder(name):
    """Oblique sweeps (stick, slip, stick again; at Stronge's and Thornton's yield kink the cone's rate jumps and a
    sliding contact sticks there): the adaptive integrator and the second-order kernel's graded Richardson ladder,
    two independent discretisations of the same law, agree within 5e-7 (e_n, e_t, Omega*; t_c, F_max relative)."""
    law = adaptive_law(name)
    adaptive = simulate(law, SWEEP, converged=True)[0]
    ladder = simulate(law, SWEEP, converged=True, extrapolate=True)[0]
    assert adaptive.message.str.startswith("converged: adaptive").all()
    assert ladder.message.str.startswith("converged: Richardson").all()
    for col in ("e_n", "e_t", "omega_star", "t_contact", "f_n_max"):
        scale = ladder[col].abs() if col in ("t_contact", "f_n_max") else 1.0
        error = ((adaptive[col] - ladder[col]).abs() / scale).fillna(0.0)
        assert error.max() < 5e-7, (col, error.max(), adaptive.theta_deg[error.idxmax()])


def test_error_is_proportional_to_the_tolerance():
    """Hertz-Mindlin sweep against the ladder's extrapolated 2^16/2^15 uniform runs: the worst error of e_n, e_t and
    Omega* falls at least 30x per 100x in tolerance, and the force evaluations grow like tol^(-1/5) (fifth
    order) - at most 2.5x per 100x."""
    law = adaptive_law("hertz-mindlin")
    scene = Scene(e_n=(0.5,), angles_deg=(5.0, 25.0, 45.0, 65.0, 85.0))
    fine = simulate(law, scene, steps_per_contact=2 ** 16)[0]
    half = simulate(law, scene, steps_per_contact=2 ** 15)[0]
    batch = adaptive_batch(law, scene, 0.5)[0]
    errors, evaluations = [], []
    for tol in (1e-5, 1e-7, 1e-9):
        out = run_adaptive(batch, np.arange(len(fine)), tol)[0]
        errors.append(max(np.abs(out[:, col] - (f + (f - h) / 3)).max() / scene.speed
                          for col, f, h in ((C.O_VZ, fine.v_n1, half.v_n1), (C.O_VX, fine.v_t1, half.v_t1))))
        evaluations.append(out[:, C.O_STEPS].mean())
    assert errors[1] < errors[0] / 30 and errors[2] < errors[1] / 30, errors
    assert evaluations[1] < 2.5 * evaluations[0] and evaluations[2] < 2.5 * evaluations[1], evaluations


def test_adaptive_costs_a_fraction_of_brute_force_refinement(count_kernel_steps):
    """The converged mode on a 3 e_n x 12 angle sweep, with the same stopping rule as plain doubling of uniform
    steps (successive results within 1e-6): the adaptive integrator's force evaluations, both tolerances, are at
    most a fifth of brute force's steps (each one force evaluation); counted, not timed (benchmarks/
    bench_converged.py times both, and the graded Richardson ladder)."""
    law = adaptive_law("hertz-mindlin")
    brute, brute_steps = count_kernel_steps(law, SWEEP, converged=True, extrapolate=False)
    adaptive = simulate(law, SWEEP, converged=True)[0]
    assert brute.message.str.contains("steps/contact agree").all() and adaptive.message.str.contains("adaptive").all()
    assert adaptive.steps_per_contact.sum() * 5 <= brute_steps, (adaptive.steps_per_contact.sum(), brute_steps)


def test_a_row_that_never_separates_is_not_called_converged():
    """A sphere resting on the wall under gravity (speed 1e-4 m/s, g = 9.81) never leaves within the step cap: its
    status says so and its message does not claim convergence."""
    scene = Scene(e_n=(0.1,), angles_deg=(0.0,), speed=1e-4, gravity=9.81)
    row = simulate(adaptive_law("hertz-mindlin"), scene, converged=True)[0].iloc[0]
    assert row.status == "no-separation" and row.message.startswith("no-separation: no release"), row.message


@settings(max_examples=100, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.sampled_from(ADAPTIVE_LAWS), st.floats(0.05, 0.95), st.one_of(st.just(0.0), st.floats(1e-6, 89.5)),
       st.floats(0.05, 1.5))
def test_two_independent_converged_methods_agree_anywhere(name, e_n, angle, mu):
    """Random law, e_n, angle and friction: the adaptive integrator and the graded Richardson ladder (each claims
    1e-6) agree within 2e-6 on e_n, e_t and Omega*, and both end with a release."""
    scene = Scene(e_n=(e_n,), angles_deg=(angle,), mu=mu)
    law = adaptive_law(name)
    adaptive = simulate(law, scene, converged=True)[0].iloc[0]
    ladder = simulate(law, scene, converged=True, extrapolate=True)[0].iloc[0]
    assert adaptive.status == "ok" and ladder.status == "ok", (adaptive.message, ladder.message)
    for col in ("e_n", "e_t", "omega_star"):
        if not np.isnan(ladder[col]):
            assert abs(adaptive[col] - ladder[col]) < 2e-6, (col, adaptive[col], ladder[col], adaptive.message)


def test_a_stick_that_lasts_to_the_release_falls_back_to_the_ladder():
    """A tangential speed 1e-49 of the normal one (Stronge, mu 1): the spring sticks until the force is ~1e-27 of
    its peak, where the adaptive step underflows; that row is taken from the ladder and says so, and its e_t is
    the same linear-response value as at a tangential speed 1e-22 of the normal one."""
    scene = Scene(e_n=(0.5,), angles_deg=(1.1080192333773765e-47, 1e-20), mu=1.0)
    frame = simulate(compose("stronge"), scene, converged=True)[0]
    assert frame.message[0].endswith("(the adaptive step underflowed or stalled)") and frame.status[0] == "ok"
    assert frame.message[1].startswith("converged: adaptive")
    assert frame.e_t[0] == pytest.approx(frame.e_t[1], abs=1e-6)


def test_the_ladder_may_go_finer_than_a_users_time_step_bound():
    """linear-spring-dashpot at e_n 0.5 and 21 deg (the spring-first Coulomb test switching inside the contact) needs
    2^20 graded steps, finer than the 1e6 steps per contact a user's --dt may ask for: the ladder runs them, and its
    e_n is the exact linear dashpot's target (theory: e_n = exp(-pi zeta/sqrt(1 - zeta^2)) set to 0.5)."""
    row = simulate(compose("linear-spring-dashpot"), Scene(e_n=(0.5,), angles_deg=(21.0,)), converged=True)[0].iloc[0]
    assert row.status == "ok" and row.message.startswith("converged: Richardson"), row.message
    assert row.steps_per_contact > 1e6
    assert row.e_n == pytest.approx(0.5, abs=1e-7)
