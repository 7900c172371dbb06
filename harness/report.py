"""HTML report: figures (matplotlib, embedded as PNG) and tables from the results table, via a Jinja template."""
import base64
import io
import os
from pathlib import Path

import jinja2

from .kinematics import CONVENTIONS

TEMPLATES = Path(__file__).resolve().parent.parent / "templates"


def figure_png(fig):
    """Encode a matplotlib figure as a base64 PNG data string."""
    buffer = io.BytesIO()
    fig.savefig(buffer, format="png", dpi=90, bbox_inches="tight")
    return base64.b64encode(buffer.getvalue()).decode("ascii")


def normalised_figure(frame, chi):
    """Psi2* and Omega* against Psi1*, one curve per e_n, with the rigid-body sliding lines (MODELS 4)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.2))
    for e_n, group in frame.groupby("e_n_target", sort=False):
        group = group.sort_values("psi1_star")
        left.plot(group.psi1_star, group.psi2_star, marker=".", label=f"e_n = {e_n:g}")
        right.plot(group.psi1_star, group.omega_star, marker=".", label=f"e_n = {e_n:g}")
    top = min(float(frame.psi1_star.max()), 5.0 * chi)       # the paper's range; grazing angles go far beyond
    left.plot([2 * chi, top], [0.0, top - 2 * chi], "k--", lw=1, label="sliding: Psi2* = Psi1* - 2 chi")
    left.set_xlim(0.0, top)
    right.set_xlim(0.0, top)
    left.set_ylim(-top / 2.0, top - 2 * chi + 0.5)
    right.axhline(2.5, color="k", ls="--", lw=1, label="sliding: Omega* = 5/2")
    left.set(xlabel="Psi1*", ylabel="Psi2*")
    right.set(xlabel="Psi1*", ylabel="Omega*")
    for ax in (left, right):
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    png = figure_png(fig)
    plt.close(fig)
    return png


def records(table):
    """A DataFrame as (columns, rows of formatted cells) for the template."""
    if table is None or table.empty:
        return None
    def cell(value):
        if isinstance(value, float):
            return f"{value:.6g}"
        return str(value)
    return list(table.columns), [[cell(v) for v in row] for row in table.itertuples(index=False)]


def engines_ran(frame):
    """(engine, version, dialects) for every engine that has rows."""
    return [(engine, str(group.engine_version.iloc[0]), ", ".join(sorted(group.dialect.unique())) + " dialect")
            for engine, group in frame.groupby("engine", sort=False)]


def write_report(out_dir, frame, law, scene, skipped, agreement=None, deviation=None, cross=None, attributions=None,
                 findings=None, failures=(), precision=None):
    """Render DIR/report.html (self-contained) and return its path."""
    env = jinja2.Environment(loader=jinja2.FileSystemLoader(str(TEMPLATES)), autoescape=True,
                             undefined=jinja2.StrictUndefined)
    figures = []
    paper = frame[(frame.engine == "reference") & (frame.dialect == "paper")]
    if (paper.psi1_star > 0).any():
        figures.append(("Normalised rebound of the paper law: Psi2* and Omega* against Psi1*",
                        normalised_figure(paper, scene.contact.chi)))
    summary = paper.groupby("e_n_target", sort=False).agg(
        e_n_min=("e_n", "min"), e_n_max=("e_n", "max"), e_t_min=("e_t", "min"), e_t_max=("e_t", "max"),
        t_contact_max=("t_contact", "max"), f_n_max=("f_n_max", "max"), ke_ratio_max=("ke_ratio", "max"),
        rows=("status", "size")).reset_index()
    html = env.get_template("report.html.j2").render(
        law=law, submodels=law.describe(), scene=scene, conventions=CONVENTIONS, figures=figures,
        summary=summary.to_dict("records"), skipped=skipped, rows=len(frame), ran=engines_ran(frame), agreement=records(agreement),
        deviation=records(deviation), cross=records(cross), findings=records(findings), failures=failures,
        precision=records(precision),
        attributions=[(name, records(table)) for name, table in (attributions or {}).items()])
    path = os.path.join(out_dir, "report.html")
    tmp = path + ".tmp"
    with open(tmp, "w", encoding="utf-8") as handle:
        handle.write(html)
    os.replace(tmp, path)
    return path
