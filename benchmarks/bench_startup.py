"""What a command costs before it does anything: `harness --help`, `--version`, `models`, `engines`, `compare
--help` and refused inputs (an unknown law to `run` and to `compare`), each as a whole process, today's code beside
the code of each reference revision (exported from git), side by side in one run: by default the code before the
lazy start-up (every command and engine imported at start) and the code whose laws were their compiled functions
(`models`, `engines` and an unknown law imported numba; `COMMAND --help` imported the command). Cold: the first run
with an empty bytecode cache (PYTHONPYCACHEPREFIX in a new directory: every module compiled from source, as after an
install that wrote none); warm: later runs. Several runs each since these machines are noisy: min and median, and
the ratio of the warm medians. Goal: warm `harness --help` well under 1 s, and `models`, `engines`, `compare --help`
and a refused law without numba or pandas.

    .venv/bin/python benchmarks/bench_startup.py [--smoke] [--repeat N] [--before REV ...]
"""
import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
BEFORE = ("28214cd",       # the last commit whose parser imported every command and engine at start
          "5a5a195")       # the last whose laws were their compiled functions and whose COMMAND --help imported it
COMMANDS = {   # label -> harness arguments, exit code expected
    "--help": (["--help"], 0),
    "--version": (["--version"], 0),
    "models": (["models"], 0),
    "engines": (["engines"], 0),
    "compare --help": (["compare", "--help"], 0),
    "run: unknown law": (["run", "--model", "nosuch", "-o", "nosuch.csv"], 2),
    "compare: unknown law": (["compare", "--model", "nosuch"], 2),
}
SMOKE = ("--help",)


def timed(tree, arguments, expected, pycache):
    """Wall seconds of one `python -m harness ARGUMENTS` from the source tree `tree`, bytecode under `pycache`."""
    env = {**os.environ, "PYTHONPATH": str(tree), "PYTHONPYCACHEPREFIX": pycache}
    env.pop("PYTHONDONTWRITEBYTECODE", None)
    start = time.perf_counter()
    done = subprocess.run([sys.executable, "-m", "harness", *arguments], env=env, capture_output=True, text=True,
                          cwd=tempfile.gettempdir())
    wall = time.perf_counter() - start
    if done.returncode != expected:
        raise SystemExit(f"harness {' '.join(arguments)} from {tree} exited {done.returncode}: {done.stderr[-500:]}")
    return wall


def measure(tree, arguments, expected, repeat, scratch):
    """(cold walls, warm walls): each cold run with a new empty bytecode cache, the warm runs with the last one's."""
    cold, warm = [], []
    for _ in range(repeat):
        pycache = tempfile.mkdtemp(dir=scratch)
        cold.append(timed(tree, arguments, expected, pycache))
    for _ in range(repeat):
        warm.append(timed(tree, arguments, expected, pycache))
    return cold, warm


def exported(rev, scratch):
    """The package as it was at `rev` (git archive), or None where git cannot give it."""
    target = Path(scratch, f"before-{rev}")
    target.mkdir()
    archive = subprocess.run(["git", "-C", str(ROOT), "archive", rev, "harness"], capture_output=True)
    if archive.returncode != 0:
        return None
    subprocess.run(["tar", "-x", "-C", str(target)], input=archive.stdout, check=True)
    return target


def spread(walls):
    return f"{min(walls):.2f} / {statistics.median(walls):.2f}"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--smoke", action="store_true", help="--help alone, once")
    parser.add_argument("--repeat", type=int, default=5)
    parser.add_argument("--before", action="append", default=None, metavar="REV",
                        help=f"a revision to compare with, repeatable (default {' and '.join(BEFORE)})")
    args = parser.parse_args()
    repeat = 1 if args.smoke else args.repeat
    labels = SMOKE if args.smoke else tuple(COMMANDS)
    with tempfile.TemporaryDirectory(prefix="harness-bench-startup-") as scratch:
        before = {rev: exported(rev, scratch) for rev in args.before or BEFORE}
        print(f"{'min / median [s]':20s} {'today cold':>12s} {'today warm':>12s}"
              + "".join(f" {rev + ' cold':>13s} {rev + ' warm':>13s} {'RATIO':>5s}" for rev in before))
        for label in labels:
            arguments, expected = COMMANDS[label]
            cold, warm = measure(ROOT, arguments, expected, repeat, scratch)
            line = f"{label:20s} {spread(cold):>12s} {spread(warm):>12s}"
            for tree in before.values():
                if tree is None:
                    line += f" {'(no git)':>13s} {'':13s} {'':5s}"
                    continue
                old_cold, old_warm = measure(tree, arguments, expected, repeat, scratch)
                line += (f" {spread(old_cold):>13s} {spread(old_warm):>13s} "
                         f"{statistics.median(old_warm) / statistics.median(warm):5.1f}")
            print(line)
        print("RATIO: the reference's warm median over today's")

if __name__ == "__main__":
    main()
