"""Nothing found relative to the working directory runs: a program harness looks up by name is searched in PATH's
absolute entries alone (an empty entry means the working directory), an environment variable naming a program or
the engines directory must be absolute, and the libraries harness calls from the command line see that PATH too.
Each test plants executables that log their own runs where a careless lookup would find them."""
import json
import os
import subprocess
import sys

import pandas as pd
import pytest
from conftest import needs

from harness.commands import main

PLANTED = """#!/bin/sh
echo "$0" >> "{log}"
"""
# what harness and its libraries run by name, beside every program of PATH's directories
NAMES = ("python", "python3", "python3.11", "lmp", "liggghts", "harness-lmp", "sbatch", "scancel", "setpriv",
         "unshare", "sh", "mount", "mkdir", "fc-list", "uname", "ldconfig", "gcc", "ld", "objdump")
RELATIVE_PATH = ["", ".", "bin", "./bin"]      # PATH entries that name the working directory or a folder in it


def plant(directory, log, names):
    """An executable under each name in `directory`, logging to `log` when it runs."""
    directory.mkdir(parents=True, exist_ok=True)
    script = directory / ".planted"
    script.write_text(PLANTED.format(log=log))
    script.chmod(0o755)
    for name in names:
        if not (directory / name).exists():
            os.symlink(script, directory / name)


def planted_tree(root):
    """`root` as a working directory holding a planted program under every name harness might look up (also in
    its `bin`, and as the prefixes of engine builds), and the log they write; returns the log's path."""
    log = root / "ran.log"
    on_path = {name for entry in os.environ["PATH"].split(os.pathsep) if os.path.isabs(entry) and
               os.path.isdir(entry) for name in os.listdir(entry)}
    for folder in (root, root / "bin", root / "kratos-9" / "bin", root / "lammps-9" / "bin"):
        plant(folder, log, set(NAMES) | on_path)
    return log


@pytest.mark.parametrize("value", ["", ".", "engines", "./engines"])
def test_an_empty_or_relative_engines_directory_is_refused_and_nothing_in_it_runs(tmp_path, monkeypatch, capfd,
                                                                                 value):
    """HARNESS_ENGINES_DIR set but empty (or relative) once made `harness engines` run ./kratos-*/bin/python."""
    log = planted_tree(tmp_path)
    plant(tmp_path / "engines" / "kratos-9" / "bin", log, NAMES)
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("HARNESS_ENGINES_DIR", value)
    assert main(["engines"]) == 2
    err = capfd.readouterr().err.strip().splitlines()
    assert len(err) == 1 and f"HARNESS_ENGINES_DIR={value!r} must be an absolute directory" in err[0], err
    assert not log.exists()


@pytest.mark.parametrize("variable", ["HARNESS_LIGGGHTS", "HARNESS_LAMMPS", "HARNESS_YADE_PYTHON",
                                      "HARNESS_KRATOS_PYTHON"])
@pytest.mark.parametrize("value", ["", "./bin/python", "bin/lmp", "kratos-9/bin/python"])
def test_an_engine_variable_naming_a_relative_path_is_refused_and_nothing_runs(tmp_path, monkeypatch, capfd,
                                                                              variable, value):
    log = planted_tree(tmp_path)
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv(variable, value)
    for command in (["engines"], ["compare", "--model", "hertz-mindlin", "--en", "0.5", "--angles", "10", "-o",
                                  str(tmp_path / "out")]):
        assert main(command) == 2, command
        err = capfd.readouterr().err.strip().splitlines()
        assert len(err) == 1 and f"{variable}={value!r} must be an absolute path or a program name on PATH" in err[0]
    assert not log.exists() and not (tmp_path / "out").exists()


def harness(arguments, cwd, env):
    return subprocess.run([sys.executable, "-m", "harness", *arguments], cwd=cwd, env=env, capture_output=True,
                          text=True, timeout=900)


@needs("liggghts")
@needs("yade")
@needs("lammps")
@needs("kratos")
def test_no_command_runs_a_program_found_in_the_working_directory(tmp_path):
    """A working directory holding a program under every name of PATH (and sbatch, fc-list, ...), PATH beginning
    with an empty entry, '.' and relative folders: listing the engines, comparing on all four, rendering a deck,
    drawing a report (matplotlib's font cache rebuilt, which runs fc-list) and a SLURM campaign (no sbatch here)
    run none of them."""
    log = planted_tree(tmp_path)
    (tmp_path / "c.toml").write_text('laws = ["thornton"]\ne_n = [0.5]\nangles = [10]\nsteps_per_contact = [500]\n')
    env = {**os.environ, "PATH": os.pathsep.join(RELATIVE_PATH + [os.environ["PATH"]]),
           "MPLCONFIGDIR": str(tmp_path / "fresh-matplotlib")}
    env.pop("HARNESS_ENGINES_DIR", None)
    listed = harness(["engines", "--json"], tmp_path, env)
    assert listed.returncode == 0, listed.stderr
    assert all(os.path.isabs(row["binary"]) and not row["binary"].startswith(str(tmp_path))
               for row in json.loads(listed.stdout))
    compared = harness(["compare", "--model", "hertz-mindlin", "--engines", "liggghts,yade,lammps,kratos", "--en",
                        "0.5", "--angles", "10", "-o", "out", "--quiet"], tmp_path, env)
    assert compared.returncode in (0, 1), compared.stderr
    frame = pd.read_csv(tmp_path / "out" / "results.csv")
    assert {"liggghts", "yade", "lammps", "kratos"} <= set(frame[frame.status == "ok"].engine), frame
    os.remove(tmp_path / "out" / "report.html")
    reported = harness(["report", "out"], tmp_path, env)
    assert reported.returncode == 0 and (tmp_path / "out" / "report.html").is_file(), reported.stderr
    assert (tmp_path / "fresh-matplotlib").is_dir()         # the premise: matplotlib built its font cache here
    rendered = harness(["render", "--model", "hertz-mindlin", "--engine", "lammps", "--en", "0.5", "-o", "decks"],
                       tmp_path, env)
    assert rendered.returncode == 0, rendered.stderr
    slurm = harness(["campaign", "c.toml", "-o", "store", "--executor", "dask", "--slurm", "queue=debug"],
                    tmp_path, env)
    assert slurm.returncode == 3 and "sbatch and scancel, not found on PATH" in slurm.stderr, slurm.stderr
    assert not log.exists(), log.read_text()
