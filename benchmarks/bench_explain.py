"""What `harness explain` costs on the default sweep (45 impact angles; the input's dialect and the paper laws on the
reference solver, the other engines' candidates and the advice's deck): the call in one process, first and warm (its
kernels loaded), and the whole command as a process, warm (numba's cache filled by a first run), beside `harness
--version` as a process (Python and the package's entry point alone). Goal: the warm call under 2 s.

    .venv/bin/python benchmarks/bench_explain.py [--smoke] [--repeat N]
"""
import argparse
import statistics
import subprocess
import sys
import time

INPUTS = {
    "lammps": "hooke 1e7 2e5 tangential linear_history 2.8e6 0.5 0.4",
    "kratos": '{"DEM_DISCONTINUUM_CONSTITUTIVE_LAW_NAME": "DEM_D_Hertz_viscous_Coulomb", "YOUNG_MODULUS": 7e10, '
              '"POISSON_RATIO": 0.3, "COEFFICIENT_OF_RESTITUTION": 0.5, "STATIC_FRICTION": 0.4, '
              '"DYNAMIC_FRICTION": 0.4}',
}


def process_seconds(arguments, repeat):
    """Wall times of `python -m harness ARGUMENTS` as a process, `repeat` times."""
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        subprocess.run([sys.executable, "-m", "harness", *arguments], check=True, capture_output=True)
        times.append(time.perf_counter() - start)
    return times


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--smoke", action="store_true", help="one repeat of each, the LAMMPS input alone")
    parser.add_argument("--repeat", type=int, default=5)
    args = parser.parse_args()
    repeat = 1 if args.smoke else args.repeat
    engines = ["lammps"] if args.smoke else list(INPUTS)
    from harness.studies.explain import explain
    version = process_seconds(["--version"], repeat)
    print(f"explain on the default sweep (min / median of {repeat}):")
    print(f"  harness --version as a process          {min(version):.2f} / {statistics.median(version):.2f} s")
    for engine in engines:
        text = INPUTS[engine]
        start = time.perf_counter()
        explain(engine, text)
        first = time.perf_counter() - start
        calls = []
        for _ in range(repeat):
            start = time.perf_counter()
            explain(engine, text)
            calls.append(time.perf_counter() - start)
        processes = process_seconds(["explain", engine, text, "--quiet"], repeat)
        ratio = statistics.median(processes) / statistics.median(version)
        print(f"{engine} {text}")
        print(f"  call, first in its process     {first:.2f} s")
        print(f"  call, warm                     {min(calls):.2f} / {statistics.median(calls):.2f} s")
        print(f"  command as a process, warm     {min(processes):.2f} / {statistics.median(processes):.2f} s "
              f"({ratio:.1f}x harness --version)")


if __name__ == "__main__":
    main()
