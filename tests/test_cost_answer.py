"""What a tolerance costs per curve (harness.analyses.cost_answer), on cost tables whose errors follow a known law:
the answers are where that law meets the tolerance, worked out by hand."""
import math

import pandas as pd
import pytest

from harness.analyses.cost_answer import answers, notes, steps_text

E_N = 0.5


def rows(engine, dialect, errors, truth=0.0, levels=False, gap=0.0):
    """Cost rows of one curve at one e_n: {steps per contact: worst error}; the velocity errors `gap` above it (an
    engine that does not compute its formulas exactly); `levels`: as levels of the converged reference."""
    out = []
    for n, error in errors.items():
        out.append({"engine": engine, "dialect": dialect, "e_n_target": E_N,
                    "rung": f"truth {n}" if levels else str(n), "steps_per_contact": float(n), "dt": 1e-4 / n,
                    "impacts": 2, "steps": 2.0 * n, "status": "ok", "err_max": error + gap, "err_truth": truth,
                    "err_v_n1": error + gap, "err_v_t1": error + gap, "err_omega1": error + gap})
    return out


def answered(*curves):
    return answers(pd.DataFrame([row for curve in curves for row in curve]))


ORDER_ONE = {n: 0.5 / n for n in (20, 50, 100, 200)}          # error 0.5/n: 1% at n = 50, 0.1% at n = 500


def test_an_order_one_curve_meets_1_percent_where_its_law_says_and_0_1_percent_by_extrapolation():
    found = answered(rows("reference", "paper", ORDER_ONE))[("reference", "paper")]
    assert found[1e-2].steps == 50 and found[1e-2].how == ""          # 0.5/50 = 1%; 0.5/20 = 2.5% (2.5x coarser)
    assert found[1e-3].how == "extrapolated" and found[1e-3].steps == pytest.approx(500, abs=1)
    assert found[1e-3].steps_per_impact == pytest.approx(found[1e-3].steps, rel=1e-2)
    assert "order 1.00" in found[1e-3].note


def test_the_truths_uncertainty_is_added_to_every_error():
    """0.5/n + 2e-4 <= 1e-3 at n = 625; 0.5/n + 2e-4 <= 1e-2 at n = 51.02 -> the rung 100 (50 misses)."""
    found = answered(rows("reference", "paper", ORDER_ONE, truth=2e-4))[("reference", "paper")]
    assert found[1e-2].steps == 100
    assert found[1e-3].steps == pytest.approx(625, abs=1)
    assert math.isnan(found[1e-4].steps) and "uncertain by 2.0e-04" in found[1e-4].note


def test_a_slow_apparent_order_is_not_extrapolated_and_says_why():
    """0.5 n^-0.2 (LAMMPS' hertz-mindlin on the paper's scene falls this way before its error drops at once): no
    number, and the local orders are named."""
    slow = {n: 0.5 * n ** -0.2 for n in (20, 50, 100, 200, 500)}
    found = answered(rows("reference", "paper", slow))[("reference", "paper")]
    assert math.isnan(found[1e-2].steps) and found[1e-2].how == "none"
    assert "not within 500 steps/contact" in found[1e-2].note and "local orders 0.20 and 0.20" in found[1e-2].note


def test_a_wide_gap_is_filled_by_the_order_where_it_is_resolved():
    """Missed at 200, met at the reference's level 65536: the order-1 law puts 0.1% at 500, inside the gap."""
    curve = rows("reference", "paper", ORDER_ONE) + rows("reference", "paper", {65536: 1e-5, 131072: 0.0},
                                                         levels=True)
    found = answered(curve)[("reference", "paper")]
    assert found[1e-3].how == "extrapolated" and found[1e-3].steps == pytest.approx(500, abs=1)
    assert "between 200 (missed) and 65536 (met)" in found[1e-3].note


def test_the_finest_level_of_the_truth_is_no_answer():
    """Met only at the truth's finest level, whose error is zero by definition: no number, and why."""
    curve = rows("reference", "paper", ORDER_ONE, truth=5e-4) + rows("reference", "paper", {65536: 8e-4, 131072: 0.0},
                                                                     levels=True, truth=5e-4)
    found = answered(curve)[("reference", "paper")][1e-3]
    assert math.isnan(found.steps) and "met only by its converged reference itself, 131072" in found.note


def test_an_engine_beyond_its_ladder_is_priced_on_its_formulas_only_where_it_computes_them():
    """LAMMPS' way: 5% at every ladder rung, then its formulas' levels 2.6% at 131072 and 0.4% at 262144 (truth
    at 524288): 1% at 262144 from the formulas, when the engine's errors equal theirs; not when they differ."""
    ladder = {20: 0.05, 100: 0.05, 500: 0.05}
    formulas = rows("reference", "lammps", ladder) + rows("reference", "lammps",
                                                          {131072: 0.026, 262144: 0.004, 524288: 0.0}, levels=True)
    same = answered(formulas, rows("lammps", "lammps", ladder))[("lammps", "lammps")]
    assert same[1e-2].steps == 262144 and same[1e-2].how == "formulas"
    assert steps_text(same[1e-2].steps, same[1e-2].how) == "262144f"
    assert "measured on its formulas in the reference beyond its ladder" in same[1e-2].note
    differs = answered(formulas, rows("lammps", "lammps", ladder, gap=1e-3))[("lammps", "lammps")]
    assert math.isnan(differs[1e-2].steps)
    assert "differ from theirs by 1.0e-03 of V" in differs[1e-2].note


def test_notes_name_the_curve_and_every_tolerance_they_answer():
    ladder = {20: 0.05, 100: 0.05, 500: 0.05}
    formulas = rows("reference", "lammps", ladder) + rows("reference", "lammps",
                                                          {131072: 0.02, 262144: 1e-4, 524288: 0.0}, levels=True)
    found = answered(formulas, rows("lammps", "lammps", ladder))
    said = notes(found, (1e-2, 1e-3), verdict_only=True)
    assert said == ["lammps 1% and 0.1%: 262144 steps/contact measured on its formulas in the reference beyond its "
                    "ladder (it computes them: its velocity errors equal theirs to 0e+00 of V on every rung it ran)"]


def test_a_rung_refused_above_the_stability_limit_is_a_coarse_rung_that_misses():
    """Refused rows carry no steps per contact: the rung's label places it (5 steps, below every other rung)."""
    refused = {"engine": "reference", "dialect": "paper", "e_n_target": E_N, "rung": "5", "status": "refused",
               "message": "above the stability limit"}
    found = answered(rows("reference", "paper", ORDER_ONE) + [refused])[("reference", "paper")]
    assert found[1e-2].steps == 50 and found[1e-2].how == ""
