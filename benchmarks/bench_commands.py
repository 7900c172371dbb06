"""What the commands the README and the user guide quote take, as a user runs them: each as a whole process, first
with an empty numba cache (cold: every kernel it needs compiled) and then with the cache that left (warm), several
times each since these machines are noisy; min and median. The README's and docs' figures are this script's.

    .venv/bin/python benchmarks/bench_commands.py [--smoke] [--repeat N]

Commands: the quick start's `harness compare --model hertz-mindlin` (every engine installed), `harness paper`, then
warm and once each `harness cost --model hertz-mindlin` (it takes minutes) and `harness benchmark chung-ooi` on the
reference and on every engine. --smoke runs compare, paper and cost on their smallest scenes and Chung & Ooi on the
reference, once; its compare runs LIGGGHTS alone, and only compare runs cold (paper runs warm in its cache).
"""
import argparse
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

HARNESS = [sys.executable, "-m", "harness"]
FULL = {   # label -> arguments (the output directory is added)
    "compare --model hertz-mindlin": ["compare", "--model", "hertz-mindlin"],
    "paper": ["paper"],
}
SMOKE = {
    "compare --model hertz-mindlin": ["compare", "--model", "hertz-mindlin", "--en", "0.5", "--angles", "10,40",
                                      "--engines", "liggghts"],
    "paper": ["paper", "--laws", "linear-spring-dashpot", "--steps-per-contact", "200"],
}
CHUNG_OOI = {"benchmark chung-ooi --engines reference": ["benchmark", "chung-ooi", "--engines", "reference"],
             "benchmark chung-ooi (every engine)": ["benchmark", "chung-ooi"]}
COST = {"full": ["cost", "--model", "hertz-mindlin"],
        "smoke": ["cost", "--model", "hertz-mindlin", "--en", "0.5", "--angles", "10,40", "--ladder", "20,40",
                  "--engines", "reference"]}


def timed(arguments, cache, scratch):
    """Wall seconds of one run of `harness ARGUMENTS -o DIR` with numba's cache in `cache`; its exit code."""
    out = tempfile.mkdtemp(dir=scratch)
    env = {**os.environ, "NUMBA_CACHE_DIR": cache}
    start = time.perf_counter()
    done = subprocess.run([*HARNESS, *arguments, "-o", out, "--quiet"], env=env, capture_output=True, text=True)
    wall = time.perf_counter() - start
    if done.returncode not in (0, 1):
        raise SystemExit(f"harness {' '.join(arguments)} exited {done.returncode}:\n{done.stderr[-2000:]}")
    return wall


def measure(arguments, repeat, scratch):
    """(cold walls, warm walls, cache): each cold run in a new empty cache, the warm runs in the last cold run's cache,
    which is returned."""
    cold, warm = [], []
    for _ in range(repeat):
        cache = tempfile.mkdtemp(dir=scratch)
        cold.append(timed(arguments, cache, scratch))
    for _ in range(repeat):
        warm.append(timed(arguments, cache, scratch))
    return cold, warm, cache


def spread(walls):
    return f"{min(walls):7.1f} / {statistics.median(walls):6.1f}"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--smoke", action="store_true", help="the smallest scenes, once")
    parser.add_argument("--repeat", type=int, default=3, help="runs of each kind (default 3)")
    args = parser.parse_args()
    repeat = 1 if args.smoke else args.repeat
    commands = SMOKE if args.smoke else FULL
    scratch = tempfile.mkdtemp(prefix="bench-commands-")
    try:
        print(f"{'harness ...':34s} {'cold min / median [s]':>22s} {'warm min / median [s]':>22s} {'runs':>5s}")
        cache = None                    # the first command's cache, left by its cold runs
        for label, arguments in commands.items():
            if args.smoke and cache:    # smoke: one cold compile only (compare's), the others warm in its cache
                warm = [timed(arguments, cache, scratch)]
                print(f"{label:34s} {'-':>22s} {spread(warm):>22s} {repeat:5d}")
                continue
            cold, warm, made = measure(arguments, repeat, scratch)
            cache = cache or made       # compare compiled the cost's kernels there
            print(f"{label:34s} {spread(cold):>22s} {spread(warm):>22s} {repeat:5d}")
        for label, arguments in (("cost --model hertz-mindlin", COST["smoke" if args.smoke else "full"]),
                                 *list(CHUNG_OOI.items())[:1 if args.smoke else None]):
            wall = timed(arguments, cache, scratch)
            print(f"{label:34s} {'':>22s} {wall:15.1f} (once) {1:5d}")
    finally:
        shutil.rmtree(scratch, ignore_errors=True)


if __name__ == "__main__":
    main()
