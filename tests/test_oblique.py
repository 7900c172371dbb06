"""Oblique impacts in the paper's normalisation: rigid-body sliding limits, the linear sticking identity, identities
and energy (docs/laws.md#normalisation)."""
import numpy as np
import pytest

from harness.laws import LAWS, compose
from harness.scenes.scene import Scene

VISCOUS = ("linear-spring-dashpot", "hertz-mindlin", "hertz-kuwabara-kono")
PSI_SLIDING = (10.0, 20.0, 40.0)     # the paper's Psi1*; a rigid sphere slides throughout from 7


def sliding_frame(name, e):
    scene = Scene(e_n=(e,), angles_deg=None, psi1_star=PSI_SLIDING)
    return scene, simulate_converged(name, scene)


def simulate_converged(name, scene, overrides=None):
    from harness.solver.simulate import simulate
    return simulate(compose(name, overrides), scene, converged=True)[0]


@pytest.mark.parametrize("name", [n for n in LAWS if n not in VISCOUS])
@pytest.mark.parametrize("e", [0.9, 0.5, 0.1])
def test_sliding_throughout_matches_rigid_body(name, e):
    """Omega* = -5 and Psi2* = Psi1* - 7 (rigid-body sliding, the paper's lines) within 1% well above the onset."""
    scene, frame = sliding_frame(name, e)
    row = frame.iloc[-1]
    assert row.omega_star == pytest.approx(-5.0, rel=0.01)
    assert row.psi2_star == pytest.approx(row.psi1_star - 7.0, rel=0.01)
    # and exactly the rigid-body centre velocity: V_tr = V_ti - mu (1 + e) V_n with the achieved e
    assert row.v_t1 == pytest.approx(row.v_t0 - scene.mu * (1 + row.e_n) * row.v_n0, rel=0.01)


@pytest.mark.parametrize("name", ["linear-spring-dashpot", "hertz-mindlin"])
def test_tangential_dashpot_makes_viscous_laws_slide_throughout(name):
    """With the paper's tangential dashpot (c_t = 2 g sqrt(m k_t) on a sticking spring) a viscous law's friction is
    at the Coulomb cone from first touch at large Psi1*: exactly the rigid-body line, Omega* = -5 (the kernel's
    sliding steps carry mu times the normal impulse, dashpot-held ones included)."""
    for e in (0.9, 0.5, 0.1):
        _, frame = sliding_frame(name, e)
        assert frame.omega_star.iloc[-1] == pytest.approx(-5.0, abs=1e-9)
        assert frame.psi2_star.iloc[-1] == pytest.approx(frame.psi1_star.iloc[-1] - 7.0, abs=1e-8)


@pytest.mark.parametrize("name,overrides", [("linear-spring-dashpot", {"tangential-damping": "none"}),
                                            ("hertz-mindlin", {"tangential-damping": "none"}),
                                            ("hertz-kuwabara-kono", {})])
def test_viscous_laws_without_tangential_dashpot_approach_sliding_line_only_slowly(name, overrides):
    """Documented dashpot lag (docs/laws.md): a normal dashpot loads the contact before the tangential spring does,
    so without a tangential dashpot viscous laws reach the sliding line only as Psi1* grows: within 1% at
    Psi1* = 40 for e >= 0.5, and at e = 0.1 the gap to Omega* = -5 shrinks monotonically with Psi1* but stays
    up to 25%."""
    for e in (0.9, 0.5):
        frame = simulate_converged(name, Scene(e_n=(e,), angles_deg=None, psi1_star=PSI_SLIDING), overrides)
        assert frame.omega_star.iloc[-1] == pytest.approx(-5.0, rel=0.01)
    frame = simulate_converged(name, Scene(e_n=(0.1,), angles_deg=None, psi1_star=PSI_SLIDING), overrides)
    gap = 5.0 + frame.omega_star.to_numpy()
    assert np.all(gap > 0) and np.all(np.diff(gap) < 0)
    assert gap[-1] / 5.0 < 0.25


def test_linear_elastic_sticking_reverses_contact_point_velocity():
    """Linear spring, e = 1, k_t/k_n = 2/7 (equal periods), sticking throughout: V_sr = -V_si (Maw et al. 1976)."""
    scene = Scene(e_n=(1.0,), angles_deg=None, psi1_star=(0.1, 0.3, 0.6))
    frame = simulate_converged("linear-spring-dashpot", scene, {"end": "tension", "tangential": "linear:2/7"})
    assert np.allclose(frame.e_n, 1.0, atol=1e-9)
    assert np.allclose(frame.psi2_star, -frame.psi1_star, rtol=0, atol=1e-3 * frame.psi1_star.max())
    assert np.allclose(frame.psi2_maw, -frame.psi1_maw, rtol=0, atol=1e-3 * frame.psi1_maw.max())


@pytest.mark.parametrize("name", list(LAWS))
def test_rotation_and_centre_identities(name):
    """No initial spin: R omega_r = 5/2 (V_ti - V_tr) and e_t = 5/7 + 2/7 Psi2*/Psi1* (the paper's identity)."""
    scene = Scene(e_n=(0.7,), angles_deg=(10.0, 30.0, 50.0, 70.0))
    from harness.solver.simulate import simulate
    frame = simulate(compose(name), scene, steps_per_contact=500)[0]
    assert np.allclose(scene.radius * frame.omega1, 2.5 * (frame.v_t0 - frame.v_t1), rtol=1e-9, atol=1e-12)
    assert np.allclose(frame.e_t, 5 / 7 + 2 / 7 * frame.psi2_star / frame.psi1_star, rtol=1e-9)


@pytest.mark.parametrize("name", list(LAWS))
def test_no_law_gains_kinetic_energy(name):
    """Over e_n x angles x mu, including spin against the motion, KE after <= KE before."""
    from harness.solver.simulate import simulate
    for mu in (0.0, 0.1, 0.5, 2.0):
        for omega0 in (0.0, -300.0):
            scene = Scene(e_n=(1.0, 0.9, 0.5, 0.1), angles_deg=(0.0, 5.0, 20.0, 45.0, 70.0, 89.5), mu=mu,
                          omega0=omega0)
            frame = simulate(compose(name), scene, steps_per_contact=200)[0]
            assert (frame.status == "ok").all()
            if name == "stronge":
                frame = frame[~in_stronge_gain_band(frame, scene)]
            assert frame.ke_ratio.max() <= 1.0 + 1e-9, frame.loc[frame.ke_ratio.idxmax()].to_dict()


def stronge_ratio(frame, scene):
    """V_n/V_y per row for the provisional Stronge law (V_y from 1/2 m V_y^2 = 2/5 F_y alpha_y)."""
    law = compose("stronge")
    contact = scene.contact
    ratio = np.empty(len(frame))
    for i, (e, v_n) in enumerate(zip(frame.e_n_target, frame.v_n0)):
        parameters = law.normal.parameters(contact, e, scene.speed)
        alpha_y, f_y = parameters["alpha_y"], parameters["f_y"]
        ratio[i] = v_n / np.sqrt(0.8 * f_y * alpha_y / contact.mass)
    return ratio


def in_stronge_gain_band(frame, scene):
    """Rows with 1 <= V_n/V_y < 1.56, where the provisional Stronge reconstruction returns e > 1 (see below)."""
    ratio = stronge_ratio(frame, scene)
    return (ratio >= 1.0 - 1e-9) & (ratio < 1.56)


def test_provisional_stronge_gains_energy_just_above_yield():
    """FINDING on docs/laws.md's reconstruction: its plastic branch F_y (2 alpha/alpha_y - 1) is stiffer than Hertz at
    yield (2 vs 1.5 F_y/alpha_y), so e = x^3/4 V_y/V exceeds 1 for 1 < V/V_y < ~1.55 (max ~1.018 at 1.25).
    The solver reproduces that closed form there; this test fails once the law is replaced by one that does not."""
    scene = Scene(e_n=(0.9,), angles_deg=tuple(np.degrees(np.arccos(np.linspace(0.01, 1.0, 400)))), mu=0.0)
    from harness.solver.simulate import simulate
    frame = simulate(compose("stronge"), scene, steps_per_contact=2000)[0]
    ratio = stronge_ratio(frame, scene)
    row = np.argmin(np.abs(ratio - 1.25))
    x = np.sqrt(1 + 1.6 * (ratio[row] ** 2 - 1))
    assert frame.e_n.iloc[row] == pytest.approx(x ** 0.75 / ratio[row], abs=1e-4)
    assert frame.e_n.iloc[row] > 1.01
    assert frame.e_n[ratio > 1.6].max() < 1.0


@pytest.mark.parametrize("form", ["linear", "mindlin:rescale", "mindlin:incremental", "mindlin:total",
                                  "mindlin-deresiewicz", "walton-braun"])
def test_every_tangential_form_reaches_the_sliding_limit(form):
    """Each tangential sub-model on the Thornton law: rigid-body sliding at Psi1* = 40."""
    scene = Scene(e_n=(0.5,), angles_deg=None, psi1_star=(40.0,))
    row = simulate_converged("thornton", scene, {"tangential": form}).iloc[0]
    assert row.omega_star == pytest.approx(-5.0, rel=1e-3)


def test_tangential_forms_differ_where_theory_says():
    """Sticking regime: Mindlin forms differ (eq. 18b rescale removes spurious unloading energy, docs/laws.md), while
    all coincide in full sliding; a form switch that changed nothing would fail here."""
    scene = Scene(e_n=(0.5,), angles_deg=None, psi1_star=(2.4,))
    results = {form: simulate_converged("thornton", scene, {"tangential": form}).iloc[0].psi2_star
               for form in ("mindlin:rescale", "mindlin:incremental", "mindlin-deresiewicz")}
    assert abs(results["mindlin:rescale"] - results["mindlin:incremental"]) > 1e-3
    assert abs(results["mindlin-deresiewicz"] - results["mindlin:incremental"]) > 1e-3
