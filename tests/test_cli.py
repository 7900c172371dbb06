"""CLI contract: one clear line and exit code 2 on bad input, no output file; run/models/compare outputs."""
import json
import subprocess
import sys

import pandas as pd
import pytest

from conftest import needs
from harness.data.results import COLUMNS


def harness(*args, cwd=None, env=None):
    import os
    return subprocess.run([sys.executable, "-m", "harness", *args], capture_output=True, text=True, cwd=cwd,
                          timeout=600, env={**os.environ, **(env or {})})


@pytest.mark.parametrize("args", [
    ["--model", "no-such-law"],
    ["--model", "thornton", "--en", "1.5"],
    ["--model", "thornton", "--en", "0"],
    ["--model", "thornton", "--en", "nan"],
    ["--model", "thornton", "--radius", "-1"],
    ["--model", "thornton", "--nu", "0.5"],
    ["--model", "thornton", "--nu", "-1"],
    ["--model", "thornton", "--angles", "90"],
    ["--model", "thornton", "--angles", "-1"],
    ["--model", "thornton", "--angles", "10:5:1"],
    ["--model", "thornton", "--material", "unobtainium"],
    ["--model", "thornton", "--with", "tangential=magic"],
    ["--model", "thornton", "--with", "damping=tsuji"],
    ["--model", "thornton", "--psi", "1,2", "--mu", "0"],
    ["--model", "thornton", "--steps-per-contact", "2"],
    ["--model", "thornton", "--steps-per-contact", "0"],
    ["--model", "thornton", "--dt", "0"],
    ["--model", "thornton", "--dt", "1e-3"],
    ["--model", "thornton", "--dt", "1e-7", "--converged"],
    ["--model", "thornton", "--speed", "abc"],
    ["--model", "thornton", "--angles", "10", "--psi", "1"],
    ["--model", "thornton", "--vt", "0.5,-1"],
    ["--model", "thornton", "--wall", "jelly"],
])
def test_bad_input_is_one_line_and_exit_2(tmp_path, capfd, args):
    """In this process (the catalogue in tests/test_bad_input.py has many more); the process-level contract, exit
    status and stderr of `python -m harness`, is the next test's."""
    from harness.commands import main
    out = tmp_path / "r.csv"
    code = main(["run", *args, "-o", str(out)])
    err = capfd.readouterr().err
    assert code == 2, err
    assert len(err.strip().splitlines()) == 1 and err.startswith("harness: error:")
    assert "Traceback" not in err
    assert not out.exists() and list(tmp_path.iterdir()) == []


def test_bad_input_is_one_line_and_exit_2_from_the_command_line(tmp_path):
    out = tmp_path / "r.csv"
    proc = harness("run", "--model", "thornton", "--en", "1.5", "-o", str(out))
    assert proc.returncode == 2, proc.stderr
    assert len(proc.stderr.strip().splitlines()) == 1 and proc.stderr.startswith("harness: error: e_n must lie")
    assert "Traceback" not in proc.stderr and list(tmp_path.iterdir()) == []


def test_unwritable_output_is_exit_2(tmp_path):
    proc = harness("run", "--model", "thornton", "-o", str(tmp_path / "missing" / "r.csv"))
    assert proc.returncode == 2 and len(proc.stderr.strip().splitlines()) == 1


def run_table(tmp_path, *args):
    """`harness run ARGS -o r.csv`, which must succeed; the table it wrote."""
    out = tmp_path / "r.csv"
    proc = harness("run", *args, "-o", str(out))
    assert proc.returncode == 0, proc.stderr
    return pd.read_csv(out)


def test_dt_gives_one_time_step_to_every_e_n(tmp_path):
    """--dt: the same time step at every e_n; steps per contact follow from each contact time."""
    frame = run_table(tmp_path, "--model", "walton-braun", "--en", "0.9,0.3", "--angles", "0,45", "--dt", "2e-7")
    assert set(frame.dt) == {2e-7}
    assert (frame.steps_per_contact * frame.dt).round(12).nunique() == 2     # = each e_n's contact-time estimate


def test_run_writes_the_results_table(tmp_path):
    frame = run_table(tmp_path, "--model", "hertz-mindlin", "--en", "0.9,0.3", "--angles", "0:60:30", "--mu", "0.2")
    assert tuple(frame.columns) == COLUMNS
    assert len(frame) == 6 and set(frame.e_n_target) == {0.9, 0.3} and set(frame.mu) == {0.2}
    assert sorted(set(frame.theta_deg)) == [0.0, 30.0, 60.0]
    assert (frame.status == "ok").all()


@pytest.mark.parametrize("sweep,expected_vt", [(["--psi", "1,4"], None), (["--vt", "0.2,0.6"], [0.2, 0.6])])
def test_run_with_normal_speed_sweeps(tmp_path, sweep, expected_vt):
    out = tmp_path / "r.csv"
    proc = harness("run", "--model", "thornton", "--en", "0.5", "--speed", "2", *sweep, "-o", str(out))
    assert proc.returncode == 0, proc.stderr
    frame = pd.read_csv(out)
    assert len(frame) == 2 and (frame.v_n0 == 2.0).all()
    if expected_vt:
        assert list(frame.v_t0) == expected_vt
    else:
        assert frame.psi1_star.to_list() == pytest.approx([1.0, 4.0], rel=1e-4)   # e_n achieved ~ target


def test_wall_material_changes_the_contact(tmp_path):
    same, steel = tmp_path / "same.csv", tmp_path / "steel.csv"
    for out, wall in ((same, "same"), (steel, "steel")):
        assert harness("run", "--model", "walton-braun", "--en", "0.5", "--angles", "0", "--wall", wall,
                       "-o", str(out)).returncode == 0
    assert pd.read_csv(steel).t_contact[0] < pd.read_csv(same).t_contact[0]      # a stiffer wall, a shorter contact


def test_models_json_lists_every_law():
    from harness.laws import LAWS
    proc = harness("models", "--json")
    assert proc.returncode == 0
    models = json.loads(proc.stdout)
    assert [m["name"] for m in models] == list(LAWS)
    assert all("normal" in m["submodels"] for m in models)


def test_compare_without_engines_runs_the_reference_and_names_what_it_skipped(tmp_path):
    proc = harness("compare", "--model", "hertz-mindlin", "--en", "0.5", "--angles", "0:80:20", "-o",
                   str(tmp_path / "out"), env={"HARNESS_LIGGGHTS": str(tmp_path / "no-such-liggghts"),
                                               "HARNESS_YADE_PYTHON": str(tmp_path / "no-such-python"),
                                               "HARNESS_LAMMPS": str(tmp_path / "no-such-lmp")})
    assert proc.returncode == 3, proc.stderr                # nothing was compared
    assert (tmp_path / "out" / "results.csv").exists()
    html = (tmp_path / "out" / "report.html").read_text()
    assert "hertz-mindlin" in html and "<figure><svg" in html and "Nothing compared" in html
    assert f"skipped liggghts: HARNESS_LIGGGHTS={str(tmp_path / 'no-such-liggghts')!r} is not an executable file" \
        in proc.stdout                                      # what was looked for, and where
    assert f"skipped yade: no Python interpreter at HARNESS_YADE_PYTHON={str(tmp_path / 'no-such-python')!r}" \
        in proc.stdout
    assert f"skipped lammps: HARNESS_LAMMPS={str(tmp_path / 'no-such-lmp')!r} is not an executable file" in proc.stdout
    assert proc.stdout.splitlines()[-1] == "agreement: not checked: no engine ran"


@needs("liggghts")
@needs("yade")
def test_compare_skips_engines_for_scenes_their_inputs_cannot_express(tmp_path):
    """LIGGGHTS' thornton_ning and YADE's Luding run against the sphere's own material only: named, each is skipped
    with that reason and nothing is compared (exit 3)."""
    for model, engine in (("thornton", "liggghts"), ("walton-braun", "yade")):
        proc = harness("compare", "--model", model, "--engines", engine, "--en", "0.5", "--angles", "0", "--wall",
                       "rigid", "-o", str(tmp_path / engine))
        assert proc.returncode == 3                          # nothing compared
        assert f"skipped {engine}: its {model} inputs use a wall of the sphere's own material" in proc.stdout


def test_engines_reference_alone_runs_the_paper_law_only(tmp_path):
    """`--engines reference` is valid wherever --engines is: the paper law alone, nothing skipped, exit 0."""
    proc = harness("compare", "--model", "thornton", "--engines", "reference", "--en", "0.5", "--angles", "0,40",
                   "-o", str(tmp_path / "out"))
    assert proc.returncode == 0, proc.stderr
    frame = pd.read_csv(tmp_path / "out" / "results.csv")
    assert set(zip(frame.engine, frame.dialect)) == {("reference", "paper")} and len(frame) == 2
    assert "skipped" not in proc.stdout
