"""Solver properties: second-order convergence, converged mode accuracy, and only the effects a scene needs."""
import math

import numpy as np
import pytest
from conftest import EXAMPLE

from harness.laws import LAWS, compose
from harness.scenes.scene import Scene
from harness.solver import layout as L
from harness.solver import dispatch as D
from harness.solver.simulate import batch_at, simulate


def test_converged_mode_is_within_1e6_of_exact_lsd():
    """Tension-allowed LSD: e is exact by construction of g (docs/laws.md), so the converged e_n must be within 1e-6."""
    scene = Scene(e_n=(0.9, 0.5, 0.2), angles_deg=(0.0,))
    frame = simulate(compose("linear-spring-dashpot", {"end": "tension"}), scene, converged=True)[0]
    assert np.allclose(frame.e_n, frame.e_n_target, rtol=1e-6, atol=0)
    assert frame.message.str.startswith("converged").all()


@pytest.mark.parametrize("name", list(LAWS))
def test_converged_mode_agrees_with_much_finer_run(name):
    """Converged results sit within 1e-6 (per V) of a brute-force run at 4x the finest converged resolution."""
    scene = Scene(e_n=(0.5,), angles_deg=(0.0, 30.0, 60.0))
    law = compose(name)
    conv = simulate(law, scene, converged=True)[0]
    fine = simulate(law, scene, steps_per_contact=int(conv.steps_per_contact.max()) * 4)[0]
    for col, scale in (("v_n1", scene.speed), ("v_t1", scene.speed), ("omega1", scene.speed / scene.radius)):
        assert np.allclose(conv[col], fine[col], rtol=0, atol=1e-6 * scale), col


@pytest.mark.parametrize("name", ["linear-spring-dashpot", "hertz-mindlin", "hertz-kuwabara-kono", "walton-braun"])
def test_normal_impact_converges_at_second_order(name):
    """Halving dt divides the error of e_n by ~4 (velocity Verlet on u = m alpha_dot + D(alpha))."""
    scene = Scene(e_n=(0.5,), angles_deg=(0.0,))
    law = compose(name)
    values = [simulate(law, scene, steps_per_contact=n)[0].e_n.iloc[0] for n in (100, 200, 400, 800)]
    diffs = np.abs(np.diff(values))
    orders = np.log2(diffs[:-1] / diffs[1:])
    assert orders.min() > 1.7, orders


@pytest.mark.parametrize("name", ["thornton", "stronge"])
def test_plastic_laws_error_falls_like_dt_squared(name):
    """Thornton/Stronge: the sampled turning point makes the error erratic, but it stays under C/N^2 against the
    exact e of an independent ODE integration (tests/oracles.py)."""
    import oracles
    scene = Scene(e_n=(0.5,), angles_deg=(0.0,))
    law = compose(name)
    p_y = law.normal.yield_pressure(scene.contact, 0.5, scene.speed)
    impact = oracles.thornton_impact if name == "thornton" else oracles.stronge_impact
    exact = impact(p_y, scene.contact.E_star, scene.radius, scene.contact.mass, scene.speed)["e"]
    steps = np.array([100, 200, 400, 800, 1600])
    errors = np.array([abs(simulate(law, scene, steps_per_contact=int(n))[0].e_n.iloc[0] - exact) for n in steps])
    assert (errors * steps ** 2).max() <= 0.5, errors


def test_normal_impact_skips_tangential_model_and_rotation():
    scene = Scene(e_n=(0.5,), angles_deg=(0.0, 30.0))
    batch = batch_at(compose("hertz-mindlin"), scene, 0.5, 100)
    assert list(batch.ints[:, L.I_TANGENTIAL]) == [D.TANGENTIAL_NONE, D.TANGENTIAL_MINDLIN_RESCALE]
    frame = simulate(compose("hertz-mindlin"), scene, steps_per_contact=100)[0]
    assert frame.omega1.iloc[0] == 0.0 and frame.v_t1.iloc[0] == 0.0


def test_frictionless_scene_needs_no_tangential_model():
    scene = Scene(e_n=(0.5,), angles_deg=(30.0, 60.0), mu=0.0)
    batch = batch_at(compose("thornton"), scene, 0.5, 100)
    assert (batch.ints[:, L.I_TANGENTIAL] == D.TANGENTIAL_NONE).all()
    frame = simulate(compose("thornton"), scene, steps_per_contact=100)[0]
    assert (frame.v_t1 == frame.v_t0).all() and (frame.omega1 == 0.0).all()


def test_spin_alone_switches_the_tangential_model_on():
    scene = Scene(e_n=(0.5,), angles_deg=(0.0,), omega0=100.0)
    batch = batch_at(compose("thornton"), scene, 0.5, 100)
    assert batch.ints[0, L.I_TANGENTIAL] != D.TANGENTIAL_NONE
    row = simulate(compose("thornton"), scene, steps_per_contact=400)[0].iloc[0]
    assert row.omega1 < 100.0 and row.v_t1 > 0.0     # friction converts spin into forward motion


def test_gravity_only_when_set_and_then_it_acts():
    """With gravity, the LSD impact matches an independent ODE integration of m a'' = -(k a + c a') + m g."""
    from oracles import normal_impact
    base = Scene(e_n=(0.5,), angles_deg=(0.0,), speed=0.01)
    assert batch_at(compose("thornton"), base, 0.5, 100).params[0, L.GRAVITY] == 0.0
    heavy = Scene(e_n=(0.5,), angles_deg=(0.0,), speed=0.01, gravity=9.81)
    law = compose("linear-spring-dashpot", {"end": "tension"})
    batch = batch_at(law, heavy, 0.5, 100)
    m, k, c = heavy.contact.mass, batch.params[0, L.NORMAL_LINEAR_K_N], batch.params[0, L.DAMPING_C0]
    expected = normal_impact(lambda a, ad: k * a + c * ad - m * 9.81, m, 0.01, end="alpha")
    still = simulate(law, base, converged=True)[0].iloc[0]
    fallen = simulate(law, heavy, converged=True)[0].iloc[0]
    assert fallen.e_n == pytest.approx(expected["e"], abs=1e-6)
    assert fallen.t_contact == pytest.approx(expected["t_c"], rel=1e-6)
    assert abs(fallen.e_n - still.e_n) > 1e-3              # and gravity made a difference here


def test_force_history_only_when_asked_and_consistent():
    scene = Scene(e_n=(0.5,), angles_deg=(0.0,))
    law = compose("walton-braun")
    frame, none = simulate(law, scene, steps_per_contact=400)
    assert none == {}
    frame, histories = simulate(law, scene, steps_per_contact=400, history_points=200)
    hist = histories[0.5][0]
    hist = hist[~np.isnan(hist[:, 0])]
    assert hist[:, 2].max() == pytest.approx(frame.f_n_max.iloc[0], rel=1e-3)
    assert hist[-1, 0] <= frame.t_contact.iloc[0] + 1e-12


def test_psi_scene_hits_requested_normalised_angle():
    """Psi1* input: 2 V_t/(mu (1 + e_target) V_n) equals the request (the paper's normalisation); Maw's form is
    kappa (1 + e)/2 times it."""
    scene = Scene(e_n=(0.5,), angles_deg=None, psi1_star=(0.5, 2.0, 8.0))
    frame = simulate(compose("walton-braun"), scene, steps_per_contact=200)[0]
    assert np.allclose(2 * frame.v_t0 / (frame.mu * 1.5 * frame.v_n0), [0.5, 2.0, 8.0], rtol=1e-12)
    assert np.allclose(frame.psi1_maw, scene.contact.kappa * 1.5 / 2 * np.array([0.5, 2.0, 8.0]), rtol=1e-12)


def test_rigid_wall_is_stiffer_than_same_material():
    same = Scene(e_n=(1.0,), angles_deg=(0.0,), wall="same")
    rigid = Scene(e_n=(1.0,), angles_deg=(0.0,), wall="rigid")
    assert rigid.contact.E_star == pytest.approx(2 * same.contact.E_star)
    law = compose("hertz-mindlin", {"damping": "none", "end": "tension"})
    t_same = simulate(law, same, steps_per_contact=400)[0].t_contact.iloc[0]
    t_rigid = simulate(law, rigid, steps_per_contact=400)[0].t_contact.iloc[0]
    assert t_rigid / t_same == pytest.approx(2 ** -0.4, rel=1e-4)    # t_c ~ E*^-2/5


def test_wall_of_another_material_combines_both_compliances():
    """E* = 1/[(1-nu1^2)/E1 + (1-nu2^2)/E2] and G* likewise (docs/laws.md), checked against hand-written formulas."""
    scene = Scene(e_n=(1.0,), angles_deg=(0.0,), E=70e9, nu=0.3, wall="other", wall_E=200e9, wall_nu=0.25)
    e_star = 1 / ((1 - 0.3 ** 2) / 70e9 + (1 - 0.25 ** 2) / 200e9)
    g1, g2 = 70e9 / (2 * 1.3), 200e9 / (2 * 1.25)
    assert scene.contact.E_star == pytest.approx(e_star, rel=1e-12)
    assert scene.contact.G_star == pytest.approx(1 / ((2 - 0.3) / g1 + (2 - 0.25) / g2), rel=1e-12)


def test_material_presets_give_valid_scenes():
    from harness.scenes.materials import MATERIALS
    from harness.scenes.scene import from_material
    for name, mat in MATERIALS.items():
        scene = from_material(name, e_n=(0.5,), angles_deg=(30.0,))
        assert scene.radius == mat.radius and mat.source
        frame = simulate(compose("hertz-mindlin"), scene, steps_per_contact=100)[0]
        assert (frame.status == "ok").all()


def test_psi_and_vt_scenes_hold_the_normal_speed():
    """With Psi1* or V_t lists, --speed is V_n: a plastic law calibrated at V_n keeps e_n at its target."""
    for scene in (Scene(e_n=(0.3,), angles_deg=None, psi1_star=(0.5, 2.0, 8.0), speed=2.0),
                  Scene(e_n=(0.3,), angles_deg=None, v_t=(0.0, 0.5, 3.0), speed=2.0)):
        frame = simulate(compose("thornton"), scene, steps_per_contact=2000)[0]
        assert np.allclose(frame.v_n0, 2.0)
        assert np.allclose(frame.e_n, 0.3, atol=1e-4)
    frame = simulate(compose("thornton"), Scene(e_n=(0.3,), angles_deg=None, v_t=(0.0, 0.5, 3.0), speed=2.0),
                     steps_per_contact=200)[0]
    assert np.allclose(frame.v_t0, [0.0, 0.5, 3.0])
    assert np.allclose(frame.theta_deg, np.degrees(np.arctan2([0, .5, 3], 2)))


NO_DASHPOT = {"tangential-damping": "none"}


@pytest.mark.parametrize("name, overrides, e_n, angle", [
    ("thornton", {}, 0.5, 30.0), ("linear-spring-dashpot", {}, 0.5, 85.0), ("linear-spring-dashpot", {}, 0.5, 30.0),
    ("hertz-mindlin", {}, 0.5, 25.0), ("hertz-mindlin", NO_DASHPOT, 0.5, 25.0),
    ("hertz-mindlin", NO_DASHPOT, 0.5, 41.0),
    ("partially-latching-spring", {}, 0.9, 1.0), ("stronge", {}, 0.5, 30.0)])
def test_regime_changes_located_in_their_step_make_the_error_smooth(name, overrides, e_n, angle):
    """Turning point, yield and stick-slip transitions (also inside the release step) are located inside their
    step, so the error is c h^2 + O(h^3) and Richardson's R = f_N + (f_N - f_N/2)/3 is far closer than f_N
    (without the location, the transitions leave an O(h^2) term that depends on where they fall in the step: R
    gained less than 3x at Hertz-Mindlin 41 deg before the end of sliding was located where the spring leaves the
    Coulomb cone rather than at the slip reversal). The rows are stick-slip rows of the 5 mm example scene; with the
    paper's tangential dashpot the transitions where spring and dashpot together reach the cone are located too.
    (Where such a contact slides again against a reversed slip, e.g. Hertz-Mindlin at 41 deg, the dashpot-held
    force chatters between the cone's sides for a few steps: the error stays O(h^2) but is not smooth in h.)"""
    scene = Scene(**EXAMPLE, e_n=(e_n,), angles_deg=(angle,))
    law = compose(name, overrides)
    cols = ["e_t", "omega_star"]
    def values(n):
        return simulate(law, scene, steps_per_contact=n)[0][cols].to_numpy()[0]
    truth = values(128000) + (values(128000) - values(64000)) / 3
    coarse, fine = values(320), values(640)
    plain = np.abs(fine - truth)
    richardson = np.abs(fine + (fine - coarse) / 3 - truth)
    assert np.all((richardson < plain / 20) | (plain < 1e-11)), (plain, richardson)   # Omega* exact when sliding


def test_graded_mesh_grows_like_s4_from_both_ends_and_covers_its_span():
    """Phi(s) of the converged mode's mesh: 0 and 1 at the ends, increasing, Phi ~ c s^4 at first touch and
    1 - Phi ~ c (1 - s)^4 at the end (so alpha^(1/4) ~ s there: smooth), uniform steps in the middle."""
    from harness.infra.jit import python_twin
    from harness.solver import mesh
    graded_step, graded_time = python_twin(mesh.graded_step), python_twin(mesh.graded_time)
    assert graded_time(0.0) == 0.0 and graded_time(1.0) == pytest.approx(1.0, abs=1e-15)
    s = np.linspace(0.0, 1.0, 2001)
    phi = np.array([graded_time(x) for x in s])
    assert np.all(np.diff(phi) > 0.0)
    for tiny in (1e-6, 1e-5):
        assert graded_time(2 * tiny) / graded_time(tiny) == pytest.approx(16.0, rel=1e-3)
    many = [graded_step(k, 10 ** 5, 1.0) for k in (0, 1, 10 ** 5 - 2, 10 ** 5 - 1)]
    assert many[1] / many[0] == pytest.approx(15.0, rel=1e-3) and many[2] / many[3] == pytest.approx(15.0, rel=1e-3)
    steps = np.array([graded_step(k, 1000, 2.0) for k in range(1000)])
    assert steps == pytest.approx(steps[::-1], rel=1e-9)
    assert steps.sum() == pytest.approx(2.0, rel=1e-12)
    assert np.ptp(steps[300:700]) < 1e-12 and steps[500] == pytest.approx(2.0 / 1000 / 0.9142857, rel=1e-6)
    assert graded_step(1000, 1000, 2.0) == 2.0 / 1000       # beyond the span: uniform


HARD_ROWS = Scene(e_n=(0.9, 0.1), angles_deg=(1.0, 25.0, 41.0, 85.0, 89.0))


@pytest.mark.parametrize("name", ["hertz-mindlin", "hertz-kuwabara-kono", "thornton"])
def test_converged_mode_reaches_1e6_on_hard_rows(name):
    """Grazing (a short stick at first touch), near-normal (e_t = v_t1/v_t0 magnifies) and stick-slip rows at high and
    low e_n: the converged values are within 1e-6 of the extrapolated pair 2^16/2^15 uniform steps per contact
    (e_n, e_t, Omega* absolute; t_c, F_max relative), and no row needs more than 10^4 force evaluations (the
    adaptive integrator's, both tolerances)."""
    law = compose(name, NO_DASHPOT if name == "hertz-mindlin" else None)   # the adaptive integrator's coverage
    conv = simulate(law, HARD_ROWS, converged=True)[0]
    fine = simulate(law, HARD_ROWS, steps_per_contact=2 ** 16)[0]
    half = simulate(law, HARD_ROWS, steps_per_contact=2 ** 15)[0]
    for col in ("e_n", "e_t", "omega_star", "t_contact", "f_n_max"):
        truth = fine[col] + (fine[col] - half[col]) / 3
        scale = truth.abs() if col in ("t_contact", "f_n_max") else 1.0
        error = ((conv[col] - truth).abs() / scale).fillna(0.0)
        assert error.max() < 1e-6, (col, error.max())
    assert conv.message.str.startswith("converged: adaptive").all()
    assert conv.steps_per_contact.max() <= 10 ** 4


def test_graded_ladder_costs_a_fraction_of_brute_force_refinement(count_kernel_steps):
    """The same stopping rule (two successive values within 1e-6, twice) on plain doubling and on the graded,
    extrapolated ladder (the converged mode of the rows the adaptive integrator does not cover): the ladder takes
    at most a quarter of the impact-steps (counted, not timed; the wall-time ratio is benchmarks/
    bench_converged.py's). Without the tangential dashpot: where a dashpot-held force chatters at a slip reversal
    the error is not smooth in h and the ladder gains nothing over doubling (same impact-steps within 3%)."""
    scene = Scene(e_n=(0.9, 0.5, 0.1), angles_deg=tuple(np.arange(1.0, 90.0, 8.0)))
    law = compose("hertz-mindlin", NO_DASHPOT)
    steps = {extrapolate: count_kernel_steps(law, scene, converged=True, extrapolate=extrapolate)[1]
             for extrapolate in (False, True)}
    assert steps[True] * 4 <= steps[False], steps


@pytest.mark.parametrize("engine", ["liggghts", "yade"])
def test_hysteresis_dialects_leave_their_latched_dent_at_low_e_n(engine):
    """Engine hysteresis laws keep the contact at zero force until the gap opens: after unloading (K2 = K1/e^2) the
    sphere crosses the dent alpha_max (1 - e^2) at e V, so t_c = sqrt(m/K1) [pi/2 (1 + e) + (1 - e^2)/e] (docs/laws.md,
    hysteresis, plus the dent), 64 contact-time estimates at e_n = 0.01: the step cap must allow for it (it stopped at
    40)."""
    from harness.engines import ENGINES
    e = 0.01
    scene = Scene(e_n=(e,), angles_deg=(0.0,))
    row = simulate(ENGINES[engine].dialect("walton-braun"), scene, steps_per_contact=1000)[0].iloc[0]
    assert row.status == "ok", row.message
    c = scene.contact
    v = scene.speed
    k1 = (16.0 / 15.0 * math.sqrt(c.radius) * c.E_star
          * (15.0 * c.mass * v * v / (16.0 * math.sqrt(c.radius) * c.E_star)) ** 0.2)
    t_c = math.sqrt(c.mass / k1) * (math.pi / 2.0 * (1.0 + e) + (1.0 - e * e) / e)
    assert row.t_contact == pytest.approx(t_c, rel=5e-3)        # the exit time inherits e_n's 3e-3 at 1000 steps
    assert row.e_n == pytest.approx(e, rel=1e-2)


VERLET = {"integrator": "velocity-verlet", "coulomb": "total", "end": "tension"}


def test_touch_overlap_starts_force_free_and_changes_nothing_where_the_force_at_zero_overlap_is_zero():
    """touch 'overlap' (velocity Verlet on a wall): no force before the first step, so the first step drifts at V
    and its force is k_n h V + c_n V (theory of the step); 'gap' kicks first with the dashpot's c_n V. The Hertz laws'
    force and dashpots vanish at alpha = 0, so there the two rules give the same bits."""
    from harness.solver.simulate import run_kernel
    scene = Scene(e_n=(0.6,), angles_deg=(0.0, 30.0), psi1_star=None)
    first = {}
    for touch in ("gap", "overlap"):
        law = compose("linear-spring-dashpot", {**VERLET, "touch": touch})
        batch = batch_at(law, scene, 0.6, 100)
        _, history, _ = run_kernel(batch, history_points=400)
        first[touch] = history[:, 0, 2]
        p = batch.params.T
        v, h = -p[L.VZ0], p[L.DT]
        expected = p[L.NORMAL_LINEAR_K_N] * h * v + p[L.DAMPING_C0] * v
    assert np.allclose(first["overlap"], expected, rtol=1e-12, atol=0)
    assert (np.abs(first["gap"] / expected - 1.0) > 1e-6).all()
    for name in ("hertz-mindlin", "hertz-kuwabara-kono"):
        gap, overlap = (simulate(compose(name, {**VERLET, "touch": t}), Scene(e_n=(0.3, 0.9), angles_deg=(0.0, 40.0),
                                                                                omega0=-20.0, psi1_star=None), 200)[0]
                        for t in ("gap", "overlap"))
        for column in ("v_n1", "v_t1", "omega1"):
            assert (gap[column].to_numpy() == overlap[column].to_numpy()).all(), (name, column)


@pytest.mark.parametrize("integrator", ["velocity-verlet", "leapfrog"])
def test_the_spring_first_rule_keeps_coulombs_bound_and_converges_to_the_paper_scheme(integrator):
    """Coulomb rule 'spring-first' in an explicit scheme: every step's |F_t| <= mu F_n with F_n >= 0 (no tension),
    so the impulses keep |J_t| <= mu J_n (theory; the rule 'spring', whose dashpot is added unclipped, breaks it by
    over 100%), and with the paper's Coulomb rule the scheme computes the paper law: its rebound approaches the paper
    scheme's as dt falls (1.2e-4 V at 1000 steps per contact, 3.5e-5 at 4000), where 'spring' stays 25% of V away."""
    from harness.analyses.invariants import coulomb_ratio
    scene = Scene(e_n=(0.25, 0.75), angles_deg=tuple(range(5, 90, 6)))
    paper = simulate(compose("hertz-mindlin"), scene, steps_per_contact=4000)[0]
    speed = np.hypot(paper.v_n0, paper.v_t0).to_numpy()

    def gap(rule, steps):
        frame = simulate(compose("hertz-mindlin", {"integrator": integrator, "coulomb": rule}), scene,
                         steps_per_contact=steps)[0]
        worst = max(np.max(np.abs(frame[c] - paper[c]).to_numpy() * (frame.radius.to_numpy() if c == "omega1" else 1)
                           / speed) for c in ("v_n1", "v_t1", "omega1"))
        return worst, np.nanmax(coulomb_ratio(frame))
    (coarse, ratio), (fine, _) = gap("spring-first", 1000), gap("spring-first", 4000)
    assert ratio <= 1.0 + 1e-10 and fine < coarse / 3.0 and fine < 5e-5          # the bound within round-off
    unclipped, over = gap("spring", 4000)
    assert unclipped > 0.2 and over > 2.0


def test_touch_overlap_is_refused_where_the_stepper_has_no_such_rule():
    from harness.infra.errors import UserError
    with pytest.raises(UserError, match="applies touch rule gap, not overlap"):
        compose("linear-spring-dashpot", {"touch": "overlap"})


def test_contact_radius_spring_applies_k_a_and_resets_to_the_displacement_of_k_alone():
    """F = -k a xi after the increment; a capped force F leaves xi = -F/k, so with no further slip the next step
    gives a F (the contact radius once more)."""
    from harness.submodels.registry import code_of, python_point
    code = code_of("tangential", "contact-radius-spring")
    spring, after_cap = (python_point("tangential", code, point) for point in ("spring", "after_cap"))
    st = np.zeros(8)
    k, a = 3.0e5, 2.0e-3
    assert math.isclose(spring(k, 0.0, 1e-6, a, a, a, 0.1, 0.0, 0.0, st, None, False), -k * a * 1e-6)
    after_cap(k, -0.25, a, st)
    assert math.isclose(spring(k, 0.0, 0.0, a, a, a, 0.1, 0.0, 0.0, st, None, False), -0.25 * a)


@pytest.mark.parametrize("integrator", ["velocity-verlet", "leapfrog"])
@pytest.mark.parametrize("rule", ["spring", "total", "total-cases", "spring-first"])
def test_a_share_of_the_normal_dashpot_is_the_tangential_dashpot_it_equals(integrator, rule):
    """c_t = x c_n with a constant c_n (linear-spring-dashpot) is the constant dashpot c_t = g m with g = x c_n/m:
    the slot 'share' and the prefactor path give one rebound (to round-off), under every Coulomb rule; without the
    share the two differ by more than 1e-3 V."""
    from dataclasses import replace

    from harness.submodels.tangential_damping import GivenTangentialDashpot
    scene = Scene(e_n=(0.5,), angles_deg=(10.0, 30.0, 50.0, 70.0), omega0=-30.0, psi1_star=None)
    law = compose("linear-spring-dashpot", {"integrator": integrator, "coulomb": rule, "end": "tension"})
    contact = scene.contact
    c_n = law.damping.dashpot(law.normal, contact, 0.5, scene.speed, law.end).c0
    k_t = law.tangential.parameter(contact, law.normal.parameters(contact, 0.5, scene.speed).linear_stiffness)
    share = 0.7
    frames = [simulate(replace(law, tangential_damping=dashpot), scene, 400)[0]
              for dashpot in (GivenTangentialDashpot(share, 0.0, k_t, 0.0),
                              GivenTangentialDashpot(0.0, share * c_n / contact.mass, k_t, 0.0),
                              GivenTangentialDashpot(0.0, 0.0, k_t, 0.0))]
    speed = np.hypot(frames[0].v_n0, frames[0].v_t0).to_numpy()

    def gap(a, b):
        return max(np.max(np.abs(a[c] - b[c]).to_numpy() * (a.radius.to_numpy() if c == "omega1" else 1) / speed)
                   for c in ("v_n1", "v_t1", "omega1"))
    assert gap(frames[0], frames[1]) < 1e-12
    assert gap(frames[0], frames[2]) > 1e-3
