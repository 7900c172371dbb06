"""A fourth engine added as its author would add it: a subclass of the Engine base class in its own package
(tests/standin, a stand-in that declares itself as one), registered for each test alone (the registry's one
entry); every command that runs engines runs it. Its agreement with its own dialect is exact (it runs that dialect in
the reference's kernel), so any difference
is the harness' plumbing."""
import pandas as pd
import pytest
from standin import ENGINE, StandIn

from harness.commands import main
from harness.engines import ENGINES
from harness.engines.base import Engine

SCENE = ["--en", "0.5", "--angles", "10,40"]


@pytest.fixture
def registered(monkeypatch):
    monkeypatch.setitem(ENGINES, ENGINE.NAME, ENGINE)      # the one registry line


def test_it_overrides_only_what_differs_from_the_base_class():
    own = {name: value for name, value in vars(StandIn).items() if not name.startswith("__")}
    assert own and all(getattr(Engine, name, None) != value for name, value in own.items()), own


def test_compare_runs_it_and_it_agrees_with_its_dialect(registered, tmp_path):
    assert main(["compare", "--model", "hertz-mindlin", "--engines", "stand-in", *SCENE, "-o", str(tmp_path)]) == 0
    results = pd.read_csv(tmp_path / "results.csv")
    mine = results[results.engine == "stand-in"].reset_index(drop=True)
    dialect = results[(results.engine == "reference") & (results.dialect == "stand-in")].reset_index(drop=True)
    assert len(mine) == len(dialect) == 2 and (mine.status == "ok").all()
    for column in ("v_n1", "v_t1", "omega1"):
        assert (mine[column] == dialect[column]).all(), column


def test_a_with_it_cannot_follow_is_refused_for_it(registered, tmp_path, capsys):
    assert main(["compare", "--model", "hertz-mindlin", "--engines", "stand-in", *SCENE, "--with",
                 "end=tension", "-o", str(tmp_path)]) == 2
    assert "stand-in cannot follow --with end=tension" in capsys.readouterr().err


def test_cost_runs_it(registered, tmp_path, monkeypatch):
    """Its runs report no wall time (they run as they are read), so its time per impact-step is never resolved: the
    timing rounds grow to their caps, here lowered so that they end in seconds (at 2^16 steps and 4096 impacts they
    took minutes)."""
    import harness.studies.cost_plan
    monkeypatch.setattr(harness.studies.cost_plan, "MAX_TIMING_STEPS", 2 ** 10)
    monkeypatch.setattr(harness.studies.cost_plan, "MAX_TIMING_IMPACTS", 512)
    assert main(["cost", "--model", "hertz-mindlin", "--engines", "stand-in", "--en", "0.5", "--angles", "30",
                 "--ladder", "50,100", "-o", str(tmp_path)]) == 0
    table = pd.read_csv(tmp_path / "cost.csv", dtype={"rung": str})
    assert set(table[table.engine == "stand-in"].status) == {"ok"}
    timing = table[(table.engine == "stand-in") & (table.rung == "per impact-step")]
    assert list(timing.timing) == ["not resolved"] and timing.impacts.iloc[0] == 512, timing.to_dict("records")


def test_the_chung_ooi_benchmark_runs_it(registered, tmp_path):
    code = main(["benchmark", "chung-ooi", "--engines", "reference,stand-in", "-o", str(tmp_path)])
    table = pd.read_csv(tmp_path / "chung-ooi.csv")
    mine = table[table.engine == "stand-in"]
    checked = mine[mine.passed.notna()]
    assert code in (0, 1) and len(checked) > 0 and not mine.quantity.isin(["not run", "failed"]).any()


def test_a_campaign_runs_it(registered, tmp_path, capsys):
    path = tmp_path / "c.toml"
    path.write_text('name = "stand-in"\nlaws = ["hertz-mindlin"]\nengines = ["reference", "stand-in"]\n'
                    'e_n = [0.5]\nangles = [10, 40]\nsteps_per_contact = [200]\n')
    assert main(["campaign", str(path), "-o", str(tmp_path / "store")]) == 0
    assert "stand-in" in capsys.readouterr().out
    assert main(["campaign", str(path), "-o", str(tmp_path / "store"), "--dry-run"]) == 0


def test_its_stored_runs_are_keyed_on_its_own_source(registered, tmp_path):
    """A store key carries a digest of the engine's source: the stand-in's is its own package's, not an empty one
    (sha256 of no bytes), and it changes when a file of that package changes."""
    import hashlib
    import shutil

    import standin
    from harness.infra.sources import source_digest
    folder = tmp_path / "standin"
    shutil.copytree(standin.__path__[0], folder)
    empty = hashlib.sha256(b"").hexdigest()[:12]
    assert ENGINE.sources() == (standin.__path__[0],)
    before = source_digest(str(folder))
    (folder / "__init__.py").write_text((folder / "__init__.py").read_text() + "\n# changed\n")
    assert empty != before != source_digest(str(folder))


def cells(line, header):
    """A verdict row as {column: cell}: the table's columns are set apart by two spaces or more."""
    import re
    return dict(zip(re.split(r"\s{2,}", header.strip()), re.split(r"\s{2,}", line.strip())))


def test_cost_says_how_long_before_it_starts_and_gives_each_tolerance_a_number_or_a_reason(registered, tmp_path,
                                                                                           monkeypatch, capsys):
    """One line on stderr before the study starts, naming each engine's share; then the stand-in's row: its
    converged reference's uncertainty (cost-truth.csv's largest), and for 1% and 0.1% a number, with a sentence
    saying how it was found unless it was measured on its own ladder, or '-' and the reason."""
    import harness.commands.cost as command
    import harness.studies.cost_plan
    monkeypatch.setattr(harness.studies.cost_plan, "MAX_TIMING_ROUNDS", 1)    # its time is never resolved: one round
    said_before = []
    study = command.cost_table
    def started(*args, **kwargs):
        said_before.append(capsys.readouterr().err)
        return study(*args, **kwargs)
    monkeypatch.setattr(command, "cost_table", started)
    assert main(["cost", "--model", "hertz-mindlin", "--engines", "stand-in", "--en", "0.5", "--angles", "10,40",
                 "--ladder", "10,20", "-o", str(tmp_path)]) == 0
    estimate = [line for line in said_before[0].splitlines() if line.startswith("harness: cost hertz-mindlin: about")]
    assert len(estimate) == 1 and "stand-in" in estimate[0] and " min" in estimate[0], said_before
    out = capsys.readouterr().out.splitlines()
    header = next(line for line in out if "1%: steps" in line)
    row = cells(next(line for line in out if line.strip().startswith("stand-in")), header)
    truth = pd.read_csv(tmp_path / "cost-truth.csv")
    assert float(row["truth +-"]) == pytest.approx(truth[truth.curve == "stand-in"].err_max.max(), rel=0.06)
    for tolerance, column in (("1%", "1%: steps"), ("0.1%", "0.1%: steps")):
        cell = row[column]
        told = [line for line in out if line.strip().startswith("stand-in ") and f" {tolerance}" in line.split(":")[0]]
        if cell.isdigit():
            continue                            # measured on its own ladder
        assert told, (tolerance, cell, out)     # a number marked f, ~ or <=, or '-': said why
        assert cell == "-" or cell.rstrip("f").lstrip("~<=").isdigit(), cell
