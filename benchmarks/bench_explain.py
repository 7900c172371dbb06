"""What `harness explain` costs on the default sweep (45 impact angles; the input's dialect and the paper laws on the
reference solver, the other engines' candidates and the advice's deck): the call in one process, first and warm (its
kernels loaded), and the whole command as a process, warm (numba's cache filled by a first run), beside `harness
--version` as a process (Python and the package's entry point alone) and beside the floor of any process that steps
the reference: numpy, pandas, scipy's optimize and integrate (the damping calibrations) imported and numba's compiler
started by one jit of x + 1. Goal: the warm call under 2 s.

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


FLOOR = ("import numpy, pandas, scipy.optimize, scipy.integrate, numba; "
         "assert numba.njit(lambda x: x + 1)(1) == 2")


def process_seconds(arguments, repeat):
    """Wall times of `python ARGUMENTS` as a process, `repeat` times."""
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        subprocess.run([sys.executable, *arguments], check=True, capture_output=True)
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
    version = process_seconds(["-m", "harness", "--version"], repeat)
    floor = process_seconds(["-c", FLOOR], repeat)
    print(f"explain on the default sweep (min / median of {repeat}):")
    print(f"  harness --version as a process          {min(version):.2f} / {statistics.median(version):.2f} s")
    print(f"  floor: numpy, pandas, scipy, numba jit  {min(floor):.2f} / {statistics.median(floor):.2f} s")
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
        processes = process_seconds(["-m", "harness", "explain", engine, text, "--quiet"], repeat)
        ratio = statistics.median(processes) / statistics.median(version)
        above = statistics.median(processes) / statistics.median(floor)
        print(f"{engine} {text}")
        print(f"  call, first in its process     {first:.2f} s")
        print(f"  call, warm                     {min(calls):.2f} / {statistics.median(calls):.2f} s")
        print(f"  command as a process, warm     {min(processes):.2f} / {statistics.median(processes):.2f} s "
              f"({ratio:.1f}x harness --version, {above:.1f}x the floor)")


if __name__ == "__main__":
    main()
