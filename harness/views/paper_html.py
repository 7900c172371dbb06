"""The paper's figure set as one HTML page, from the three tables `harness paper` writes (paper.py)."""
import datetime
import os

import numpy as np

from ..infra.files import write_text
from ..scenes.kinematics import CONVENTIONS
from ..laws import LAWS
from ..analyses.published import GOAL
from ..data.digitised import points_of, provenance
from ..analyses.paper_axis import ELASTIC, PSI1_GRID
from ..infra.render import environment
from ..infra.version import __version__
from .drawing import draw_all
from .figure_files import filed
from .paper_axes import PAPER_PANELS, draw_published, draw_rigid_body, set_paper_axes
from .pieces import figure_svg, legend_below, records

OBLIQUE, NORMAL, SLIDING, PUBLISHED = "paper.csv", "paper-normal.csv", "paper-sliding.csv", "paper-published.csv"
PAGE = "paper.html"
FILES = (OBLIQUE, NORMAL, SLIDING, PUBLISHED, PAGE)
PUBLISHED_LABEL = "published (TCC13, digitised)"
NORMAL_COLUMNS = {"t_contact": "contact time [s]", "f_n_max": "peak force [N]"}     # as the page heads them
COLOURS = ("#1b9e77", "#d95f02", "#7570b3", "#e7298a", "#66a61e", "#e6ab02")    # one per e_n, in every figure


def law_figure(oblique, sliding, name):
    """Psi2*, Omega* and e_t against Psi1* for one law: one curve per e_n, elastic Hertz-Mindlin and the rigid body
    dashed, the simulated sliding-throughout thresholds dotted and the paper's published points (open circles) in
    each e_n's colour."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    rows = oblique[oblique.model == name]
    elastic = oblique[oblique.model == ELASTIC].sort_values("psi1_star")
    thresholds = dict(zip(sliding[sliding.model == name].e_n_target, sliding[sliding.model == name].simulated))
    fig, axes = plt.subplots(1, len(PAPER_PANELS), figsize=(4.2 * len(PAPER_PANELS), 3.8), constrained_layout=True)
    for ax, (column, label, _) in zip(axes, PAPER_PANELS):
        published = False
        for colour, (e_n, group) in zip(COLOURS, rows.groupby("e_n_target", sort=True)):
            group = group.sort_values("psi1_star")
            ax.plot(group.psi1_star, group[column], color=colour, lw=1.4, label=f"e_n = {e_n:g}")
            if np.isfinite(thresholds.get(e_n, np.nan)):
                ax.axvline(thresholds[e_n], color=colour, ls=":", lw=1)
            points = points_of(name, column, e_n)
            if not points.empty:
                draw_published(ax, points, colour, None if published else PUBLISHED_LABEL)
                published = True
        ax.plot(elastic.psi1_star, elastic[column], color="0.3", ls=":", lw=1.4, label="elastic Hertz-Mindlin")
        draw_rigid_body(ax, column)
        set_paper_axes(ax, column, label)
    legend_below(fig)
    fig.suptitle(f"{name}{' (provisional)' if LAWS[name].provisional else ''}: dotted, where it slides throughout")
    svg = figure_svg(fig)
    plt.close(fig)
    return svg


def normal_figure(normal):
    """Contact duration and peak force of the normal impact against e_n, relative to elastic Hertz, per law."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(11, 4), constrained_layout=True)
    for ax, column, label in zip(axes, ("t_c/t_Hertz", "F_max/F_Hertz"),
                                 ("contact duration / elastic Hertz", "peak force / elastic Hertz")):
        for name, group in normal.groupby("model", sort=False):
            ax.plot(group.e_n_target, group[column], marker="o", ms=3,
                    ls="--" if LAWS[name].provisional else "-", label=name)
        ax.axhline(1.0, color="k", lw=0.8)
        ax.set(xlabel="target e_n", ylabel=label)
        ax.grid(alpha=0.3)
    legend_below(fig)
    fig.suptitle("normal impact at 5 m/s (dashed: provisional laws)")
    svg = figure_svg(fig)
    plt.close(fig)
    return svg


def write_paper_report(out_dir, oblique, normal, sliding, command, published=None):
    """DIR/paper.html from the tables (the distances from the published points, when given); returns its path."""
    names = [n for n in oblique.model.unique() if n != ELASTIC]
    calls = [(law_figure, (oblique, sliding, name)) for name in names] + [(normal_figure, (normal,))]
    titles = names + ["contact duration and peak force against e_n"]
    figures = filed(out_dir, list(zip(titles, draw_all(calls), [f"paper-{n}-vs-psi1" for n in names]
                                      + ["paper-contact-duration-and-peak-force-vs-e_n"])))
    at_paper_en = normal[normal.e_n_target.isin(sorted(set(oblique.e_n_target) - {1.0}))]
    html = environment(autoescape=True).get_template("paper.html.j2").render(
        figures=figures, laws=[LAWS[n] for n in names], sliding=records(sliding.drop(columns=["method"])),
        methods=sorted(set(sliding.method)), normal=records(at_paper_en.rename(columns=NORMAL_COLUMNS)),
        conventions=CONVENTIONS,
        psi_points=len(PSI1_GRID), psi_from=PSI1_GRID[0], command=command, version=__version__,
        published=records(published) if published is not None and not published.empty else None,
        goal=GOAL, provenance=provenance(), date=datetime.datetime.now().strftime("%Y-%m-%d %H:%M"),
        files=(OBLIQUE, NORMAL, SLIDING) + ((PUBLISHED,) if published is not None else ()))
    return write_text(os.path.join(out_dir, PAGE), html)
