"""The paper's published curves (Kratos' digitised TCC13 figures, shipped as package data): their provenance, their
normalisation against harness', the paper laws' distance from them (issue 27's goal), and their overlay on the
figures, whose axes hide no data."""
import math

import numpy as np
import pandas as pd
import pytest

from harness.analyses.published import curve_distance
from harness.digitised import path, provenance, published_points

PAPER_LAWS = ("linear-spring-dashpot", "hertz-mindlin")
QUANTITIES = ("psi2_star", "omega_star", "e_t")
PAPER_EN = (0.25, 0.5, 0.75, 0.9)


def test_shipped_file_keeps_its_provenance():
    """The file reached through the installed package (importlib.resources) starts with its provenance: who digitised
    it from which file, the scene and the normalisation; and it holds every law, e and quantity."""
    assert path().name == "tcc13-digitised.csv" and path().is_file()
    header = "\n".join(provenance())
    for words in ("Thornton, Cummins & Cleary 2013", "digitised by the Kratos Multiphysics project",
                  "paper_data/bench_10_", "benchmarks 10 linear, 11 Hertz", "Scene: R 0.025 m, rho 2650",
                  "psi1s = 2 tan(theta)/(mu(1+e))", "omegas = 2 R w'/(mu(1+e)V_n)", "Digitising scatter"):
        assert words in header, words
    points = published_points()
    assert points.notna().all().all()
    counts = points.groupby(["model", "quantity", "e_n"]).size()
    assert len(counts) == 2 * 3 * 4 and counts.min() >= 8
    assert set(points.model) == set(PAPER_LAWS) and set(points.quantity) == set(QUANTITIES)


def test_published_points_are_in_harness_normalisation():
    """Rigid-body identities in harness' convention (docs/laws.md#normalisation), written out here: beyond the
    sliding threshold Psi2* = Psi1* - 7 and Omega* = -5 (within the file's digitising scatter, 0.05), and without
    spin e_t = 5/7 + 2 Psi2*/(7 Psi1*) links its e_t and Psi2* points (Psi1* > 1, where the ratio is not
    amplified by digitising)."""
    points = published_points()
    for (model, e_n), group in points.groupby(["model", "e_n"]):
        sliding = group[group.psi1_star >= 7.3]
        psi2, omega = sliding[sliding.quantity == "psi2_star"], sliding[sliding.quantity == "omega_star"]
        assert len(psi2) and len(omega)
        assert np.abs(psi2.value - (psi2.psi1_star - 7.0)).max() < 0.05, (model, e_n)
        assert np.abs(omega.value + 5.0).max() < 0.05, (model, e_n)
        slip = group[group.quantity == "psi2_star"].sort_values("psi1_star")
        e_t = group[(group.quantity == "e_t") & (group.psi1_star > 1.0)]
        implied = 5.0 / 7.0 + 2.0 * np.interp(e_t.psi1_star, slip.psi1_star, slip.value) / (7.0 * e_t.psi1_star)
        assert np.abs(implied - e_t.value).max() < 0.01, (model, e_n)


def test_curve_distance_by_hand():
    """Linear interpolation at each point's Psi1*, the scale applied, points outside the curve's range left out."""
    points = pd.DataFrame({"psi1_star": [0.5, 1.5, 9.0], "value": [1.0, 0.0, 5.0]})
    used, reference, rms, worst, at = curve_distance([2.0, 0.0, 1.0], [4.0, 0.0, 2.0], points, scale=10.0)
    assert list(used.psi1_star) == [0.5, 1.5] and list(reference) == [1.0, 3.0]
    assert worst == pytest.approx(30.0) and at == 1 and rms == pytest.approx(math.sqrt((0 + 900) / 2))
