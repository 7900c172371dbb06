"""How long `harness calibrate` takes warm, beside `harness compare` of the same engine on the same scene (the
issue's goal: under a minute on the quick start's scene for one engine), each as a whole process with the user's
numba cache already filled, several times (these machines are noisy); min and median, and the ratio.

    .venv/bin/python benchmarks/bench_calibrate.py [ENGINE] [--smoke] [--repeat N]

ENGINE defaults to liggghts (any installed engine); the quick start's scene is the paper's (4 e_n x 45 angles).
--smoke: one e_n and two angles, once, without the warm-up runs (it checks that the script runs, not the figures).
"""
import argparse
import statistics
import subprocess
import sys
import tempfile
import time

HARNESS = [sys.executable, "-m", "harness"]


def timed(arguments):
    """Wall seconds of `harness ARGUMENTS -o DIR --quiet` (exit 0, 1 or 3 are answers; anything else stops)."""
    start = time.perf_counter()
    with tempfile.TemporaryDirectory() as out:
        done = subprocess.run([*HARNESS, *arguments, "-o", out, "--quiet"], capture_output=True, text=True)
    if done.returncode not in (0, 1, 3):
        raise SystemExit(f"harness {' '.join(arguments)} exited {done.returncode}:\n{done.stderr[-2000:]}")
    return time.perf_counter() - start


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("engine", nargs="?", default="liggghts")
    parser.add_argument("--smoke", action="store_true")
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    scene = ["--en", "0.5", "--angles", "10,40"] if args.smoke else []
    repeat = 1 if args.smoke else args.repeat
    law = ["--model", "hertz-mindlin"]
    commands = {"calibrate": ["calibrate", *law, "--engine", args.engine, *scene],
                "compare": ["compare", *law, "--engines", args.engine, *scene]}
    for arguments in commands.values() if not args.smoke else ():   # warm the cache: the first run may compile
        timed(arguments)
    walls = {label: [timed(arguments) for _ in range(repeat)] for label, arguments in commands.items()}
    print(f"{'command':12s} {'min [s]':>8s} {'median [s]':>10s}   ({args.engine}, hertz-mindlin, "
          f"{'smoke scene, not warmed first' if args.smoke else 'the quick start scene, warm'}, {repeat} run(s))")
    for label, values in walls.items():
        print(f"{label:12s} {min(values):8.1f} {statistics.median(values):10.1f}")
    print(f"RATIO calibrate/compare (medians): "
          f"{statistics.median(walls['calibrate']) / statistics.median(walls['compare']):.2f}")


if __name__ == "__main__":
    main()
