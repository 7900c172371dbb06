"""What the report's figures show: a panel per e_n even when every impact lies beyond the paper's Psi1* window
(steep angles alone), with the count of impacts not drawn; and legends that cover no data point and fit the figure."""
import math
import re

import matplotlib
import numpy as np
import pandas as pd
import pytest

import harness
from harness.commands import main

matplotlib.use("Agg")
LAWS = ("hertz-mindlin", "linear-spring-dashpot", "thornton", "walton-braun", "hertz-kuwabara-kono", "stronge",
        "partially-latching-spring")


def psi1_star(theta_deg, e_n, mu=0.1):
    """The paper's Psi1* of an impact without spin: 2 V_t / (mu (1 + e) V_n) = 2 tan(theta) / (mu (1 + e))."""
    return 2.0 * math.tan(math.radians(theta_deg)) / (mu * (1.0 + e_n))


@pytest.mark.parametrize("angles", ["60", "65,71,77"])
def test_steep_angles_alone_draw_a_panel_per_e_n_that_counts_what_lies_beyond(tmp_path, capfd, angles):
    """At 60 deg and beyond every impact of the paper's scene has Psi1* > 14 (23 at 60 deg and e_n 0.5): the report
    still draws each e_n's panel, saying how many impacts lie beyond the window, and compare exits 0."""
    thetas = [float(a) for a in angles.split(",")]
    e_ns = (0.5, 0.9)
    assert min(psi1_star(t, e) for t in thetas for e in e_ns) > 14.0
    out = tmp_path / "out"
    code = main(["compare", "--model", "hertz-mindlin", "--engines", "reference", "--en", "0.5,0.9", "--angles",
                 angles, "--steps-per-contact", "200", "-o", str(out)])
    assert code == 0, capfd.readouterr()
    words = f"{len(thetas)} impact{'s' if len(thetas) > 1 else ''} beyond Psi1* = 14 not drawn"
    for name in ("psi2", "omega", "e_t"):
        svg = (out / "figures" / f"hertz-mindlin-{name}-vs-psi1.svg").read_text()
        assert svg.count(words) == len(e_ns), name
        assert all(f"e_n = {e:g}" in svg for e in e_ns)


@pytest.fixture(scope="module")
def seven_curves():
    """Every law on the paper's scene at e_n 0.5 and 0.9 over 0..85 deg, each labelled as a dialect of the
    reference: the number of curves a compare with every engine draws."""
    frames = [harness.run(law, en=[0.5, 0.9], angles=list(range(0, 90, 5)), steps_per_contact=200).assign(dialect=law)
              for law in LAWS]
    return pd.concat(frames, ignore_index=True)


def legend_problems(fig):
    """Data points drawn inside a panel that lie under a legend, and legends that stick out of the figure."""
    fig.canvas.draw()
    legends = [*fig.legends, *(ax.get_legend() for ax in fig.axes if ax.get_legend() is not None)]
    assert legends, "the figure has no legend"
    boxes = [legend.get_window_extent() for legend in legends]
    problems = [f"legend {box} beyond the figure's width {fig.bbox.width}" for box in boxes
                if box.x0 < 0 or box.x1 > fig.bbox.width or box.y0 < 0]
    for ax in fig.axes:
        for line in ax.get_lines():
            xy = line.get_transform().transform(np.asarray(line.get_xydata(), dtype=float))
            xy = xy[np.isfinite(xy).all(axis=1)]
            xy = xy[[ax.bbox.contains(x, y) for x, y in xy]]
            for box in boxes:
                under = [(x, y) for x, y in xy if box.contains(x, y)]
                if under:
                    problems.append(f"{len(under)} points of {line.get_label()!r} under the legend")
    return problems


@pytest.mark.parametrize("column", ["psi2_star", "omega_star", "e_t", "theta_r_com_deg"])
def test_the_report_figures_legend_covers_no_data(seven_curves, column):
    import matplotlib.pyplot as plt
    fig = harness.plot(seven_curves, column)
    try:
        assert legend_problems(fig) == []
    finally:
        plt.close(fig)


def test_the_paper_figures_legend_covers_no_data(seven_curves, monkeypatch):
    """The figure set's figure of a law (one curve per e_n, elastic Hertz-Mindlin, the rigid body, the published
    points) and its contact-duration figure."""
    import harness.views.paper_html as paper_html
    problems = []

    def checked(fig):
        problems.extend(legend_problems(fig))
        return "<svg/>"
    monkeypatch.setattr(paper_html, "figure_svg", checked)
    rows = seven_curves[seven_curves.dialect == "hertz-mindlin"].assign(model="hertz-mindlin")
    elastic = rows[rows.e_n_target == 0.9].assign(model=paper_html.ELASTIC, e_n_target=1.0)
    oblique = pd.concat([rows, elastic])
    sliding = pd.DataFrame({"model": ["hertz-mindlin"] * 2, "e_n_target": [0.5, 0.9], "simulated": [6.3, 6.1]})
    paper_html.law_figure(oblique[oblique.psi1_star > 0], sliding, "hertz-mindlin")
    normal = pd.DataFrame({"model": ["hertz-mindlin", "thornton"] * 3, "e_n_target": [0.25, 0.25, 0.5, 0.5, 0.9, 0.9],
                           "t_c/t_Hertz": [1.1, 1.7, 1.05, 1.2, 1.0, 1.01],
                           "F_max/F_Hertz": [0.7, 0.3, 0.8, 0.5, 0.95, 0.9]})
    paper_html.normal_figure(normal)
    assert problems == []


def test_the_legend_check_sees_a_legend_over_data():
    """A positive control: a legend placed over the middle of a full panel is found."""
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots()
    x = np.linspace(0, 1, 200)
    for k in range(5):
        ax.plot(x, x * k, label=f"curve {k}")
    ax.legend(loc="center")
    assert any(re.search(r"points of 'curve \d' under the legend", p) for p in legend_problems(fig))
    plt.close(fig)
