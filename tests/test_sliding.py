"""The sliding-throughout threshold: found from simulation (located stick events) against the conditions derived in
docs/laws.md#sliding-throughout, and against the rigid-body impulse it implies."""
import math

import numpy as np
import pytest

import oracles
from harness.laws import compose
from harness.scenes.scene import Scene
from harness.analyses.sliding import derived_threshold, impulse_deficit
from harness.studies.sliding_search import sliding_thresholds
from harness.solver.simulate import simulate

PAPER_EN = (0.25, 0.5, 0.75, 0.9)
KAPPA = 2 * 0.7 / 1.7          # 2(1 - nu)/(2 - nu) at nu = 0.3


HIDDEN_STICK = 5e-5    # a stick shorter than one of the search's steps, just before the release, hides (2.2e-5 found
                       # for the linear law at e 0.25: its spring leaves the cone within the last step)


def hand_formula(name, overrides, e):
    """The derived conditions written out again here, by hand, for the paper's nu = 0.3."""
    tangential = (overrides or {}).get("tangential", "")
    if (overrides or {}).get("tangential-damping", "").endswith(":total"):
        return 7.0                                      # a dashpot-held contact sticks once V_s reaches 0
    if name == "linear-spring-dashpot":                 # the spring leaves the shrinking cone at the release
        return 7.0 - 2.0 * e / (KAPPA * (1 + e))
    if name in ("thornton", "stronge"):
        lam = 1.0 if tangential == "mindlin:incremental" else 2.0 / 3.0
        return 7.0 - 2.0 * lam * e / (KAPPA * (1 + e))
    q = KAPPA if tangential == "linear:kappa" else 2.0 / 7.0          # the latching spring's k_t = q K1
    return max(2 * max(3.5, 1 / q) / (1 + e), 7 - 2 / (q * e * (1 + e)))


@pytest.mark.parametrize("name, overrides", [
    ("thornton", None), ("thornton", {"tangential": "mindlin:incremental"}), ("stronge", None),
    ("partially-latching-spring", None), ("partially-latching-spring", {"tangential": "linear:kappa"}),
    ("walton-braun", {"tangential": "linear:kappa"}), ("linear-spring-dashpot", None),
    ("linear-spring-dashpot", {"tangential-damping": "classical:sphere-mass"}),
    ("linear-spring-dashpot", {"tangential-damping": "normal-ratio:total"}),
    ("hertz-mindlin", {"tangential-damping": "normal-ratio:total"})])
def test_simulated_threshold_meets_the_derived_condition(name, overrides):
    """At the paper's e_n the threshold found from simulation is within its bracket (+1e-5) of the condition,
    which the code computes and this test writes out by hand (a stick hidden in the last step may lower it)."""
    law = compose(name, overrides)
    scene = Scene(e_n=PAPER_EN)
    for found in sliding_thresholds(law, scene):
        expected = hand_formula(name, overrides, found.e_n)
        assert found.derived == pytest.approx(expected, abs=1e-12)
        assert -HIDDEN_STICK <= found.simulated - expected <= found.resolution + 1e-5, (found, expected)


def test_hertz_mindlin_threshold_meets_the_oracles_condition():
    """The paper's Hertz law (spring-first tangential dashpot): the threshold found from simulation is where a spring
    on the shrinking cone can no longer follow it, found by oracles.tsuji_mindlin_sliding_threshold from the normal
    impact alone (scipy, no harness code); it binds at the release for e 0.25 and 0.5 (7 - 5e/(3 kappa (1 + e)))
    and before it at 0.75 and 0.9. No closed form is claimed."""
    law = compose("hertz-mindlin")
    for found in sliding_thresholds(law, Scene(e_n=PAPER_EN)):
        expected, achieved = oracles.tsuji_mindlin_sliding_threshold(
            math.sqrt(6.0) * oracles.thornton_appendix_b_g(found.e_n), KAPPA)
        assert -HIDDEN_STICK <= found.simulated - expected <= found.resolution + 1e-5, (found, expected)
        if found.e_n <= 0.5:
            assert expected == pytest.approx(7.0 - 5.0 * achieved / (3.0 * KAPPA * (1.0 + achieved)), abs=1e-9)
        assert math.isnan(found.derived)


def test_dashpot_too_weak_for_the_cone_claims_no_release_condition():
    """A tangential dashpot far weaker than the normal one cannot hold the force on the cone from first touch
    (2 c_n/(c_t (1 + e)) = 21 at e 0.25, g_t 0.05): the release condition is not claimed, and the simulated
    threshold lies above that first-touch bound."""
    law = compose("linear-spring-dashpot", {"tangential-damping": "0.05"})
    found = sliding_thresholds(law, Scene(e_n=(0.25,)))[0]
    assert math.isnan(found.derived) and found.simulated > 7.0 - 2 * 0.25 / (KAPPA * 1.25) + 10.0


@pytest.mark.parametrize("form, lam", [("mindlin:rescale", 2.0 / 3.0), ("mindlin:incremental", 1.0)])
def test_elastic_limit_is_maws(form, lam):
    """e = 1 (elastic Hertz-Mindlin): 7 - 2 lam/(2 kappa); with the incremental spring Maw, Barber & Fawcett's
    elastic 7 - 1/kappa (their 4 chi - 1 in the paper's normalisation)."""
    law = compose("hertz-mindlin", {"damping": "none", "tangential-damping": "none", "tangential": form})
    found = sliding_thresholds(law, Scene(e_n=(1.0,)))[0]
    assert abs(found.simulated - (7.0 - lam / KAPPA)) <= found.resolution + 1e-5
    if form == "mindlin:incremental":
        chi = 3.5 * 0.7 / 1.7
        assert 7.0 - 1.0 / KAPPA == pytest.approx((4 * chi - 1) * 2 / (KAPPA * 2))


def test_threshold_separates_full_and_partial_coulomb_impulse():
    """Independent of the stick events: just above the threshold the tangential impulse is mu times the normal one
    (to round-off), just below it falls short."""
    law = compose("thornton")
    found = sliding_thresholds(law, Scene(e_n=(0.5,)))[0]
    above, below = found.simulated * (1 + 1e-3), found.simulated * (1 - 2e-2)
    frame = simulate(law, Scene(e_n=(0.5,), angles_deg=None, psi1_star=(below, above)), converged=True)[0]
    deficit = impulse_deficit(frame)
    assert abs(deficit[1]) < 1e-9 and deficit[0] > 1e-6, deficit


def test_viscous_law_without_tangential_dashpot_never_slides_throughout():
    """The documented dashpot lag: without the tangential dashpot the normal dashpot loads the cone before the
    spring does, so no Psi1* up to 40 slides throughout, and no condition is claimed."""
    law = compose("hertz-mindlin", {"tangential-damping": "none"})
    found = sliding_thresholds(law, Scene(e_n=(0.5,)))[0]
    assert math.isnan(found.simulated) and math.isnan(found.derived) and found.formula == ""


def test_no_condition_is_claimed_for_engine_dialects():
    from harness.engines import liggghts
    assert math.isnan(derived_threshold(liggghts.dialect("hertz-mindlin"), Scene().contact, 0.5)[0])


def test_impulse_deficit_is_zero_for_a_rigid_sliding_row():
    import pandas as pd
    row = pd.DataFrame({"v_t0": [3.0], "v_t1": [3.0 - 0.1 * 1.5 * 2.0], "v_n0": [2.0], "v_n1": [1.0], "mu": [0.1]})
    assert impulse_deficit(row)[0] == pytest.approx(0.0, abs=1e-15)
    assert np.isfinite(impulse_deficit(row)).all()
