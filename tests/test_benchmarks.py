"""Every script in benchmarks/ runs at its smallest size (--smoke) and prints the ratio it exists to measure, so
none of them rots unnoticed. The figures themselves are measured by running the scripts, never asserted here."""
import re
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import needs

BENCHMARKS = Path(__file__).resolve().parents[1] / "benchmarks"

# script -> (extra arguments, a line its output must hold, whether it runs an engine: True, or the one it needs)
SMOKES = {
    "bench_cold_start.py": ([], r"run \(paper scheme\)\s+[\d.]+ /\s+[\d.]+\s+[\d.]+ /\s+[\d.]+\s+[\d.]+", False),
    "bench_reference.py": ([], r"reference, 1 thread\(s\): \d+ impact-steps", False),
    "bench_converged.py": ([], r"hertz-kuwabara-kono\s+[\d.e+]+\s+[\d.]+", False),
    "bench_effects.py": ([], r"normal impacts.*\s[\d.]+\s+True", True),
    "bench_compare.py": ([], r"RATIO", True),
    "bench_accuracy_cost.py": ([], r"reference \(paper law\)\s+\d+", True),
    "bench_engine_batch.py": (["liggghts"], r"RATIO separate/batched: [\d.]+x \(identical results: True\)", True),
    "bench_campaign.py": ([], r"cached rerun\s+[\d.]+ s\s+ran 0 of \d+", True),
    "bench_calibrate.py": (["liggghts"], r"RATIO calibrate/compare \(medians\): [\d.]+", True),
    "bench_startup.py": ([], r"--help\s+[\d.]+ /\s+[\d.]+\s+[\d.]+ /\s+[\d.]+", False),
    "bench_kratos.py": ([], r"RATIO separate/batched: [\d.]+x \(same results to 1e-12: True\)", "kratos"),
    "bench_explain.py": ([], r"call, warm\s+[\d.]+ /\s+[\d.]+ s", False),
    "bench_commands.py": ([], r"compare --model hertz-mindlin\s+[\d.]+ /\s+[\d.]+\s+[\d.]+ /\s+[\d.]+\s+1", True),
}


def test_every_benchmark_has_a_smoke_run():
    assert sorted(p.name for p in BENCHMARKS.glob("bench_*.py")) == sorted(SMOKES)
    for name in SMOKES:
        assert "--smoke" in (BENCHMARKS / name).read_text(), f"{name} has no --smoke size"


def smoke(name):
    arguments, expected, _ = SMOKES[name]
    done = subprocess.run([sys.executable, str(BENCHMARKS / name), *arguments, "--smoke"], capture_output=True,
                          text=True, timeout=900, cwd=BENCHMARKS.parent)
    assert done.returncode == 0, done.stderr[-2000:]
    assert re.search(expected, done.stdout), done.stdout[-2000:]


@pytest.mark.parametrize("name", [n for n, (_, _, engine) in SMOKES.items() if not engine])
def test_reference_benchmark_runs_at_smallest_size(name):
    smoke(name)


@needs("liggghts")
@needs("yade")
@pytest.mark.parametrize("name", [n for n, (_, _, engine) in SMOKES.items() if engine is True])
def test_engine_benchmark_runs_at_smallest_size(name):
    smoke(name)


@needs("kratos")
def test_kratos_benchmark_runs_at_smallest_size():
    smoke("bench_kratos.py")
