"""The campaign file's entrance: every wrong type anywhere in the TOML, an unknown key or engine, nesting, size,
work beyond the stated limits and files that are not regular files are each refused in one line with exit 2,
without a traceback and without writing anything; numbers given as TOML integers are the same runs as floats."""
import os
import subprocess
import sys
import time

import pytest

from harness.studies.campaign.driver import keyed
from harness.studies.campaign.limits import MAX_TASKS
from harness.studies.campaign.spec import from_dict
from harness.commands import main

LAW = 'laws = ["thornton"]\n'
# (file text, words the one line must hold)
BAD_FILES = [
    ("laws = [", "not valid TOML"),
    ("lawz = ['thornton']", "lawz is an unknown key"),
    ("laws = ['nope']", "unknown law"),
    ("e_n = [0.5]", "give laws"),
    (LAW + "angles = [10]\npsi = [1]", "one of angles"),
    (LAW + "e_n = [2]", "e_n must lie"),
    (LAW + 'e_n = ["0.5"]', "e_n[0] is a string"),
    (LAW + "e_n = {a = 1}", "e_n is a table"),
    (LAW + "e_n = [[0.5]]", "e_n[0] is an array"),
    (LAW + "e_n = []", "e_n is empty"),
    (LAW + "e_n = 0.5", "e_n is a float"),
    (LAW + "e_n = [inf]", "finite"),
    (LAW + "e_n = [nan]", "finite"),
    (LAW + "e_n = [1979-05-27]", "e_n[0] is a date"),
    (LAW + "angles = 10", "angles is an integer"),
    (LAW + "angles = [10, true]", "angles[1] is a boolean"),
    (LAW + 'psi = ["x"]', "psi[0] is a string"),
    (LAW + "vt = {}", "vt is a table"),
    (LAW + "speeds = [true]", "speeds[0] is a boolean"),
    (LAW + "normal_speeds = 1", "normal_speeds is an integer"),
    (LAW + 'spins = ["a"]', "spins[0] is a string"),
    (LAW + 'dt = ["a"]', "dt[0] is a string"),
    (LAW + "steps_per_contact = [1.5]", "steps_per_contact[0] is a float"),
    (LAW + 'steps_per_contact = ["a"]', "steps_per_contact[0] is a string"),
    (LAW + "steps_per_contact = [0]", "whole number >= 1"),
    (LAW + "steps_per_contact = 1000", "steps_per_contact is an integer"),
    (LAW + 'block = "a"', "block is a string"),
    (LAW + "block = 1.5", "block is a float"),
    (LAW + "block = 0", "whole number >= 1"),
    (LAW + 'converged = "yes"', "converged is a string"),
    (LAW + "name = 1", "name is an integer"),
    ('laws = "thornton"', "laws is a string"),
    ("laws = [1]", "laws[0] is an integer"),
    ("laws = [['thornton']]", "laws[0] is an array"),
    (LAW + 'engines = ["nope"]', "engines[0] is a string ('nope'); expected one of reference"),
    (LAW + 'engines = "reference"', "engines is a string"),
    (LAW + "engines = []", "engines is empty"),
    (LAW + "materials = [1]", "materials[0] is an integer"),
    (LAW + "materials = 'tcc13'", "materials is a string"),
    (LAW + 'materials = [{radius = "x"}]', "materials[0].radius is a string"),
    (LAW + "materials = [{foo = 1}]", "materials[0].foo is an unknown key"),
    (LAW + "materials = ['nope']", "unknown material"),
    (LAW + "variants = 1", "variants is an integer"),
    (LAW + "variants = [1]", "variants[0] is an integer"),
    (LAW + "[[variants]]\nwith = {tangential = 'mindlin:incremental'}", "variants[0] has no law"),
    (LAW + "[[variants]]\nlaw = 'thornton'\nwith = 1", "variants[0].with is an integer"),
    (LAW + "[[variants]]\nlaw = 'thornton'\nwith = {tangential = 1}", "variants[0].with.tangential is an integer"),
    (LAW + "engine_options = 1", "engine_options is an integer"),
    (LAW + "engine_options = {nope = {a = 'b'}}", "engine_options.nope is a string"),
    (LAW + "engine_options = {yade = 1}", "engine_options.yade is an integer"),
    (LAW + 'engines = ["yade"]\nengine_options = {yade = {precision = 1}}', "engine_options.yade.precision is an"),
    (LAW + 'engines = ["yade"]\nengine_options = {yade = {precision = "quad"}}', "precision takes"),
    (LAW + "e_n = " + "[" * 3000 + "]" * 3000, "too deeply"),
    (LAW + "e_n = [0.5]\nangles = " + str(list(range(MAX_TASKS + 1))), "at most"),
    (LAW + "e_n = " + str([0.001 * i for i in range(1, 1000)]) + "\nspins = " + str(list(range(1000))),
     f"at most {MAX_TASKS} are taken"),
    ("name = '\u00e9'\n".encode("latin-1"), "not UTF-8"),
]


def refused_in_one_line(code, capfd, tmp_path, before, words, exit_code=2):
    """The command exited `exit_code` with one line on stderr holding `words`, no traceback, nothing new written."""
    out, err = capfd.readouterr()
    lines = err.strip().splitlines()
    assert code == exit_code, (out, err)
    assert len(lines) == 1 and lines[0].startswith("harness: error: ") and words in lines[0], err
    assert "Traceback" not in out + err
    assert sorted(os.listdir(tmp_path)) == before


def test_the_catalogue_covers_the_schema():
    assert len(BAD_FILES) >= 50


@pytest.mark.parametrize("text, words", BAD_FILES, ids=[f"{i}:{str(t)[:40]}" for i, (t, _) in enumerate(BAD_FILES)])
def test_a_bad_campaign_file_is_refused_in_one_line(tmp_path, capfd, text, words):
    path = tmp_path / "c.toml"
    (path.write_bytes if isinstance(text, bytes) else path.write_text)(text)
    before = sorted(os.listdir(tmp_path))
    started = time.perf_counter()
    code = main(["campaign", str(path), "-o", str(tmp_path / "store"), "--dry-run"])
    refused_in_one_line(code, capfd, tmp_path, before, words)
    assert time.perf_counter() - started < 20           # refused before expanding work beyond the limits
    code = main(["campaign", str(path), "-o", str(tmp_path / "store")])
    refused_in_one_line(code, capfd, tmp_path, before, words)


def test_a_campaign_file_that_is_too_large_is_refused(tmp_path, capfd):
    path = tmp_path / "c.toml"
    path.write_text(LAW + "# " + "x" * (1 << 20) + "\n")
    before = sorted(os.listdir(tmp_path))
    code = main(["campaign", str(path), "-o", str(tmp_path / "store")])
    refused_in_one_line(code, capfd, tmp_path, before, "larger than")


@pytest.mark.parametrize("kind", ["fifo", "directory", "missing", "device"])
def test_a_campaign_file_that_is_not_a_regular_file_is_refused_without_blocking(tmp_path, kind):
    """Run as a process with a deadline: reading a FIFO would block for ever."""
    path = {"device": "/dev/zero"}.get(kind, str(tmp_path / "c.toml"))
    if kind == "fifo":
        os.mkfifo(path)
    elif kind == "directory":
        os.mkdir(path)
    done = subprocess.run([sys.executable, "-m", "harness", "campaign", path, "-o", str(tmp_path / "store")],
                          capture_output=True, text=True, timeout=60)
    lines = done.stderr.strip().splitlines()
    assert done.returncode == 2 and len(lines) == 1 and lines[0].startswith("harness: error: "), done.stderr
    assert not (tmp_path / "store").exists()


def test_toml_integers_are_the_same_runs_as_floats():
    """examples/campaign.toml writes angles = [10, 30]; the CLI gives 10.0, 30.0: one set of task keys."""
    integers = from_dict({"laws": ["thornton"], "e_n": [0.5], "angles": [10, 30], "speeds": [5], "spins": [0],
                          "materials": [{"radius": 0.01, "E": 70000000000, "nu": 0.3, "rho": 2650, "mu": 0.1}]})
    floats = from_dict({"laws": ["thornton"], "e_n": [0.5], "angles": [10.0, 30.0], "speeds": [5.0], "spins": [0.0],
                        "materials": [{"radius": 0.01, "E": 7e10, "nu": 0.3, "rho": 2650.0, "mu": 0.1}]})
    assert set(keyed(integers)[0]) == set(keyed(floats)[0])
