"""The Chung & Ooi benchmark as one HTML page, from the suite's table (harness.studies.verification.chung_ooi)."""
import datetime
import os

from ..infra.files import write_text
from ..infra.render import environment
from ..studies.verification import chung_ooi as suite
from ..studies.verification.chung_ooi_cases import TESTS
from ..infra.version import __version__
from .figure_files import one
from .pieces import checks_headline, figure_svg, legend_below, records
from .style import colour

CSV, PAGE = "chung-ooi.csv", "chung-ooi.html"


def summary(table):
    """Per engine: checks passed and failed of checks made, and the cases it could not run."""
    rows = []
    for engine, group in table.groupby("engine", sort=False):
        checked = group[group.passed.notna()]
        not_run = group[group.quantity.isin(["not run", "failed"])]
        reasons = sorted(set(not_run.note))
        passed = int((checked.passed == True).sum())     # noqa: E712
        rows.append({"engine": engine, "passed": passed, "failed": len(checked) - passed, "checked": len(checked),
                     "not run": len(not_run), "why not": "; ".join(reasons)})
    import pandas as pd
    return pd.DataFrame(rows)


def sliding_figure(table, test):
    """Tests 4-5: the rebound tangential velocity of the centre against the impact angle per engine and material,
    the gross-sliding line dashed where it applies."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    rows = table[(table.test == test) & (table.quantity == "v_t1 [m/s]")]
    if rows.empty:
        return None
    fig, ax = plt.subplots(figsize=(7, 4), constrained_layout=True)
    for (engine, material), group in rows.groupby([rows.engine, rows.case.str.split(",").str[0]], sort=False):
        angle = group.case.str.extract(r"theta ([0-9.]+)")[0].astype(float)
        ax.plot(angle, group.value, marker="o", ms=3, color=colour(engine),
                ls="-" if material == rows.case.iloc[0].split(",")[0] else ":", label=f"{engine}, {material}")
        ax.plot(angle, group.expected, color="0.5", ls="--", lw=0.8)
    ax.set(xlabel="impact angle from the normal [deg]", ylabel="rebound tangential velocity [m/s]",
           title="gross sliding: simulated (markers) and rigid-body line (dashed)")
    ax.grid(alpha=0.3)
    legend_below(fig)
    svg = figure_svg(fig)
    plt.close(fig)
    return svg


def write_chung_ooi_report(out_dir, table, command):
    """DIR/chung-ooi.html from the suite's table; returns its path."""
    ok, passed, checked = suite.verdict(table)
    tests = []
    for number, (title, scene, expected) in TESTS.items():
        rows = table[table.test == number].drop(columns="test")
        curves = suite.curve_errors(table[table.test == number]).drop(columns="test")
        tests.append({"number": number, "title": title, "scene": scene, "expected": expected,
                      "rows": records(rows) or ([], []), "open": len(rows) <= 12, "curves": records(curves),
                      "figure": one(out_dir, title, sliding_figure(table, number),
                                    f"chung-ooi-test-{number}-v_t-vs-angle") if number in (4, 5) else None})
    html = environment(autoescape=True).get_template("chung-ooi.html.j2").render(
        ok=ok, passed=passed, checked=checked, summary=records(summary(table)), tests=tests, command=command,
        version=__version__, date=datetime.datetime.now().strftime("%Y-%m-%d %H:%M"), csv=CSV, law=suite.LAW,
        headline=checks_headline(passed, checked), tolerances={"hertz": f"{suite.HERTZ_TOLERANCE:g}",
                                                   "restitution": f"{suite.RESTITUTION_TOLERANCE:g}",
                                                   "sliding": f"{suite.SLIDING_TOLERANCE:g}",
                                                   "psi": f"{suite.GROSS_SLIDING_PSI:g}"})
    return write_text(os.path.join(out_dir, PAGE), html)
