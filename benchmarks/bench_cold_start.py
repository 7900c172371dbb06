"""First use against later use: `harness run` with an empty numba cache (every integrator it needs compiled) and then
with the cache it left (loaded), side by side in one run, for the plain scheme and for --converged. Goal: cold at
most 5x warm.

    .venv/bin/python benchmarks/bench_cold_start.py [--smoke]
"""
import os
import subprocess
import sys
import tempfile
import time

CASES = {   # name -> harness run arguments
    "run (paper scheme)": ["--model", "hertz-mindlin"],
    "run --converged (adaptive)": ["--model", "thornton", "--converged"],
}
WARM_REPEATS = 3


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


def main(smoke=False):
    cases = dict(list(CASES.items())[:1]) if smoke else CASES
    print(f"{'':28s} {'cold [s]':>9s} {'warm [s] (min of 3)':>20s} {'RATIO cold/warm':>16s}")
    for name, args in cases.items():
        if smoke:
            args = args + ["--en", "0.5", "--angles", "10"]
        with tempfile.TemporaryDirectory(prefix="harness-bench-cache-") as cache:
            out = os.path.join(cache, "results.csv")
            cold = timed(args, cache, out)
            warm = min(timed(args, cache, out) for _ in range(1 if smoke else WARM_REPEATS))
        print(f"{name:28s} {cold:9.2f} {warm:20.2f} {cold / warm:16.1f}")


if __name__ == "__main__":
    main("--smoke" in sys.argv[1:])
