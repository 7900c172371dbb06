"""No thread harness starts imports a module at run time: everything a thread needs is imported by the main thread
before the thread starts. An import on a thread waits on import locks that another thread may hold (pandas loading
pyarrow for a string column while matplotlib loads beside it), and a main thread stuck there never handles SIGTERM.
Each command runs in a process of its own with an audit hook that records every import made off the main thread."""
import json
import os
import pty
import subprocess
import sys

import pytest

from conftest import needs

AUDITED = r"""
import json, sys, threading
off_main = []

def hook(event, args):
    if event == "import" and threading.current_thread() is not threading.main_thread():
        off_main.append([threading.current_thread().name, args[0]])

sys.addaudithook(hook)
from harness.commands import main
code = main(sys.argv[2:])
with open(sys.argv[1], "w") as handle:
    json.dump({"code": code, "off_main": off_main}, handle)
"""


def imports_off_the_main_thread(tmp_path, argv, terminal=False, env=None):
    """(exit code, [(thread, module)] imported off the main thread) of `harness ARGV`; on a pseudo-terminal (rich's
    live bar and its refresh thread) when `terminal`."""
    record = tmp_path / "record.json"
    command = [sys.executable, "-c", AUDITED, str(record), *argv]
    env = {**os.environ, **(env or {})}
    if terminal:
        controller, terminal_end = pty.openpty()
        done = subprocess.run(command, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=terminal_end,
                              timeout=600, env=env)
        os.close(terminal_end)
        os.close(controller)
    else:
        done = subprocess.run(command, capture_output=True, text=True, timeout=600, env=env)
    assert record.exists(), getattr(done, "stderr", "")
    found = json.loads(record.read_text())
    return found["code"], [tuple(pair) for pair in found["off_main"]]


SMALL = ["--en", "0.5", "--angles", "10,40"]


def test_the_audit_sees_an_import_on_a_thread(tmp_path):
    """Positive control: the hook catches an import a thread makes."""
    code = AUDITED.replace("from harness.commands import main",
                           "import threading as t\nworker = t.Thread(target=lambda: __import__('xml.dom'))\n"
                           "worker.start(); worker.join()\nfrom harness.commands import main")
    record = tmp_path / "record.json"
    subprocess.run([sys.executable, "-c", code, str(record), "models"], capture_output=True, timeout=120, check=True)
    assert ("Thread-1 (<lambda>)", "xml.dom") in [tuple(p) for p in json.loads(record.read_text())["off_main"]]


@pytest.mark.parametrize("terminal", [False, True], ids=["log", "terminal"])
def test_a_compare_on_the_reference_imports_nothing_on_its_threads(tmp_path, terminal):
    code, found = imports_off_the_main_thread(
        tmp_path, ["compare", "--model", "hertz-mindlin", *SMALL, "--engines", "reference", "-o",
                   str(tmp_path / "out")], terminal)
    assert code == 0 and found == []


def test_kernels_compiled_during_a_compare_are_compiled_by_the_main_thread(tmp_path):
    """A numba cache that holds what importing the solver compiles but no kernel: the compare compiles them, and
    what compiling imports (numba's runtime context, its boxing) is imported by the main thread."""
    env = {"NUMBA_CACHE_DIR": str(tmp_path / "cache")}
    subprocess.run([sys.executable, "-c", "import harness.solver.simulate"], env={**os.environ, **env}, check=True,
                   timeout=600)
    code, found = imports_off_the_main_thread(
        tmp_path, ["compare", "--model", "hertz-mindlin", *SMALL, "--engines", "reference", "-o",
                   str(tmp_path / "out"), "--quiet"], env=env)
    assert code == 0 and found == []


@needs("yade")
@needs("liggghts")
@needs("lammps")
def test_a_compare_with_every_engine_imports_nothing_on_its_threads(tmp_path):
    code, found = imports_off_the_main_thread(
        tmp_path, ["compare", "--model", "hertz-mindlin", *SMALL, "--engines", "yade,liggghts,lammps", "-o",
                   str(tmp_path / "out"), "--quiet"])
    assert code in (0, 1) and found == []


@needs("liggghts")
def test_a_cost_study_with_an_engine_imports_nothing_on_its_threads(tmp_path):
    code, found = imports_off_the_main_thread(
        tmp_path, ["cost", "--model", "hertz-mindlin", *SMALL, "--ladder", "20,40", "--engines", "liggghts", "-o",
                   str(tmp_path / "out"), "--quiet"])
    assert code == 0 and found == []


def test_paper_imports_nothing_on_its_threads(tmp_path):
    code, found = imports_off_the_main_thread(
        tmp_path, ["paper", "--laws", "linear-spring-dashpot", "--steps-per-contact", "200", "-o",
                   str(tmp_path / "out"), "--quiet"])
    assert code == 0 and found == []
