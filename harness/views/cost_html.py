"""The report's accuracy-against-cost section, from cost.csv alone: log-log figures and the tables."""
import numpy as np

from . import style
from .drawing import draw_all
from .pieces import figure_svg, legend_below, number, records
from ..analyses.cost import (ADAPTIVE, EXTRAPOLATED, MEASURE, METRICS, NOT_RESOLVED, TOLERANCES, convergence_orders,
                             ladder_rows, per_rung, step_times)
from ..analyses.cost_answer import answers, notes, recommendations, steps_text, verdict
from ..runs.outputs import COST, COST_RUN, COST_TRUTH

LABELS = {"v_n1": "v_n1 (of V)", "v_t1": "v_t1 (of V)", "omega1": "R omega1 (of V)",
          "t_contact": "contact time (of its largest)", "f_n_max": "peak force (of its largest)", "max": "worst metric"}


def curve_style(engine, dialect):
    """The report's colour per engine and line style per dialect (views.style); the converged mode's rungs (adaptive
    or extrapolated) as the paper law's colour, dotted, with triangles."""
    if engine == "reference" and dialect in (EXTRAPOLATED, ADAPTIVE):
        return {"color": style.colour(engine), "lw": 1.8, "ls": ":", "marker": "^", "ms": 4}
    return {**style.curve(engine, dialect), "marker": "o" if engine == "reference" else "s", "ms": 3}


def curve_label(engine, dialect):
    """The legend's words for a curve: the converged mode's rungs as the paper law's (views.style otherwise)."""
    if engine == "reference" and dialect in (EXTRAPOLATED, ADAPTIVE):
        return f"paper law, {dialect.split(', ')[1]} (converged mode)"
    return style.label(engine, dialect)


def _curves(cost):
    """(engine, dialect, ladder rows aggregated over e_n, Rayleigh row, converged row) per curve."""
    for (engine, dialect), per_curve in per_rung(cost).groupby(["engine", "dialect"], sort=False):
        per_curve = per_curve.rename(columns={"steps_per_contact": "n"})
        ladder = ladder_rows(per_curve).sort_values("n")
        yield (engine, dialect, ladder, per_curve[per_curve.rung == "rayleigh"],
               per_curve[per_curve.rung == "converged"])


def cost_figure(cost, x_column, x_label, metrics):
    """One log-log panel per metric: error against `x_column`, one curve per engine and dialect; the 20%-Rayleigh
    run as a diamond (and, against steps per contact, a vertical line), the converged mode as a star, the 1%, 0.1%,
    0.01% levels as grey lines; one legend below; a curve whose time is not resolved is named on the panel."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.ticker import LogLocator, NullFormatter
    fig, axes = plt.subplots(1, len(metrics), figsize=(3.9 * len(metrics) + 0.6, 4.2), squeeze=False,
                             layout="constrained")
    for ax, metric in zip(axes[0], metrics):
        column, missing = f"err_{metric}", []
        for engine, dialect, ladder, rayleigh, converged in _curves(cost):
            data = ladder[np.isfinite(ladder[column]) & (ladder[column] > 0) & (ladder[x_column] > 0)]
            if data.empty:
                if not ladder.empty:
                    missing.append(curve_label(engine, dialect))
                continue
            line, = ax.plot(data[x_column], data[column], label=curve_label(engine, dialect),
                            **curve_style(engine, dialect))
            for row in rayleigh.itertuples():
                if getattr(row, column) > 0 and getattr(row, x_column) > 0:
                    ax.plot(getattr(row, x_column), getattr(row, column), "D", ms=7, mfc="none", color=line.get_color())
            for row in converged.itertuples():
                if getattr(row, column) > 0 and getattr(row, x_column) > 0:
                    ax.plot(getattr(row, x_column), getattr(row, column), "*", ms=11, color=line.get_color())
        for tol in TOLERANCES:
            ax.axhline(tol, color="0.6", lw=0.8, ls=":")
        if x_column == "n":
            rule = per_rung(cost)
            rule = rule[(rule.rung == "rayleigh") & (rule.engine == "reference") & (rule.dialect == "paper")]
            for n in rule.steps_per_contact:
                ax.axvline(n, color="0.3", lw=0.9, ls="--")
                ax.annotate(f"20% T_R\n({n:.3g}/contact)", (n, 1), xycoords=("data", "axes fraction"),
                            xytext=(3, -3), textcoords="offset points", va="top", fontsize=7, color="0.3")
        if missing:
            ax.text(0.02, 0.02, "time not resolved: " + ", ".join(missing), transform=ax.transAxes, fontsize=7,
                    color="#b22222", va="bottom")
        ax.set(xscale="log", yscale="log", title=LABELS[metric], xlabel=x_label)
        for axis in (ax.xaxis, ax.yaxis):
            axis.set_major_locator(LogLocator(base=10, numticks=5))
            axis.set_minor_formatter(NullFormatter())
        ax.grid(alpha=0.3, which="major")
    axes[0][0].set_ylabel("error (worst impact and e_n)")
    marks = [plt.Line2D([], [], marker="D", mfc="none", color="k", ls="none", label="20% of the Rayleigh time"),
             plt.Line2D([], [], marker="*", color="k", ls="none", label="converged mode")]
    legend_below(fig, marks)
    svg = figure_svg(fig)
    plt.close(fig)
    return svg


def timing_cells(cost):
    """Each curve's time per impact-step as the page shows it: the seconds, or 'not resolved', and how it was timed."""
    times = step_times(cost)
    if times.empty:
        return None
    shown = times.assign(s_per_impact_step=[number(v) if v == v else NOT_RESOLVED for v in times.s_per_impact_step])
    return records(shown.rename(columns={"s_per_impact_step": "s per impact-step", "message": "timed on"}))


def verdict_cells(cost, found):
    """The verdict box's rows (analyses.cost_answer.verdict), a time not resolved said as such, the steps marked as
    the terminal marks them (analyses.cost_answer.steps_text)."""
    verdicts = verdict(cost, found)
    if verdicts.empty:
        return None
    verdicts["s/impact-step"] = [number(v) if v == v else NOT_RESOLVED for v in verdicts["s/impact-step"]]
    for key in ("1%", "0.1%"):
        verdicts[f"steps/contact for {key}"] = [steps_text(v, how) for v, how in
                                                zip(verdicts[f"steps/contact for {key}"], verdicts[f"how for {key}"])]
    return records(verdicts.drop(columns=["timing", "how for 1%", "how for 0.1%"]))


def cost_section(cost, uncertainty, run):
    """Figures and tables of the cost section, from the cost table, the truth's uncertainty and the study's record."""
    model = run["model"]
    titles, names, calls = zip(
        (f"{model}: worst-metric error against time per impact (impact-steps x the curve's resolved time per "
         f"impact-step)", f"{model}-worst-error-vs-time-per-impact",
         (cost_figure, (cost, "s_per_impact", "time per impact [s]", ("max",)))),
        (f"{model}: error of each metric against time per impact", f"{model}-errors-vs-time-per-impact",
         (cost_figure, (cost, "s_per_impact", "time per impact [s]", METRICS))),
        (f"{model}: error of each metric against steps per contact (the adaptive curve: force evaluations)",
         f"{model}-errors-vs-steps-per-contact", (cost_figure, (cost, "n", "steps or evaluations/contact", METRICS))))
    figures = list(zip(titles, draw_all(list(calls)), names))
    found = answers(cost)
    refused = cost[cost.status == "refused"].drop_duplicates(["engine", "dialect", "rung"])
    times = step_times(cost)
    return {"figures": figures, "recommendations": records(recommendations(cost, found)),
            "verdict": verdict_cells(cost, found), "notes": notes(found, TOLERANCES[:2], verdict_only=True),
            "all_notes": notes(found), "measure": MEASURE,
            "timings": timing_cells(cost),
            "unresolved": list(times[times.timing == NOT_RESOLVED].engine), "files": (COST, COST_TRUTH, COST_RUN),
            "orders": records(convergence_orders(cost)),
            "refused": records(refused[["engine", "dialect", "rung", "message"]]),
            "table": records(cost.drop(columns=["model", "message"])),
            "model": model, "skipped": [tuple(s) for s in run["skipped"]], "failures": run.get("failures", []),
            "scene": run["scene"], "uncertainty": records(uncertainty) if not uncertainty.empty else None}
