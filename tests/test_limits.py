"""Work that could not finish is refused before it starts: paper's resolution and cost's ladder have stated bounds,
and a request beyond one is one line naming the bound, exit 2, no traceback and nothing written."""
import subprocess
import sys

import pytest

CASES = {   # name -> (arguments, the bound the message names)
    "paper at 1e6 + 1 steps per contact": (["paper", "--steps-per-contact", "1000001"], "at most 1e+06"),
    "paper at 1e9 steps per contact": (["paper", "--steps-per-contact", "1000000000"], "at most 1e+06"),
    "a rung above 1e6": (["cost", "--model", "hertz-mindlin", "--ladder", "5,1000001"], "at most 1e+06"),
    "31 rungs": (["cost", "--model", "hertz-mindlin", "--ladder", ",".join(str(n) for n in range(1, 32))],
                 "at most 30 rungs"),
    "rungs adding up beyond 2e6": (["cost", "--model", "hertz-mindlin", "--ladder", "600000,700000,800000"],
                                   "at most 2e+06"),
}


@pytest.mark.parametrize("name", list(CASES))
def test_work_beyond_a_bound_is_refused_in_one_line(tmp_path, name):
    argv, bound = CASES[name]
    out = tmp_path / "out"
    done = subprocess.run([sys.executable, "-m", "harness", *argv, "-o", str(out)], capture_output=True, text=True,
                          timeout=120)
    lines = done.stderr.strip().splitlines()
    assert done.returncode == 2 and len(lines) == 1 and lines[0].startswith("harness: error:"), done.stderr
    assert bound in lines[0] and done.stdout == ""
    assert not out.exists()


def test_the_largest_ladder_allowed_is_accepted():
    from harness.commands.cost import ladder_from_text
    from harness.studies.cost_plan import MAX_RUNGS
    assert ladder_from_text(",".join(str(n) for n in range(1, MAX_RUNGS + 1))) == tuple(range(1, MAX_RUNGS + 1))
    assert ladder_from_text("1000000,") == (1000000,)
