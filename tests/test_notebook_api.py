"""A notebook's session with the Python API: run, compare (with a real engine), cost and campaign from Python, the
units of the columns read from harness.columns, a report and a figure written, short reprs, and a wrong type
refused as a TypeError naming the argument, for every public function."""
import importlib
import inspect
import math
import subprocess
import sys

import pytest

import harness
from harness.infra.errors import UserError, UserTypeError

from conftest import needs

SCENE = dict(en=[0.5], angles=[10.0, 40.0])


def test_import_harness_stays_cheap_and_lists_the_api():
    """`import harness` loads neither numba nor pandas, yet dir() (tab completion) and __all__ name every command."""
    code = ("import sys, harness; names = dir(harness); "
            "print(sorted(m for m in ('numba', 'pandas') if m in sys.modules)); print(names)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    loaded, names = out.splitlines()
    assert loaded == "[]"
    for name in ("run", "compare", "calibrate", "cost", "paper", "benchmark", "campaign", "columns", "plot"):
        assert name in harness.__all__ and repr(name) in names
    importlib.import_module("harness.studies.campaign.spec")     # the modules named as commands, imported
    importlib.import_module("harness.studies.paper")
    assert callable(harness.campaign) and callable(harness.paper) and inspect.isfunction(harness.paper)


@pytest.mark.parametrize("name", ["run", "compare", "calibrate", "cost", "paper", "benchmark", "campaign", "plot"])
def test_every_function_has_an_explicit_signature_and_a_docstring(name):
    function = getattr(harness, name)
    parameters = inspect.signature(function).parameters
    assert not [p for p in parameters.values() if p.kind in (p.VAR_KEYWORD, p.VAR_POSITIONAL)]
    assert function.__doc__ and len(function.__doc__) > 80
    if name in ("run", "compare", "calibrate", "cost"):
        assert {"model", "en", "angles", "mu", "speed", "with_"} <= set(parameters)
        assert ("steps_per_contact" in parameters) == (name != "cost")


def test_the_columns_carry_units_and_the_docs_show_the_same_table():
    """harness.columns covers exactly the results table's columns; docs/results.md holds the table generated from
    it (harness.data.descriptions.markdown)."""
    import pathlib
    from harness.data.descriptions import markdown
    from harness.data.results import COLUMNS
    columns = harness.columns
    assert list(columns.index) == list(COLUMNS)
    assert columns.loc["v_n1", "unit"] == "m/s" and columns.loc["theta_deg", "unit"] == "deg"
    assert columns.loc["omega1", "unit"] == "rad/s" and columns.loc["f_n_max", "unit"] == "N"
    assert columns.loc["e_n", "unit"] == "" and columns.description.str.len().min() > 3
    docs = (pathlib.Path(__file__).parents[1] / "docs" / "results.md").read_text()
    assert markdown() in docs, "docs/results.md's Units table differs from harness/data/descriptions.py:\n" + markdown()


def test_run_reads_units_and_draws_a_figure(tmp_path):
    frame = harness.run("hertz-mindlin", steps_per_contact=500, **SCENE)
    unit = harness.columns.loc["v_t1", "unit"]
    assert unit == "m/s" and (frame.status == "ok").all()
    # e_t is v_t1 / v_t0 (docs/results.md): the table's own columns, read with their units, say the same
    assert frame.e_t.to_numpy() == pytest.approx((frame.v_t1 / frame.v_t0).to_numpy())
    figure = harness.plot(frame, "e_t")
    figure.savefig(tmp_path / "e_t.svg")
    assert (tmp_path / "e_t.svg").read_text().startswith("<?xml")
    assert figure.axes[0].get_xlabel() == "impact angle Psi1*"
    other = harness.plot(frame, "ke_ratio")
    assert other.axes[0].get_xlabel() == "theta_deg [deg]" and other.axes[0].get_ylabel() == "ke_ratio"


@needs("liggghts")
def test_compare_with_an_engine_reports_and_plots(tmp_path):
    comparison = harness.compare("hertz-mindlin", engines=["liggghts"], steps_per_contact=500, **SCENE)
    assert comparison.engines == ["liggghts"] and comparison.ok is True
    text = repr(comparison)
    assert len(text) < 400 and text.count("\n") <= 4 and "liggghts" in text and "ok True" in text
    page = comparison._repr_html_()
    assert "<b>ok</b>" in page and "<table" in page and "liggghts" in page and len(page) < 4000
    report = comparison.report(tmp_path / "out")
    assert report.endswith("report.html") and (tmp_path / "out" / "results.csv").is_file()
    html = (tmp_path / "out" / "report.html").read_text()
    assert "liggghts" in html and "hertz-mindlin" in html
    figure = comparison.plot("psi2_star")
    names = {line.get_label() for line in figure.axes[0].get_lines()}
    assert any("liggghts" in name for name in names) and "paper law" in names
    figure.savefig(tmp_path / "psi2.png")
    assert (tmp_path / "psi2.png").stat().st_size > 1000


def test_compare_is_not_ok_when_its_only_engine_was_skipped():
    comparison = harness.compare("hertz-mindlin", engines=["liggghts"], **SCENE)
    assert comparison.skipped and comparison.ok is False
    assert "<b>not ok</b>" in comparison._repr_html_() and "liggghts skipped" in repr(comparison)


def test_cost_of_a_small_ladder(tmp_path):
    """The reference's error falls as the ladder refines (a first-order scheme at least), and the report exists."""
    study = harness.cost("hertz-mindlin", engines=["reference"], ladder=[20, 200], en=[0.5], angles=[30.0])
    assert study.ok and len(repr(study)) < 400
    paper = study.table[(study.table.engine == "reference") & (study.table.dialect == "paper")
                        & study.table.steps_per_contact.isin([20, 200])].sort_values("steps_per_contact")
    coarse, fine = paper.err_max.to_numpy()
    assert fine < coarse / 5 and math.isfinite(fine)
    assert "<table" in study._repr_html_()
    assert study.report(tmp_path / "cost").endswith("report.html")
    assert (tmp_path / "cost" / "cost.csv").is_file()


def test_a_tiny_campaign_in_process(tmp_path):
    """Two e_n x two angles on the reference: its table holds the 4 impacts; a rerun takes them from the store."""
    spec = {"name": "tiny", "laws": ["hertz-mindlin"], "engines": ["reference"], "e_n": [0.5, 0.9],
            "angles": [10, 40], "steps_per_contact": [200]}
    first = harness.campaign(spec, tmp_path / "store")
    assert first.ok and first.summary.ran == first.summary.tasks > 0
    table = first.table
    assert len(table) == 4 and set(table.e_n_target) == {0.5, 0.9}
    again = harness.campaign(spec, str(tmp_path / "store"))
    assert again.summary.ran == 0 and again.summary.cached == again.summary.tasks
    assert first.report().endswith("store.html") and len(repr(first)) < 400


WRONG = [   # (function, arguments, the argument the message must name)
    ("run", ("hertz-mindlin",), dict(en=0.5), "en"),
    ("run", ("hertz-mindlin",), dict(bogus=1), "bogus"),
    ("compare", ("hertz-mindlin",), dict(engines="liggghts"), "engines"),
    ("compare", ("hertz-mindlin",), dict(tolerances="velocity=0.1"), "tolerances"),
    ("calibrate", ("hertz-mindlin", ["lammps"]), {}, "engine"),
    ("calibrate", ("hertz-mindlin", "lammps"), dict(timestep_tolerance="0.01"), "timestep_tolerance"),
    ("cost", ("hertz-mindlin",), dict(ladder="10,100"), "ladder"),
    ("cost", ("hertz-mindlin",), dict(ladder=[10.0, 100.0]), "ladder"),
    ("cost", ("hertz-mindlin",), dict(steps_per_contact=100), "steps_per_contact"),
    ("paper", (), dict(laws="thornton"), "laws"),
    ("paper", (), dict(steps_per_contact="2000"), "steps_per_contact"),
    ("benchmark", (), dict(suite=3), "suite"),
    ("benchmark", (), dict(engines="reference"), "engines"),
    ("campaign", (["laws"], "store"), {}, "spec"),
    ("campaign", ({"laws": ["thornton"]}, 3), {}, "store"),
    ("plot", ([1, 2], "e_t"), {}, "frame"),
]


@pytest.mark.parametrize("name, args, keywords, argument", WRONG, ids=[f"{w[0]}-{w[3]}" for w in WRONG])
def test_a_wrong_type_is_a_type_error_naming_the_argument(name, args, keywords, argument):
    with pytest.raises(UserTypeError) as raised:
        getattr(harness, name)(*args, **keywords)
    assert argument in str(raised.value) and "\n" not in str(raised.value)


BAD_VALUES = [
    ("cost", ("hertz-mindlin",), dict(ladder=[100, 10]), "--ladder"),
    ("paper", (), dict(laws=["nonsense"]), "nonsense"),
    ("paper", (), dict(steps_per_contact=10), "steps-per-contact"),
    ("benchmark", (), dict(suite="other"), "suite"),
    ("benchmark", (), dict(engines=["nonsense"]), "nonsense"),
    ("benchmark", (), dict(engines=[]), "unknown engine(s) []"), ("paper", (), dict(laws=[]), "unknown law(s) []"),
]


@pytest.mark.parametrize("name, args, keywords, shown", BAD_VALUES, ids=[f"{b[0]}-{b[3]}" for b in BAD_VALUES])
def test_a_bad_value_is_a_value_error(name, args, keywords, shown):
    with pytest.raises(UserError) as raised:
        getattr(harness, name)(*args, **keywords)
    assert not isinstance(raised.value, TypeError) and shown in str(raised.value)


def test_plot_refuses_a_column_the_table_lacks():
    frame = harness.run("hertz-mindlin", steps_per_contact=200, **SCENE)
    with pytest.raises(ValueError, match="y must be a column"):
        harness.plot(frame, "no_such_column")
    with pytest.raises(ValueError, match="psi1_star"):
        harness.plot(frame, "ke_ratio", x="psi1_star")


@needs("liggghts")
@needs("lammps")
def test_the_user_guide_python_example_runs_as_shown(tmp_path, monkeypatch):
    """Every Python block of docs/user-guide.md's "Python" section, run as shown (in a scratch directory), writes
    what it says it writes."""
    import pathlib
    import re
    guide = (pathlib.Path(__file__).parents[1] / "docs" / "user-guide.md").read_text()
    section = guide[guide.index("## Python\n"):]
    section = section[:section.index("\n## ", 1)] if "\n## " in section[1:] else section
    blocks = re.findall(r"```python\n(.*?)```", section, re.S)
    assert blocks
    monkeypatch.chdir(tmp_path)
    for block in blocks:
        exec(compile(block, "docs/user-guide.md", "exec"), {})
    assert (tmp_path / "compare-out" / "report.html").is_file() and (tmp_path / "psi2_star.pdf").is_file()
    assert (tmp_path / "campaign-store").is_dir()
