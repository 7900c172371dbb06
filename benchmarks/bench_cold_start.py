"""First use against later use: `harness run` with an empty numba cache (every integrator it needs compiled) and then
with the cache it left (loaded), side by side in one run, for the plain scheme and for --converged. Each is timed
several times (a fresh cache for every cold run), since these machines are noisy: min and median, and the ratio of
the medians. Goal: cold at most 5x warm.

    .venv/bin/python benchmarks/bench_cold_start.py [--smoke]
"""
import os
import statistics
import subprocess
import sys
import tempfile
import time

CASES = {   # name -> harness run arguments
    "run (paper scheme)": ["--model", "hertz-mindlin"],
    "run --converged (adaptive)": ["--model", "thornton", "--converged"],
}
REPEATS = 3


def timed(args, cache, out):
    """Wall time of one `harness run` process with numba's cache in `cache`."""
    env = {**os.environ, "NUMBA_CACHE_DIR": cache}
    start = time.perf_counter()
    done = subprocess.run([sys.executable, "-m", "harness", "run", *args, "-o", out, "--quiet"], env=env,
                          capture_output=True, text=True)
    seconds = time.perf_counter() - start
    if done.returncode != 0:
        raise SystemExit(f"harness run {' '.join(args)} failed: {done.stderr.strip()}")
    return seconds


def cold_and_warm(args, repeats):
    """(cold times, warm times): each cold run in a fresh cache, the warm runs in the last cold run's cache."""
    cold, warm = [], []
    for k in range(repeats):
        with tempfile.TemporaryDirectory(prefix="harness-bench-cache-") as cache:
            out = os.path.join(cache, "results.csv")
            cold.append(timed(args, cache, out))
            if k == repeats - 1:
                warm = [timed(args, cache, out) for _ in range(repeats)]
    return cold, warm


def main(smoke=False):
    cases = dict(list(CASES.items())[:1]) if smoke else CASES
    repeats = 1 if smoke else REPEATS
    print(f"{'':28s} {'cold min/median [s]':>20s} {'warm min/median [s]':>20s} {'RATIO of medians':>17s}")
    for name, args in cases.items():
        if smoke:
            args = args + ["--en", "0.5", "--angles", "10"]
        cold, warm = cold_and_warm(args, repeats)
        c, w = statistics.median(cold), statistics.median(warm)
        print(f"{name:28s} {min(cold):9.2f} / {c:7.2f}  {min(warm):9.2f} / {w:7.2f}  {c / w:16.1f}")


if __name__ == "__main__":
    main("--smoke" in sys.argv[1:])
