"""No command writes into the installed package: each command's cheapest use, run from a scratch
directory, leaves every file of the package directory as it was (Python's own __pycache__ aside)."""
import hashlib
import pathlib
import subprocess
import sys

import pytest

import harness

PACKAGE = pathlib.Path(harness.__file__).resolve().parent
EXAMPLES = pathlib.Path(__file__).resolve().parent.parent / "examples"
SCENE = ["--en", "0.5", "--angles", "10"]
COMMANDS = [
    ["models"], ["engines"], ["cite"],
    ["run", "--model", "thornton", *SCENE, "-o", "run.csv"],
    ["compare", "--model", "thornton", *SCENE, "--engines", "reference", "-o", "cmp"],
    ["report", "cmp"],
    ["render", "--model", "thornton", "--engine", "liggghts", *SCENE, "-o", "deck"],
    ["explain", "lammps", "hooke 1e7 2e5 tangential linear_history 2.8e6 0.5 0.4", "--angles", "10"],
    ["calibrate", "--model", "hertz-mindlin", "--engine", "liggghts", *SCENE, "-o", "cal"],
    ["cost", "--model", "thornton", "--engines", "reference", "--en", "0.5", "--angles", "40", "--ladder", "100",
     "-o", "cost"],
    ["paper", "--laws", "thornton", "--steps-per-contact", "100", "-o", "paper"],
    ["compile", "--laws", "thornton"],
    ["campaign", str(EXAMPLES / "campaign.toml"), "-o", "store", "--dry-run"],
    ["campaign", "small.toml", "-o", "store"],
    ["query", "store", "SELECT count(*) FROM results"],
    ["benchmark", "chung-ooi", "--engines", "reference", "-o", "chung-ooi"],
    ["baseline", "--update", "--baseline", ""],
    ["check", "--baseline", ""],
]


def snapshot():
    """{relative path: sha256} of every file under the package directory but Python's bytecode caches."""
    out = {}
    for path in sorted(PACKAGE.rglob("*")):
        if "__pycache__" in path.parts or not path.is_file():
            continue
        out[str(path.relative_to(PACKAGE))] = hashlib.sha256(path.read_bytes()).hexdigest()
    return out


@pytest.fixture(scope="module")
def scratch(tmp_path_factory):
    """A scratch working directory holding the smallest campaign (for campaign, then query on its store)."""
    where = tmp_path_factory.mktemp("scratch")
    (where / "small.toml").write_text('laws = ["thornton"]\nengines = ["reference"]\ne_n = [0.5]\nangles = [10]\n'
                                      'steps_per_contact = [200]\n')
    return where


@pytest.mark.parametrize("argv", COMMANDS, ids=[a[0] + (" --dry-run" if "--dry-run" in a else "") for a in COMMANDS])
def test_no_command_writes_into_the_package(argv, scratch):
    before = snapshot()
    done = subprocess.run([sys.executable, "-m", "harness", *argv], cwd=scratch, capture_output=True, text=True,
                          timeout=900, stdin=subprocess.DEVNULL)
    assert done.returncode in (0, 1, 2, 3), done.stderr[-2000:]         # whatever it says, never a traceback (4)
    after = snapshot()
    changed = sorted(set(before.items()) ^ set(after.items()))
    assert not changed, f"{argv[0]} wrote into the package: {changed[:5]}"
