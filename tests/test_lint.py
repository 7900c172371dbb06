"""The code is linted by ruff (pycodestyle's errors and warnings, lines within 120 columns, and pyflakes: unused
imports and names, undefined names), as pyproject.toml configures it, over the package, the tests, the tools and the
benchmarks."""
import pathlib
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent


def test_ruff_finds_nothing():
    done = subprocess.run([sys.executable, "-m", "ruff", "check", "--no-cache", "--output-format", "concise",
                           "harness", "tests", "tools", "benchmarks"], cwd=ROOT, capture_output=True, text=True,
                          timeout=300)
    assert done.returncode == 0, done.stdout[-4000:] + done.stderr[-2000:]


def test_ruff_sees_a_long_line(tmp_path):
    """The check can fail: a line of 121 columns in a scratch module is reported under the project's settings."""
    (tmp_path / "long.py").write_text("x = '" + "a" * 115 + "'\n")
    done = subprocess.run([sys.executable, "-m", "ruff", "check", "--no-cache", "--config",
                           str(ROOT / "pyproject.toml"), str(tmp_path / "long.py")],
                          capture_output=True, text=True, timeout=300)
    assert done.returncode == 1 and "E501" in done.stdout, done.stdout + done.stderr
