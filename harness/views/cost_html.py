"""The report's accuracy-against-cost section, from cost.csv alone: log-log figures and the tables."""
import numpy as np

from . import style
from .drawing import draw_all
from .pieces import figure_svg, records
from ..analyses.cost import (ADAPTIVE, EXTRAPOLATED, METRICS, TOLERANCES, WITHIN_NOISE, convergence_orders, ladder_rows, per_rung,
                   recommendations)

LABELS = {"e_n": "e_n", "e_t": "e_t", "omega_star": "Omega*", "t_contact": "contact time", "f_n_max": "peak force",
          "max": "worst metric"}


def curve_style(engine, dialect):
    """The report's colour per engine and line style per dialect (views.style); the converged mode's rungs (adaptive
    or extrapolated) as the paper law's colour, dotted, with triangles."""
    if engine == "reference" and dialect in (EXTRAPOLATED, ADAPTIVE):
        return {"color": style.colour(engine), "lw": 1.8, "ls": ":", "marker": "^", "ms": 4}
    return {**style.curve(engine, dialect), "marker": "o" if engine == "reference" else "s", "ms": 3}


def _curves(cost):
    """(engine, dialect, ladder rows aggregated over e_n, Rayleigh row, converged row) per curve."""
    for (engine, dialect), per_curve in per_rung(cost).groupby(["engine", "dialect"], sort=False):
        per_curve = per_curve.rename(columns={"steps_per_contact": "n"})
        ladder = ladder_rows(per_curve).sort_values("n")
        yield (engine, dialect, ladder, per_curve[per_curve.rung == "rayleigh"],
               per_curve[per_curve.rung == "converged"])


def cost_figure(cost, x_column, x_label, metrics):
    """One log-log panel per metric: error against `x_column`, one curve per engine and dialect; the 20%-Rayleigh
    run as a diamond, the converged mode as a star, the 1%, 0.1%, 0.01% levels as grey lines."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, len(metrics), figsize=(3.7 * len(metrics), 3.6), squeeze=False, layout="constrained")
    for ax, metric in zip(axes[0], metrics):
        column = f"err_{metric}"
        for engine, dialect, ladder, rayleigh, converged in _curves(cost):
            data = ladder[np.isfinite(ladder[column]) & (ladder[column] > 0) & (ladder[x_column] > 0)]
            if x_column == "net_wall_s":             # a time within the machine's noise is not a time
                data = data[data.timing != WITHIN_NOISE]
            if data.empty:
                continue
            line, = ax.plot(data[x_column], data[column], label=style.label(engine, dialect),
                            **curve_style(engine, dialect))
            for row in rayleigh.itertuples():
                if getattr(row, column) > 0 and getattr(row, x_column) > 0:
                    ax.plot(getattr(row, x_column), getattr(row, column), "D", ms=7, mfc="none", color=line.get_color())
            for row in converged.itertuples():
                if getattr(row, column) > 0 and getattr(row, x_column) > 0:
                    ax.plot(getattr(row, x_column), getattr(row, column), "*", ms=11, color=line.get_color())
        for tol in TOLERANCES:
            ax.axhline(tol, color="0.6", lw=0.8, ls=":")
        ax.set(xscale="log", yscale="log", title=LABELS[metric], xlabel=x_label)
        ax.grid(alpha=0.3, which="both")
    axes[0][0].set_ylabel("relative error")
    axes[0][-1].plot([], [], "D", mfc="none", color="k", label="20% Rayleigh time")
    axes[0][-1].plot([], [], "*", color="k", label="converged mode")
    axes[0][-1].legend(fontsize=7)
    svg = figure_svg(fig)
    plt.close(fig)
    return svg


def cost_section(cost, uncertainty, run):
    """Figures and tables of the cost section, from the cost table, the truth's uncertainty and the study's record."""
    model = run["model"]
    titles, names, calls = zip(
        (f"{model}: worst-metric error against wall time (start-up excluded)", f"{model}-worst-error-vs-wall-time",
         (cost_figure, (cost, "net_wall_s", "wall time [s]", ("max",)))),
        (f"{model}: error of each metric against wall time (start-up excluded)", f"{model}-errors-vs-wall-time",
         (cost_figure, (cost, "net_wall_s", "wall time [s]", METRICS))),
        (f"{model}: error of each metric against steps per contact (the adaptive curve: force evaluations)",
         f"{model}-errors-vs-steps-per-contact", (cost_figure, (cost, "n", "steps or evaluations/contact", METRICS))))
    figures = list(zip(titles, draw_all(list(calls)), names))
    refused = cost[cost.status == "refused"].drop_duplicates(["engine", "dialect", "rung"])
    return {"figures": figures, "recommendations": records(recommendations(cost)),
            "orders": records(convergence_orders(cost)),
            "refused": records(refused[["engine", "dialect", "rung", "message"]]),
            "table": records(cost.drop(columns=["model", "message"])),
            "model": model, "skipped": [tuple(s) for s in run["skipped"]], "failures": run.get("failures", []),
            "scene": run["scene"], "uncertainty": records(uncertainty) if not uncertainty.empty else None}
