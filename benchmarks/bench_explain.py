"""What `harness explain` costs on the default sweep (45 impact angles; the input's dialect and three paper laws on
the reference solver, and the advice's deck): the call in one process, first and warm (its kernels loaded), and the
whole command as a process, warm (numba's cache filled by a first run). Goal: the warm call under 2 s.

    .venv/bin/python benchmarks/bench_explain.py [--smoke] [--repeat N]
"""
import argparse
import statistics
import subprocess
import sys
import time

INPUT = "hooke 1e7 2e5 tangential linear_history 2.8e6 0.5 0.4"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--smoke", action="store_true", help="one repeat of each")
    parser.add_argument("--repeat", type=int, default=5)
    args = parser.parse_args()
    repeat = 1 if args.smoke else args.repeat
    from harness.studies.explain import explain
    start = time.perf_counter()
    explain("lammps", INPUT)
    first = time.perf_counter() - start
    calls = []
    for _ in range(repeat):
        start = time.perf_counter()
        explain("lammps", INPUT)
        calls.append(time.perf_counter() - start)
    processes = []
    for _ in range(repeat):
        start = time.perf_counter()
        subprocess.run([sys.executable, "-m", "harness", "explain", "lammps", INPUT, "--quiet"], check=True,
                       capture_output=True)
        processes.append(time.perf_counter() - start)
    print(f"explain lammps '{INPUT}' on the default sweep (min / median of {repeat}):")
    print(f"  call, first in its process     {first:.2f} s")
    print(f"  call, warm                     {min(calls):.2f} / {statistics.median(calls):.2f} s")
    print(f"  command as a process, warm     {min(processes):.2f} / {statistics.median(processes):.2f} s")


if __name__ == "__main__":
    main()
