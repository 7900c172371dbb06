"""The paper's published curves (Kratos' digitised TCC13 figures, shipped as package data): their provenance, their
normalisation against harness', the paper laws' distance from them (issue 27's goal), and their overlay on the
figures, whose axes hide no data."""
import math
import re

import numpy as np
import pandas as pd
import pytest

from harness.analyses.published import curve_distance, meets_goal, published_distances
from harness.data.digitised import path, provenance, published_curves_apply, published_points
from harness.laws import compose
from harness.studies.paper import PSI1_GRID, oblique_curves, paper_scene
from harness.scenes.scene import Scene
from harness.solver.simulate import simulate

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


@pytest.fixture(scope="module")
def paper_curves():
    """The two paper laws over the paper's Psi1* axis at `harness paper`'s resolution."""
    return oblique_curves(PAPER_LAWS, paper_scene(), 2000)


def test_paper_laws_meet_the_goal(paper_curves):
    """Issue 27's goal: against every shipped point (none outside the Psi1* axis), each law, e and quantity within
    0.2 worst and 0.1 RMS of the published curves, e_t counted x10."""
    distances = published_distances(paper_curves)
    assert len(distances) == 24
    expected = published_points().groupby(["model", "e_n", "quantity"]).size()
    for row in distances.itertuples():
        assert row.points == expected[(row.model, row.e_n_target, row.quantity)]
    assert PSI1_GRID[0] < published_points().psi1_star.min()
    assert meets_goal(distances).all(), distances[~meets_goal(distances)].to_string()


def test_the_goal_fails_for_the_former_reading():
    """The test above can fail: the former reading (Coulomb's test on spring plus dashpot) misses the goal, worst
    0.31 at the linear law's e 0.25, Psi1* 2.8 (issue 27)."""
    frame = simulate(compose("linear-spring-dashpot", {"tangential-damping": "normal-ratio:total"}),
                     paper_scene((0.25,)), steps_per_contact=2000)[0]
    distances = published_distances(frame)
    worst = distances.loc[distances.worst.idxmax()]
    assert not meets_goal(distances).all()
    assert worst.worst == pytest.approx(0.31, abs=0.01) and worst.quantity == "psi2_star"
    assert worst.psi1_star_at_worst == pytest.approx(2.8, abs=0.01)


def test_published_curves_apply_to_the_paper_scene_at_any_speed():
    """The predicate: the paper's sphere, mu and wall, no spin or gravity, a covered law; the speed, normal or
    resultant, is free, because both laws' normalised rebounds are self-similar in it: simulated here at 5 m/s
    resultant, 5 and 1 m/s normal, at the same impact angles (the same Psi1*), they agree."""
    assert published_curves_apply(Scene(), "hertz-mindlin") and published_curves_apply(Scene(), "linear-spring-dashpot")
    assert published_curves_apply(Scene(speed=2.0, speed_is="normal"), "hertz-mindlin")
    assert not published_curves_apply(Scene(), "thornton")
    for change in ({"mu": 0.3}, {"radius": 5e-3}, {"wall": "rigid"}, {"omega0": 10.0}, {"gravity": 9.81}):
        assert not published_curves_apply(Scene(**change), "hertz-mindlin"), change
    angles = (10.0, 35.0, 60.0, 80.0)
    for name in PAPER_LAWS:
        law = compose(name)
        frames = [simulate(law, Scene(e_n=(0.5,), angles_deg=angles, speed=v, speed_is=how), steps_per_contact=4000)[0]
                  for v, how in ((5.0, "resultant"), (5.0, "normal"), (1.0, "normal"))]
        for frame in frames[1:]:
            for column in QUANTITIES + ("psi1_star",):
                assert np.allclose(frame[column], frames[0][column], atol=1e-4), (name, column)


def svg_ids(svg, name):
    return len(re.findall(f'id="{name}', str(svg)))


def test_paper_figure_overlays_the_published_points(paper_curves):
    """Each covered law's figure draws the published points in all three panels at each e_n; other laws' none."""
    from harness.views.paper_html import law_figure
    sliding = pd.DataFrame({"model": [], "e_n_target": [], "simulated": []})
    svg = law_figure(paper_curves, sliding, "hertz-mindlin")
    assert svg_ids(svg, "published-points") == 3 * 4 and "published (TCC13, digitised)" in svg
    thornton = simulate(compose("thornton"), paper_scene((0.5,)), steps_per_contact=200)[0]
    assert svg_ids(law_figure(thornton, sliding, "thornton"), "published-points") == 0


def compare_rows(omega_yade):
    """A compare-like frame at e 0.25: the paper law, and a YADE run falling to -9 whose last Omega* is
    `omega_yade`."""
    psi = np.linspace(0.5, 13.5, 14)
    rows = []
    for engine, dialect, low, last in (("reference", "paper", -5.0, -5.0), ("yade", "yade", -9.0, omega_yade)):
        omega = np.append(np.linspace(-0.3, low, len(psi) - 1), last)
        rows.append(pd.DataFrame({"engine": engine, "dialect": dialect, "e_n_target": 0.25, "psi1_star": psi,
                                  "omega_star": omega, "theta_deg": np.degrees(np.arctan(psi * 0.0625))}))
    return pd.concat(rows, ignore_index=True)


def test_compare_figure_grows_its_axis_to_the_data():
    """Omega* at -10.2 (YADE on the paper's scene) was clipped at the paper's -6: now the axis reaches it; a point
    far beyond (-1e3) gets a marker on the edge and a count instead of stretching the axis; rows past Psi1* = 14 are
    counted."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from harness.views.paper_axes import set_paper_axes
    for last, reaches in ((-10.2, True), (-1e3, False)):
        fig, ax = plt.subplots()
        frame = compare_rows(last)
        for _, series in frame.groupby("engine"):
            ax.plot(series.psi1_star, series.omega_star)
        set_paper_axes(ax, "omega_star", "Omega*")
        low = ax.get_ylim()[0]
        assert (low <= -10.2) == reaches and low < -6.0
        texts = " ".join(t.get_text() for t in ax.texts)
        assert ("1 beyond the axis" in texts) == (not reaches)
        plt.close(fig)
    from harness.views.html import series_figure
    frame = compare_rows(-1e3)
    frame = pd.concat([frame, frame.iloc[:1].assign(psi1_star=40.0, theta_deg=68.2)], ignore_index=True)
    svg = series_figure(frame, "Omega*", "psi1_star", ("omega_star",), published="hertz-mindlin")
    assert svg_ids(svg, "beyond-axis") == 1 and "1 beyond the axis" in svg
    assert "1 impact beyond Psi1* = 14 not drawn" in svg
    assert svg_ids(svg, "published-points") == 1


def test_compare_report_overlays_only_where_the_paper_applies():
    """compare's Psi1* figures get the published points on the paper's scene for a covered law (one per panel), and
    its report the distance table, and neither where mu differs from the paper's."""
    import harness
    from harness.views.html import compare_context
    for mu, expected in ((0.1, 3), (0.3, 0)):
        comparison = harness.compare("hertz-mindlin", engines=[], en=[0.5], angles=[20, 40, 60], mu=mu,
                                     steps_per_contact=200)
        context = compare_context(comparison)
        assert sum(svg_ids(svg, "published-points") for _, svg, _ in context["figures"]) == expected, mu
        distances = context["published"]
        assert (distances is not None) == bool(expected)
        if distances:
            columns, rows = distances
            assert [row[columns.index("quantity")] for row in rows] == ["psi2_star", "omega_star", "e_t"]
