"""The calibration report: a verdict box (before and after, per stage; what did not run and why), what to type per
target e_n (every value, the lines to paste), the paper law's figures on the paper's axes with the engine's formulas
as given, calibrated and the engine run with the calibrated inputs, the choices with their price and the rule, the
time-step ladder, how the input moves with the scene, and links to calibration.json, the CSVs and the inputs."""
import datetime
import os

import numpy as np

from ..infra.files import write_text
from ..infra.render import environment
from ..infra.version import __version__
from .figure_files import filed, one
from .paper_axes import PAPER_PANELS, PSI1_RANGE, draw_rigid_body, in_window, set_paper_axes
from .pieces import figure_svg, legend_below, records

STAGE_STYLES = {"paper": ("black", "-", "paper law"), "formulas, e as given": ("tab:red", ":", None),
                "your input": ("tab:red", ":", None),
                "formulas, calibrated": ("tab:blue", "--", None), "engine, calibrated": ("tab:blue", "-", None)}


def paper_figure(frame, column):
    """`column` against Psi1* per stage on the paper's axes (Psi1* 0 to 14, the impacts beyond counted and not
    drawn, a point far beyond the y range marked on its edge), with the rigid body's curve, one panel per target."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    targets = sorted(frame.e_n_target.unique())
    fig, axes = plt.subplots(1, len(targets), figsize=(3.6 * len(targets), 3.2), constrained_layout=True,
                             squeeze=False)
    for ax, target in zip(axes[0], targets):
        everything = frame[frame.e_n_target == target]
        beyond = everything[everything.psi1_star > PSI1_RANGE[1]].theta_deg.nunique()
        rows = in_window(everything)
        for stage, (colour, dashes, name) in STAGE_STYLES.items():
            data = rows[rows.dialect == stage].sort_values("psi1_star")
            if not data.empty:
                ax.plot(data.psi1_star, data[column], color=colour, ls=dashes, lw=2.2 if stage.startswith("engine")
                        else 1.3, alpha=0.6 if stage.startswith("engine") else 1.0, label=name or stage)
        draw_rigid_body(ax, column)
        set_paper_axes(ax, column, dict((c, label) for c, label, _ in PAPER_PANELS)[column], int(beyond))
        ax.set_title(f"e_n {target:g}")
    legend_below(fig)
    svg = figure_svg(fig)
    plt.close(fig)
    return svg


def variation_figure(variation):
    """The input e against the target e_n, one line per (speed, radius) of the scene's times 0.5, 1 and 2."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6, 4), constrained_layout=True)
    for (speed, radius), rows in variation.groupby(["speed_m_s", "radius_m"], sort=False):
        ax.plot(rows.e_n_target, rows.input_e.astype(float), marker="o", ms=3, label=f"{speed:g} m/s, R {radius:g} m")
    lims = [0, 1]
    ax.plot(lims, lims, color="0.6", lw=0.8, ls=":", label="input = target")
    ax.set(xlabel="target e_n", ylabel="e to give the engine", title="calibrated input against the scene")
    ax.grid(alpha=0.3)
    legend_below(fig)
    svg = figure_svg(fig)
    plt.close(fig)
    return svg


def verdict_rows(calibration):
    """Per stage: its physics verdict and worst case of each failed check."""
    rows = []
    for stage, physics in calibration.physics.items():
        failed = [c for c in physics["checks"] if not c["passed"]]
        rows.append({"stage": stage, "state": physics["state"], "impacts": physics["impacts"],
                     "what fails (worst case)": "; ".join(c["short"] for c in failed) or "nothing",
                     "ingredient": "; ".join(filter(None, (c.get("ingredient") for c in failed)))})
    import pandas as pd
    return pd.DataFrame(rows)


def write_calibration_report(calibration, out_dir, inputs):
    """Write DIR/report.html of a calibration; its path."""
    c = calibration
    advice = c.advice
    env = environment(autoescape=True)
    page = env.get_template("calibration.html.j2").render(
        c=c, version=__version__, date=datetime.datetime.now().isoformat(timespec="minutes"),
        verdict=records(verdict_rows(c)), stages=records(c.stages), inputs=records(c.inputs),
        alternatives=records(c.alternatives), attribution=records(c.attribution), refused=c.refused, typed=c.typed,
        ladder=records(advice.ladder), variation=records(c.variation), files=inputs,
        figures=filed(out_dir, [("e_t against Psi1*", paper_figure(c.frame, "e_t"), "calibration-e_t-vs-psi1"),
                                ("Omega* against Psi1*", paper_figure(c.frame, "omega_star"),
                                 "calibration-omega-vs-psi1")]),
        variation_figure=one(out_dir, "input e against target e_n", variation_figure(c.variation),
                             "calibration-input-e-vs-e_n")
        if np.isfinite(c.variation.input_e.astype(float)).any() else None, advice=advice, confirmed=c.confirmed)
    path = os.path.join(out_dir, "report.html")
    write_text(path, page)
    return path
