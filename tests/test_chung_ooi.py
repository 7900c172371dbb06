"""Chung & Ooi (2011)'s benchmark: its closed forms against independent statements of them, the reference passing
every test, checks that fail when a result is off, the command's files and exit codes, and LIGGGHTS' results."""
import math

import pandas as pd
import pytest

from conftest import needs
from harness.commands import main
from harness.verification import chung_ooi as suite


def case(test, label=None):
    return next(c for c in suite.cases() if c.test == test and (label is None or c.label == label))


def test_hertz_closed_forms_match_the_textbook_constants():
    """Johnson (1985) eq. 11.24: t_c = 2.868 (m*^2/(R* E*^2 V))^1/5; for test 2's aluminium alloy on a rigid plane
    E* = E/(1 - nu^2), R* = R, m* = m; for test 1's two glass spheres R* = R/2, m* = m/2, E* = E/(2(1 - nu^2))."""
    c = case(2, "aluminium alloy")
    E_star = 7.0e10 / (1 - 0.30 ** 2)
    m = 4 / 3 * math.pi * 0.1 ** 3 * 2699.0
    expected = suite.hertz(c)
    assert expected["t_contact"] == pytest.approx(2.868 * (m ** 2 / (0.1 * E_star ** 2 * 0.2)) ** 0.2, rel=2e-4)
    alpha = (15 * m * 0.2 ** 2 / (16 * E_star * 0.1 ** 0.5)) ** 0.4
    assert expected["overlap_max"] == pytest.approx(alpha, rel=1e-12)
    assert expected["f_n_max"] == pytest.approx(4 / 3 * E_star * 0.1 ** 0.5 * alpha ** 1.5, rel=1e-12)
    two = suite.hertz(case(1, "glass"))
    m = 4 / 3 * math.pi * 0.01 ** 3 * 2800.0
    assert two["t_contact"] == pytest.approx(2.868 * ((m / 2) ** 2 / (0.005 * (4.8e10 / (2 * 0.96)) ** 2 * 20.0))
                                             ** 0.2, rel=2e-4)


def test_the_reference_passes_every_test_with_checks_in_each():
    table = suite.run_suite(("reference",))
    checked = table[table.passed.notna()]
    assert set(checked.test) == set(range(1, 9))
    assert checked.passed.all(), checked[~checked.passed.astype(bool)]
    assert suite.verdict(table) == (True, len(checked), len(checked))


def test_a_result_off_by_one_percent_fails_its_checks():
    """The checks can fail: test 4's gross-sliding rows with v_t1 1% too large, test 2's force 1% too small."""
    c = case(4, "alumina")
    table, failure = suite.results(c, "reference")
    assert failure is None
    off = table.assign(v_t1=table.v_t1 * 1.01)
    rows = pd.DataFrame(suite.checks(c, "reference", off))
    sliding = rows[(rows.note == "gross sliding") & (rows.quantity == "v_t1 [m/s]")]
    assert len(sliding) >= 5 and not sliding.passed.any()
    c = case(2, "aluminium alloy")
    table, _ = suite.results(c, "reference")
    rows = pd.DataFrame(suite.checks(c, "reference", table.assign(f_n_max=table.f_n_max * 0.99)))
    assert not rows[rows.quantity == "f_n_max [N]"].passed.iloc[0]
    assert rows[rows.quantity != "f_n_max [N]"].passed.all()


def test_a_missing_value_fails_rather_than_passing_unchecked():
    row = suite.row(case(2), "liggghts", "f_n_max [N]", math.nan, 1.0, 1.0, 1e-3)
    assert row["passed"] is False


def test_benchmark_command_writes_the_table_and_the_page(tmp_path, capsys):
    out = tmp_path / "co"
    assert main(["benchmark", "chung-ooi", "--engines", "reference", "-o", str(out)]) == 0
    table = pd.read_csv(out / "chung-ooi.csv")
    assert list(table.columns) == list(suite.COLUMNS)
    assert table.passed.dropna().astype(bool).all()
    page = (out / "chung-ooi.html").read_text()
    assert "Every applicable check passes" in page
    assert all(f'id="test{n}"' in page for n in range(1, 9))
    assert "chung-ooi:" in capsys.readouterr().out


def test_benchmark_exits_3_when_a_named_engine_is_missing(tmp_path, capsys):
    code = main(["benchmark", "chung-ooi", "--engines", "reference,liggghts", "-o", str(tmp_path / "co")])
    out = capsys.readouterr().out
    assert code == 3 and "could not run: liggghts" in out
    table = pd.read_csv(tmp_path / "co" / "chung-ooi.csv")
    assert (table[table.engine == "liggghts"].quantity == "not run").all()


def test_benchmark_refuses_an_unknown_engine(tmp_path, capsys):
    assert main(["benchmark", "chung-ooi", "--engines", "fluent", "-o", str(tmp_path / "co")]) == 2
    assert not (tmp_path / "co").exists()


@needs("liggghts")
def test_liggghts_on_the_rigid_plane_tests():
    """LIGGGHTS' Hertz against a rigid plane is Hertz's (test 2) and returns e_in (test 3), but under spin with e 0.5
    (test 6) its tangential impulse exceeds mu J_n: its Coulomb cap bounds the spring alone, not spring + dashpot
    (docs/findings.md)."""
    rows = []
    for c in [case(2, "aluminium alloy"), case(3, "e_in 0.5"), case(6, "omega0 20 rad/s")]:
        table, failure = suite.results(c, "liggghts")
        assert failure is None
        rows += suite.checks(c, "liggghts", table)
    rows = pd.DataFrame(rows)
    assert rows[rows.test.isin([2, 3])].passed.all()
    sliding = rows[(rows.test == 6) & (rows.quantity == "v_t1 [m/s]")].iloc[0]
    assert abs(sliding.value) > 1.1 * abs(sliding.expected)


@needs("yade")
def test_yade_on_two_spheres_and_a_rigid_plane():
    """YADE's Mindlin law between two identical spheres (test 1, observed) and against a rigid wall (test 2) is
    Hertz's; under spin (test 8) its tangential impulse exceeds mu J_n: below the Coulomb cap it adds its shear
    dashpot to the spring, uncapped (docs/findings.md)."""
    rows = []
    for c in [case(1, "glass"), case(2, "aluminium alloy"), case(8, "omega 20 rad/s")]:
        table, failure = suite.results(c, "yade")
        assert failure is None
        rows += suite.checks(c, "yade", table)
    rows = pd.DataFrame(rows)
    assert rows[rows.test.isin([1, 2])].passed.all() and len(rows[rows.test.isin([1, 2])]) == 6
    target = rows[(rows.test == 8) & (rows.quantity == "v2_t [m/s]")].iloc[0]
    assert abs(target.value) > 1.1 * abs(target.expected)


def test_kratos_curve_error_is_the_l1_error_over_the_checked_points():
    """sum |v - e| / sum |e| by hand on a small table: (|1.1 - 1| + |1.8 - 2|)/3 = 0.1 fails 5%, 0.02/1 passes;
    unchecked rows (no expectation) do not count."""
    rows = pd.DataFrame([
        {"test": 4, "engine": "x", "quantity": "q", "value": 1.1, "expected": 1.0, "passed": False},
        {"test": 4, "engine": "x", "quantity": "q", "value": 1.8, "expected": 2.0, "passed": False},
        {"test": 4, "engine": "x", "quantity": "q", "value": 9.0, "expected": math.nan, "passed": None},
        {"test": 4, "engine": "x", "quantity": "r", "value": 1.02, "expected": 1.0, "passed": True}])
    curves = suite.curve_errors(rows).set_index("quantity")
    assert curves.loc["q", "L1 error"] == pytest.approx(0.1) and curves.loc["q", "points"] == 2
    assert not curves.loc["q", "within Kratos' 5%"] and curves.loc["r", "within Kratos' 5%"]


def test_benchmark_json_is_one_document_with_the_verdict(tmp_path, capsys):
    import json
    assert main(["benchmark", "chung-ooi", "--engines", "reference", "-o", str(tmp_path / "co"), "--json"]) == 0
    summary = json.loads(capsys.readouterr().out)
    assert summary["ok"] is True and summary["exit_code"] == 0 and summary["passed"] == summary["checked"] > 0
    assert [row["engine"] for row in summary["engines"]] == ["reference"]
