"""The HTML report: a summary of the verdict first, then figures (inline SVG) and tables, all from the saved
results directory, via a Jinja template."""
import os

import numpy as np
import pandas as pd

from ..analyses.physics import CHECK_WORDS, MARGINAL_SHARE, MARGINAL_TIMES, Tolerances
from ..analyses.published import published_distances
from ..analyses.verdict import verdict
from ..data.digitised import points_of, published_curves_apply
from ..infra.files import write_text
from ..scenes.kinematics import CONVENTIONS
from ..runs.outputs import kinds, load_comparison, load_cost
from ..infra.render import environment
from ..infra.version import __version__
from . import style
from .cost_html import cost_section
from .drawing import draw_all
from .figure_files import filed
from .paper_axes import (ANGLE_LABELS, PAPER_PANELS, PSI1_RANGE, draw_published, draw_rigid_body, in_window,
                         set_paper_axes)
from .states_view import first_impacts
from .pieces import figure_svg, legend_below, number, records, si


def engines_ran(frame):
    """(engine, version, dialects) for every engine that has rows."""
    return [(engine, str(group.engine_version.iloc[0]), ", ".join(sorted(group.dialect.unique())) + " dialect")
            for engine, group in frame.groupby("engine", sort=False)]


def run_facts(frame, arithmetic):
    """One row per (engine, dialect) run: version, arithmetic, steps per contact, dt range, impacts, wall time."""
    import pandas as pd
    rows = []
    for (engine, dialect), group in frame.groupby(["engine", "dialect"], sort=False):
        rows.append({"engine": engine, "dialect": dialect, "version": str(group.engine_version.iloc[0]),
                     "arithmetic": arithmetic.get(engine, "double"),
                     "steps per contact": ", ".join(f"{n:.4g}" for n in group.steps_per_contact.unique()),
                     "dt min [s]": group.dt.min(), "dt max [s]": group.dt.max(), "impacts": len(group),
                     "not ok": int((group.status != "ok").sum()),
                     "wall time [s]": float(group.wall_s.sum()),
                     "wall per impact [s]": float(group.wall_s.mean()),
                     "binary": str(group.engine_binary.iloc[0]), "sha256": str(group.engine_sha256.iloc[0])[:16]})
    return pd.DataFrame(rows)


def series_figure(frame, title, x, ys, thresholds=None, published=None):
    """series_plot as inline SVG."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig = series_plot(frame, title, x, ys, thresholds, published)
    svg = figure_svg(fig)
    plt.close(fig)
    return svg


def series_plot(frame, title, x, ys, thresholds=None, published=None):
    """A matplotlib Figure: one panel per e_n; one curve per (engine, dialect) and y column, in the colours and line
    styles of views.style. Against Psi1* the paper's axes and ranges, the rigid body's curve, where known the
    sliding-throughout threshold of the paper law (dotted) and, with `published` (the law's name, where the paper's
    published curves apply to the scene: digitised.published_curves_apply), the paper's points. Drawn with pyplot's
    backend as it is (a notebook's stays)."""
    import matplotlib.pyplot as plt
    paper = x == "psi1_star"
    beyond = {}
    if paper:
        beyond = frame[frame.psi1_star > PSI1_RANGE[1]].groupby("e_n_target").theta_deg.nunique().to_dict()
    groups = list(frame.groupby("e_n_target", sort=False))    # a panel per e_n, even one whose impacts all lie beyond
    fig, axes = plt.subplots(1, len(groups), figsize=(3.4 * len(groups), 3.6), squeeze=False, layout="constrained")
    for ax, (e_n, group) in zip(axes[0], groups):
        group = in_window(group) if paper else group
        for (engine, dialect), series in group.groupby(["engine", "dialect"], sort=False):
            series = series.sort_values(x)
            for y, marker in zip(ys, ("", "o")):
                suffix = "" if len(ys) == 1 else (", centre" if "com" in y else ", contact point")
                ax.plot(series[x], series[y], marker=marker, ms=2.5, label=style.label(engine, dialect) + suffix,
                        **style.curve(engine, dialect))
        if paper:
            draw_rigid_body(ax, ys[0])
            if published:
                points = points_of(published, ys[0], e_n)
                if not points.empty:
                    draw_published(ax, points, "tab:red", "published (TCC13, digitised)")
            set_paper_axes(ax, ys[0], dict((c, label) for c, label, _ in PAPER_PANELS)[ys[0]], int(beyond.get(e_n, 0)))
            threshold = (thresholds or {}).get(e_n)
            if threshold is not None and np.isfinite(threshold):
                ax.axvline(threshold, color="0.4", ls=":", lw=1, label="the paper law slides throughout from here")
                ax.annotate(f"{threshold:.3f}", (threshold, 1), xycoords=("data", "axes fraction"), xytext=(2, -2),
                            textcoords="offset points", va="top", fontsize=7, color="0.4")
        else:
            ax.set(xlabel=ANGLE_LABELS[0], ylabel=ANGLE_LABELS[1])
            ax.grid(alpha=0.3)
        ax.set_title(f"e_n = {e_n:g}", fontsize=10)
        if ax is not axes[0][0]:
            ax.set_ylabel("")
    legend_below(fig)
    fig.suptitle(title)
    return fig


PANELS = (   # (title, x column, y columns, file name)
    ("Psi2*, the normalised rebound slip, against Psi1*", "psi1_star", ("psi2_star",), "psi2-vs-psi1"),
    ("Omega*, the normalised rebound spin, against Psi1*", "psi1_star", ("omega_star",), "omega-vs-psi1"),
    ("e_t, the tangential restitution, against Psi1*", "psi1_star", ("e_t",), "e_t-vs-psi1"),
    ("rebound angles of the centre (line) and the contact point (dots) against the impact angle", "theta_deg",
     ("theta_r_com_deg", "theta_r_cp_deg"), "rebound-angles-vs-angle"),
)


def force_figure(histories, contact, speed):
    """Normal impact: force against time and against overlap, one curve per e_n (paper law)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 3.8), layout="constrained")
    for e_n, history in histories.items():
        h = history[0][~np.isnan(history[0][:, 0])]
        left.plot(h[:, 0] * 1e6, h[:, 2], label=f"e_n = {e_n:g}")
        right.plot(h[:, 1] * 1e6, h[:, 2], label=f"e_n = {e_n:g}")
    left.set(xlabel="time since first touch [us]", ylabel="normal force [N]", title="force against time")
    right.set(xlabel="overlap [um]", ylabel="normal force [N]", title="force against overlap")
    for ax in (left, right):
        ax.grid(alpha=0.3)
    legend_below(fig, fontsize=8)
    fig.suptitle("normal impact at the scene speed, paper law")
    svg = figure_svg(fig)
    plt.close(fig)
    return svg


def hertz_ratios(normal, contact, speed):
    """Contact time and peak force of the normal impacts against elastic Hertz at the same speed (docs/laws.md)."""
    alpha = (15.0 * contact.mass * speed ** 2 / (16.0 * contact.E_star * np.sqrt(contact.radius))) ** 0.4
    t_h = 2.94328 * alpha / speed
    f_h = 4.0 / 3.0 * contact.E_star * np.sqrt(contact.radius) * alpha ** 1.5
    table = normal[["e_n_target", "e_n", "t_contact", "f_n_max"]].copy()
    table["t_c/t_Hertz"] = table.t_contact / t_h
    table["F_max/F_Hertz"] = table.f_n_max / f_h
    return table


def rebuild(out_dir):
    """Write DIR/report.html from the files in DIR alone (a comparison, a cost study or both); returns its path.
    The report is always built from the saved data, so `harness report DIR` simulates nothing."""
    has_compare, has_cost = kinds(out_dir)
    return write_report(out_dir, load_comparison(out_dir) if has_compare else None,
                        load_cost(out_dir) if has_cost else None)


def write_report(out_dir, comparison=None, cost=None):
    """Render DIR/report.html (self-contained) from a Comparison, a cost study (table, truth uncertainty, its run
    record) or both; returns its path."""
    env = environment(autoescape=True)
    cost_part = cost_section(*cost) if cost is not None else None
    files = sorted(name for name in os.listdir(out_dir) if name.endswith((".csv", ".json")))
    compare = compare_context(comparison, files) if comparison is not None else None
    for part in (compare, cost_part):
        if part is not None:
            part["figures"] = filed(out_dir, part["figures"])
    context = {"compare": compare, "cost": cost_part,
               "conventions": CONVENTIONS, "files": files, "version": __version__,
               "dialect_styles": style.dialect_styles(),
               "title": comparison.law.name if comparison is not None else cost_part["model"]}
    html = env.get_template("report.html.j2").render(**context)
    return write_text(os.path.join(out_dir, "report.html"), html)


def sliding_lines(sliding):
    """{e_n: simulated threshold} of the paper law, from the sliding table (None when there is none)."""
    if sliding is None or sliding.empty:
        return None
    return dict(zip(sliding.e_n_target, sliding.simulated))


def scene_facts(scene):
    """The scene in words and units."""
    return [("material", scene.material), ("radius", si(scene.radius, "m")), ("Young's modulus E", si(scene.E, "Pa")),
            ("Poisson's ratio", number(scene.nu)), ("density", f"{number(scene.rho)} kg/m^3"),
            ("friction coefficient", number(scene.mu)),
            (f"impact speed ({'normal' if scene.speed_is == 'normal' else 'resultant'})", f"{number(scene.speed)} m/s"),
            ("wall", scene.wall), ("initial spin", f"{number(scene.omega0)} rad/s"),
            ("gravity", f"{number(scene.gravity)} m/s^2"), ("target e_n", ", ".join(number(e) for e in scene.e_n))] + (
        [("gap before contact", si(scene.gap, "m"))] if scene.gap else [])


def compare_context(comparison, files=()):
    """The summary, figures and tables of the compare sections."""
    frame, law, scene = comparison.results, comparison.law, comparison.scene
    histories, sliding = comparison.histories, comparison.sliding
    cross = [(f"{b} against {a}", records(table)) for (a, b), table in comparison.cross.items() if not table.empty]
    figures = []
    paper = frame[(frame.engine == "reference") & (frame.dialect == "paper")]
    oblique = frame[frame.psi1_star > 0]
    calls = []
    published = law.name if published_curves_apply(scene, law.name) else None
    if not oblique.empty:
        for title, x, ys, name in PANELS:
            figures.append((f"{law.name}: {title}", f"{law.name}-{name}"))
            calls.append((series_figure, (oblique, title, x, ys, sliding_lines(sliding), published)))
    normal_rows = paper[paper.theta_deg == 0.0]
    ratios = records(hertz_ratios(normal_rows, scene.contact, scene.speed)) if not normal_rows.empty else None
    if histories:
        figures.append((f"{law.name}: normal impact, force against time and overlap (paper law)",
                        f"{law.name}-normal-force-vs-time-and-overlap"))
        calls.append((force_figure, (histories, scene.contact, scene.speed)))
    figures = [(title, svg, name) for (title, name), svg in zip(figures, draw_all(calls))]
    summary = paper.groupby("e_n_target", sort=False).agg(
        e_n_min=("e_n", "min"), e_n_max=("e_n", "max"), e_t_min=("e_t", "min"), e_t_max=("e_t", "max"),
        t_contact_max=("t_contact", "max"), f_n_max=("f_n_max", "max"), ke_ratio_max=("ke_ratio", "max"),
        rows=("status", "size")).reset_index()
    precision = pd.DataFrame([comparison.precision]) if comparison.precision else None
    distances = published_distances(paper) if published else None
    record = verdict(comparison)
    checks = pd.DataFrame([{"engine": e["engine"], "check": CHECK_WORDS[c["check"]],
                            "grade": c.get("grade", "holds" if c["passed"] else ""), "tolerance": c["tolerance"],
                            "worst": c.get("worst"), "x tolerance": c.get("times_tolerance"), "impacts": c["impacts"],
                            "beyond": c["failing"], "worst case": c.get("text", ""), "causes": c.get("cause", "")}
                           for e in record["engines"] for c in e["physics"]["checks"]])
    return dict(law=law, submodels=law.describe(), scene=scene_facts(scene), figures=figures,
                tolerance_words=Tolerances.of(record["tolerances"]).describe(), check_words=CHECK_WORDS,
                marginal_times=f"{MARGINAL_TIMES:g}", marginal_share=f"{MARGINAL_SHARE:.0%}",
                verdict=record, command=comparison.command, date=comparison.date, files=files,
                partial=comparison.partial,
                summary=records(summary), skipped=comparison.skipped, rows=len(frame),
                ran=engines_ran(frame), facts=records(run_facts(frame, comparison.arithmetic)),
                agreement=records(comparison.agreement), physics=records(checks),
                deviation=records(comparison.deviation), cross=cross,
                findings=records(comparison.findings), failures=comparison.failures, precision=records(precision),
                ratios=ratios, sliding=records(sliding), published=records(distances),
                attributions=[(name, records(table)) for name, table in comparison.attribution.items()],
                versions=records(comparison.versions) if not comparison.versions.empty else None,
                notes=[(engine, b["note"]) for engine, b in comparison.builds.items() if b.get("note")],
                inputs=comparison.engine_inputs, states=records(first_impacts(comparison.states), digits=6),
                more_states=0 if comparison.states is None else
                len(comparison.states) - len(first_impacts(comparison.states)))
