"""Regression check against the committed baseline (baselines/baseline.csv, shipped with the package)."""
from pathlib import Path

import pandas as pd
import pytest

from harness.studies import baseline
from harness.laws import compose
from harness.data.results import read_csv, write_csv
from harness.solver.simulate import simulate

REFERENCE = Path(__file__).resolve().parent.parent / "baselines"


@pytest.fixture(scope="module")
def now():
    frame, _ = baseline.compute()
    return frame


def test_committed_baseline_holds(now):
    failures, skipped, _ = baseline.check(str(REFERENCE), now=now)
    assert failures.empty, failures.to_string()


def test_perturbed_baseline_value_is_named(now, tmp_path):
    frame = read_csv(REFERENCE / baseline.BASELINE_FILE)
    row = frame.index[(frame.model == "thornton") & (frame.engine == "reference") & (frame.theta_deg == 30.0)][0]
    frame.loc[row, "e_t"] *= 1.0 + 1e-7                   # beyond the reference's 1e-9 tolerance
    write_csv(frame, tmp_path / baseline.BASELINE_FILE)
    failures, _, _ = baseline.check(str(tmp_path), now=now)
    assert len(failures) == 1
    assert failures.iloc[0].metric == "e_t" and failures.iloc[0].model == "thornton"


def test_engine_rows_have_a_looser_tolerance(now, tmp_path):
    frame = read_csv(REFERENCE / baseline.BASELINE_FILE)
    engines = frame.engine != "reference"
    if not engines.any():
        pytest.skip("no engine rows in the baseline")
    frame.loc[engines, "v_t1"] *= 1.0 + 1e-8              # within the engines' 1e-6
    write_csv(frame, tmp_path / baseline.BASELINE_FILE)
    failures, _, _ = baseline.check(str(tmp_path), now=now)
    assert failures.empty


def test_deliberately_broken_damping_is_caught(now, monkeypatch):
    """Scale the Appendix-B damping by 1.01: the hertz-mindlin paper rows move and the check names them."""
    from harness.submodels import calibration
    original = calibration.thornton_appendix_b_g
    monkeypatch.setattr(calibration, "thornton_appendix_b_g", lambda e: 1.01 * original(e))
    broken = simulate(compose("hertz-mindlin"), baseline.matrix_scene(),
                      steps_per_contact=baseline.STEPS_PER_CONTACT)[0]
    keep = ~((now.model == "hertz-mindlin") & (now.engine == "reference") & (now.dialect == "paper"))
    failures, _, _ = baseline.check(str(REFERENCE), now=pd.concat([now[keep], broken], ignore_index=True))
    assert not failures.empty
    assert set(failures.model) == {"hertz-mindlin"} and "e_n" in set(failures.metric)


def test_check_without_baseline_is_a_user_error(tmp_path):
    from harness.infra.errors import UserError
    with pytest.raises(UserError, match="no baseline"):
        baseline.check(str(tmp_path))


def test_the_baseline_records_each_input_verbatim_with_its_composition():
    """The LAMMPS input's rows (hooke 1e7 with a velocity dashpot of 45) rebound at the damped oscillator's
    e = exp(-pi zeta / sqrt(1 - zeta^2)), zeta = eta / (2 sqrt(k m)), m of the matrix's sphere, in the reference and
    the engine alike."""
    import math
    frame = read_csv(REFERENCE / baseline.BASELINE_FILE)
    law, code, text = baseline.INPUT_CASES[0]
    rows = frame[frame.engine_input == text]
    assert set(rows.model) == {law} and set(rows.dialect.str.partition("@")[0]) == {code}
    assert {"reference", code} <= set(rows.engine.str.partition("@")[0])
    (composition,) = set(rows.composition)
    assert "normal linear(k_n=1e+07)" in composition
    radius, rho = rows.radius.iloc[0], rows.rho.iloc[0]
    zeta = 45.0 / (2.0 * math.sqrt(1e7 * 4.0 / 3.0 * math.pi * radius ** 3 * rho))
    assert abs(rows.e_n - math.exp(-math.pi * zeta / math.sqrt(1.0 - zeta ** 2))).max() < 1e-3
    assert set(frame.engine_input.fillna("")) == {""} | {text for _, _, text in baseline.INPUT_CASES}


def test_a_perturbed_input_row_is_named_with_its_input(now, tmp_path):
    frame = read_csv(REFERENCE / baseline.BASELINE_FILE)
    _, _, text = baseline.INPUT_CASES[1]
    row = frame.index[(frame.engine_input == text) & (frame.engine == "reference") & (frame.theta_deg == 30.0)][0]
    frame.loc[row, "v_t1"] *= 1.0 + 1e-7
    write_csv(frame, tmp_path / baseline.BASELINE_FILE)
    failures, _, _ = baseline.check(str(tmp_path), now=now)
    assert len(failures) == 1 and failures.iloc[0].engine_input == text and failures.iloc[0].metric == "v_t1"
