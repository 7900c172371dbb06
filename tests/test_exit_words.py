"""Bad input is exit 2 in one line naming what is wrong, never 'could not run' (3) or silence (issue 40.6)."""
import subprocess
import sys

import pytest

import harness
from harness.commands import main

SCENE = ["--model", "thornton"]


@pytest.mark.parametrize("args, words", [
    (["--engines", "lammps@@x"], "lammps@@x: a build is named by its version"),
    (["--engines", "liggghts@"], "liggghts@: a build is named by its version"),
    (["--engines", "reference@all"], "reference@all: the reference solver has no builds"),
    (["--tolerance", "velocity=1e-320"], "--tolerance velocity must lie in [1e-12, 1000)"),
    (["--tolerance", "coulomb=0"], "--tolerance coulomb must lie in [1e-12, 1000)"),
    (["--en", "0.5", "--en", "0.6"], "--en given more than once"),
    (["--en=0.5", "--en", "0.6"], "--en given more than once"),
    (["--mu", "0.3", "--mu=0.3"], "--mu given more than once"),
    (["--en", "0.5,0.25,0.5"], "0.5 given more than once"),
    (["--en", "0.5", "--angles", "10,20,10"], "10 given more than once"),
])
def test_bad_words_are_one_line_and_exit_2(args, words, tmp_path, capfd):
    angles = [] if "--angles" in args else ["--angles", "10"]
    assert main(["compare", *SCENE, *angles, "-o", str(tmp_path / "out"), *args]) == 2
    (line,) = capfd.readouterr().err.strip().splitlines()
    assert line.startswith("harness: error:") and words in line, line
    assert not (tmp_path / "out").exists()


def test_repeated_sweep_items_are_refused_from_python_and_in_a_campaign(tmp_path):
    with pytest.raises(ValueError, match="0.5 given more than once"):
        harness.compare("thornton", en=[0.5, 0.5], angles=[10])
    (tmp_path / "c.toml").write_text('laws = ["thornton"]\ne_n = [0.5]\nangles = [10.0, 20.0, 10.0]\n')
    assert main(["campaign", str(tmp_path / "c.toml"), "-o", str(tmp_path / "store"), "--dry-run"]) == 2


def test_a_closed_stdout_is_said_and_not_exit_0():
    """`harness cite >&-`: what it would print is lost, so it says so on stderr and exits 2."""
    done = subprocess.run(f"{sys.executable} -m harness cite >&-", shell=True, capture_output=True, text=True)
    assert done.returncode == 2 and "stdout is closed" in done.stderr


@pytest.mark.parametrize("keywords, words", [
    (dict(speed=10 ** 400), "speed is beyond the range of a double"),
    (dict(angles=[10.0], en=range(200_000)), "en holds 200000 numbers; at most 100000"),
])
def test_limits_from_python_are_one_clear_error(keywords, words):
    """issue 40.5: an integer beyond a double and a list beyond the limit are refused before any work (the list by
    its length, before it is copied)."""
    with pytest.raises(ValueError, match=words):
        harness.compare("thornton", **{"angles": [10.0], **keywords})


def test_a_query_that_is_not_utf8_is_one_line_and_exit_2(tmp_path):
    """issue 40.5: bytes of the command line that are not UTF-8 reach Python as surrogates; DuckDB took them for a
    TypeError traceback (exit 4)."""
    (tmp_path / "c.toml").write_text('laws = ["thornton"]\ne_n = [0.5]\nangles = [10.0]\n')
    assert main(["campaign", str(tmp_path / "c.toml"), "-o", str(tmp_path / "store"), "--quiet"]) == 0
    done = subprocess.run([sys.executable, "-m", "harness", "query", str(tmp_path / "store"), b"SELECT \xff\xfe"],
                          capture_output=True, text=True)
    assert done.returncode == 2 and done.stderr.strip().splitlines() == [
        "harness: error: the query is not UTF-8 text (character 8)"], done.stderr
