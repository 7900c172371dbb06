"""A scene's run as one HTML page (scene.html), from its files: the verdict of its closed-form checks, the checks'
table, and per case the bodies' heights and their mechanical energy against time, one colour per engine."""
import datetime
import os

from ..infra.files import write_text
from ..infra.render import environment
from ..infra.version import __version__
from .figure_files import filed
from .pieces import checks_headline, figure_svg, legend_below, records
from .style import colour

PAGE = "scene.html"


def engines_of(series):
    """The series' engine column, or the reference alone where it has none."""
    return series["engine"] if "engine" in series else ["reference"] * len(series)


def specific_energy(group, radius, g):
    """(v_x^2 + v_z^2)/2 + g z + R^2 w^2/5 summed over the bodies at each time: a solid sphere's kinetic, rotational
    and gravitational energy per unit mass [J/kg] (the contacts' elastic energy is not in it)."""
    each = 0.5 * (group.vx ** 2 + group.vz ** 2) + g * group.z + 0.2 * radius ** 2 * group.w ** 2
    return each.groupby(group.t, sort=True).sum()


def case_figure(series, case, radius, g):
    """Heights of every body's centre and the mechanical energy per unit mass against time, per engine."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    rows = series[series.case == case].assign(engine=list(engines_of(series[series.case == case])))
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(7, 5), sharex=True, constrained_layout=True)
    for engine, group in rows.groupby("engine", sort=False):
        for body, path in group.groupby("body", sort=True):
            top.plot(path.t, path.z, color=colour(engine), lw=1.2,
                     label=engine if body == group.body.min() else None)
        energy = specific_energy(group, radius, g)
        bottom.plot(energy.index, energy.to_numpy(), color=colour(engine), lw=1.2)
    top.set(ylabel="centre height z [m]", title=case)
    bottom.set(xlabel="t [s]", ylabel="kinetic + rotational + g z [J/kg]")
    for ax in (top, bottom):
        ax.grid(alpha=0.3)
    legend_below(fig)
    svg = figure_svg(fig)
    plt.close(fig)
    return svg


def write_scene_report(directory, run, command=""):
    """DIR/scene.html from a SceneRun (harness.studies.scenes; scene_files.load_scene reads one from the files);
    returns its path."""
    g = float(run.values.get("g", 0.0))
    figures = filed(directory, [(case, case_figure(run.series, case, run.radius, g), f"scene-{run.scene}-{case}")
                                for case in run.series.case.unique()])
    verdict = checks_headline(int(run.checks.passed.sum()), len(run.checks),
                              "No closed-form check applies to this law on this scene.")
    html = environment(autoescape=True).get_template("scene.html.j2").render(
        run=run, ok=bool(run.checks.passed.all()), headline=verdict, checks=records(run.checks, 9),
        values=sorted(run.values.items()), figures=figures, command=command, version=__version__,
        date=datetime.datetime.now().strftime("%Y-%m-%d %H:%M"))
    path = os.path.join(directory, PAGE)
    write_text(path, html)
    return path
