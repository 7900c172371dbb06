"""What compare prints and the exit code it ends with: a short summary by default, --quiet one line, --json one
document, the verdict 0/1/3, an internal error 4 (never 1, the code of a disagreement)."""
import json

import numpy as np
import pandas as pd
import pytest
from conftest import needs

from harness.commands import main
from harness.engines import ENGINES, EXTERNAL
from harness.engines import liggghts

needs_liggghts = needs("liggghts")
SMALL = ["--en", "0.5", "--angles", "10,40"]


@needs_liggghts
def test_json_is_one_document_whose_numbers_follow_from_results_csv(tmp_path, capsys):
    code = main(["compare", "--model", "hertz-mindlin", "--engines", "liggghts", *SMALL, "-o", str(tmp_path),
                 "--json"])
    record = json.loads(capsys.readouterr().out)                 # nothing else on stdout
    assert code == record["exit_code"] == 0 and record["verdict"] == "agree"
    results = pd.read_csv(tmp_path / "results.csv")
    (engine,) = record["engines"]
    assert engine["engine"] == "liggghts" and engine["version"] == str(results[results.engine == "liggghts"]
                                                                        .engine_version.iloc[0])
    ours = results[results.engine == "liggghts"].set_index("theta_deg")
    paper = results[results.dialect == "paper"].set_index("theta_deg")
    speed = np.hypot(paper.v_n0, paper.v_t0)
    for d in engine["deviation"]:                                 # recomputed here from the table
        diff = (ours[d["metric"]] - paper[d["metric"]]) / speed * (paper.radius if d["metric"] == "omega1" else 1)
        assert d["relative"] == pytest.approx(diff.loc[diff.abs().idxmax()], rel=1e-12)
        assert d["theta_deg"] == diff.abs().idxmax()


@needs_liggghts
def test_quiet_prints_the_verdict_line_alone(tmp_path, capsys):
    code = main(["compare", "--model", "hertz-mindlin", "--engines", "liggghts", *SMALL, "-o", str(tmp_path),
                 "--quiet"])
    out = capsys.readouterr().out
    assert code == 0 and out.endswith("; agreement: ok for liggghts\n") and out.startswith("paper law: ")
    assert out.count("\n") == 1


@needs_liggghts
def test_summary_is_short_and_verbose_has_every_table(tmp_path, capsys, monkeypatch):
    monkeypatch.setenv("COLUMNS", "120")        # a terminal 120 wide (pytest-xdist's workers say 80)
    store = ["--store", str(tmp_path / "runs")]          # the verbose compare reads the first one's runs
    main(["compare", "--model", "hertz-mindlin", *SMALL, *store, "-o", str(tmp_path / "a")])
    short = capsys.readouterr().out.splitlines()
    main(["compare", "--model", "hertz-mindlin", *SMALL, *store, "-o", str(tmp_path / "b"), "--verbose"])
    verbose = capsys.readouterr().out
    engines = sum(ENGINES[name].available() for name in EXTERNAL)
    # per engine: its physics line with each failed check's causes, its agreement and its three deviations
    assert len(short) <= 10 + 8 * engines and all(len(line) <= 120 for line in short if str(tmp_path) not in line)
    assert short[-1].startswith("paper law: ") and "agreement: ok for" in short[-1]
    assert "attribution (liggghts dialect -> paper" in verbose and "attribution" not in "\n".join(short)


@needs_liggghts
def test_an_engine_that_disagrees_with_its_formulas_exits_1(tmp_path, capsys, monkeypatch):
    """The real LIGGGHTS against formulas made wrong on purpose (its hertz dialect with YADE's lever arm)."""
    monkeypatch.setitem(liggghts.DIALECTS, "hertz-mindlin", {**liggghts.DIALECTS["hertz-mindlin"], "lever": "1"})
    code = main(["compare", "--model", "hertz-mindlin", "--engines", "liggghts", *SMALL, "-o", str(tmp_path)])
    last = capsys.readouterr().out.splitlines()[-1]
    assert code == 1 and "agreement: FAILED for liggghts (worst " in last


def test_an_internal_error_exits_4_with_its_traceback(tmp_path, capsys, monkeypatch):
    import harness.api.requests as api            # `harness run` imports run_request from it when it runs

    def broken(request, **keywords):
        raise ZeroDivisionError("a bug")
    monkeypatch.setattr(api, "run_request", broken)
    code = main(["run", "--model", "thornton", *SMALL, "-o", str(tmp_path / "r.csv")])
    err = capsys.readouterr().err
    assert code == 4 and "ZeroDivisionError: a bug" in err and "internal error" in err.splitlines()[-1]
