"""Start-up and first use: the commands that do no physics import none of its libraries, numba's cache lives under
the user's own cache directory, `harness compile` fills it so that a later run compiles nothing, and the time left a
progress line promises leaves out the time spent compiling."""
import io
import json
import os
import subprocess
import sys

import pytest

from harness.commands import COMMANDS
from harness.views.progress import Progress

HEAVY = ("numba", "pandas", "matplotlib", "scipy", "dask")
PROBE = """
import json, sys
from harness.commands import main
try:
    code = main({argv!r})
except SystemExit as exc:
    code = exc.code
print(json.dumps([code, sorted(m for m in sys.modules if m.split('.')[0] in {heavy!r} or m.startswith('harness.'))]),
      file=sys.stderr)
"""


def imported(argv, tmp_path):
    """(exit code, the heavy libraries and harness modules imported) of `harness ARGV` in a fresh interpreter."""
    done = subprocess.run([sys.executable, "-c", PROBE.format(argv=argv, heavy=HEAVY)], capture_output=True,
                          text=True, cwd=tmp_path, timeout=300)
    code, modules = json.loads(done.stderr.strip().splitlines()[-1])
    return code, modules


@pytest.mark.parametrize("argv", [["--help"], ["--version"], ["nosuch"], ["run", "--model", "thornton", "--speed",
                                                                            "abc", "-o", "r.csv"]])
def test_help_version_and_a_refused_option_import_no_library_of_the_physics(argv, tmp_path):
    code, modules = imported(argv, tmp_path)
    assert code in (0, 2)
    assert not [m for m in modules if m.split(".")[0] in HEAVY + ("numpy",)], modules


@pytest.mark.parametrize("argv", [["models"], ["scenes"], ["engines"], ["run", "--model", "nosuch", "-o", "r.csv"],
                                  ["compare", "--model", "nosuch"], ["compile", "--laws", "nosuch"]])
def test_listing_and_an_unknown_law_load_no_kernel_table_or_plot(argv, tmp_path):
    """The laws' names and labels come from their registration table: no compiled kernel (numba), no table
    (pandas), no plotting, no solver."""
    code, modules = imported(argv, tmp_path)
    assert code == (2 if "nosuch" in argv else 0)
    assert not [m for m in modules if m.split(".")[0] in HEAVY], modules
    assert not [m for m in modules if m in ("harness.runs.plan", "harness.solver.batch", "harness.api.requests",
                                            "harness.laws.named")], modules


@pytest.mark.parametrize("command", ["compare", "run", "cost", "calibrate", "paper", "benchmark", "campaign", "check",
                                     "baseline", "render", "report", "query", "compile", "models", "scenes", "engines",
                                     "cite", "stability"])
def test_a_commands_help_imports_none_of_its_implementation(command, tmp_path):
    code, modules = imported([command, "--help"], tmp_path)
    assert code == 0
    assert not [m for m in modules if m.split(".")[0] in HEAVY], modules
    implementation = COMMANDS[command][0]
    assert f"harness.commands.{implementation}" not in modules, modules


def test_models_prints_the_composed_laws():
    """What `harness models --json` prints from the table is what the composed laws (their sub-models) describe."""
    from harness.laws import LAWS
    done = subprocess.run([sys.executable, "-m", "harness", "models", "--json"], capture_output=True, text=True,
                          timeout=300, check=True)
    printed = json.loads(done.stdout)
    assert [law["name"] for law in printed] == list(LAWS)
    assert [(law["summary"], law["provisional"], law["submodels"]) for law in printed] == [
        (law.summary, law.provisional, law.describe()) for law in LAWS.values()]


def test_a_table_that_misnames_a_composed_law_is_refused(monkeypatch):
    import dataclasses

    from harness.laws import LAWS, named
    wrong = dataclasses.replace(named.TABLE["thornton"], tangential="mindlin(total)")
    monkeypatch.setitem(named.TABLE, "thornton", wrong)
    with pytest.raises(ImportError, match="thornton"):
        named.check_table(LAWS)


def test_every_command_is_listed_and_its_module_builds_it():
    """The full parser (every module's parser) holds exactly the commands listed, each with its own options."""
    from harness.commands import COMMANDS, build_parser
    full = build_parser()
    commands = next(a for a in full._actions if a.dest == "command").choices
    assert list(commands) == list(COMMANDS)
    assert all(any(a.option_strings == ["-h", "--help"] for a in commands[name]._actions) for name in COMMANDS)
    assert build_parser({"run"}).parse_args(["run", "--model", "thornton", "-o", "r.csv"]).model == "thornton"


def cache_directory(env):
    """numba's cache directory as harness sets it, in a fresh interpreter with `env`."""
    code = "import harness.infra.jit, numba; print(numba.config.CACHE_DIR)"
    return subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True,
                          check=True).stdout.strip()


def test_the_numba_cache_is_the_users_own(tmp_path):
    base = {k: v for k, v in os.environ.items() if k not in ("NUMBA_CACHE_DIR", "XDG_CACHE_HOME", "HOME")}
    alice, bob, xdg = tmp_path / "alice", tmp_path / "bob", tmp_path / "xdg"
    for_alice = cache_directory({**base, "HOME": str(alice)})
    for_bob = cache_directory({**base, "HOME": str(bob)})
    assert for_alice.startswith(str(alice / ".cache" / "harness" / "numba") + os.sep)
    assert for_bob.startswith(str(bob / ".cache" / "harness" / "numba") + os.sep)
    assert cache_directory({**base, "HOME": str(alice), "XDG_CACHE_HOME": str(xdg)}).startswith(
        str(xdg / "harness" / "numba") + os.sep)
    assert cache_directory({**base, "HOME": str(alice), "NUMBA_CACHE_DIR": str(tmp_path / "own")}).startswith(
        str(tmp_path / "own") + os.sep)


def harness(*args, cache):
    return subprocess.run([sys.executable, "-m", "harness", *args], capture_output=True, text=True, timeout=900,
                          env={**os.environ, "NUMBA_CACHE_DIR": str(cache)}, cwd=cache.parent)


def test_compile_ahead_of_time_leaves_nothing_for_a_first_run_to_compile(tmp_path):
    cache = tmp_path / "cache"
    compiled = harness("compile", "--laws", "linear-spring-dashpot", cache=cache)
    assert compiled.returncode == 0, compiled.stderr
    assert "compiling the paper integrator" in compiled.stderr and "compiled 1 law in" in compiled.stdout
    first = harness("run", "--model", "linear-spring-dashpot", "--en", "0.5", "--angles", "10,60", "-o",
                    str(tmp_path / "r.csv"), cache=cache)
    assert first.returncode == 0, first.stderr
    assert "compiling" not in first.stderr
    again = harness("compile", "--laws", "linear-spring-dashpot", cache=cache)
    assert again.returncode == 0 and "(0 s compiling" in again.stdout, again.stdout


def test_compile_refuses_an_unknown_law_in_one_line(tmp_path):
    done = harness("compile", "--laws", "nosuch", cache=tmp_path / "cache")
    assert done.returncode == 2 and done.stderr.startswith("harness: error: unknown law 'nosuch'")


class Log(io.StringIO):
    def isatty(self):
        return False


def lines_of(steps, total):
    """The progress lines of `total` steps done at the (clock, seconds compiling so far) of `steps`."""
    times = iter([(0.0, 0.0)] + steps)
    now = [None]

    def clock():
        now[0] = next(times)
        return now[0][0]
    log = Log()
    progress = Progress("paper", stream=log, clock=clock, compiling=lambda: now[0][1])
    progress.expect(total)
    for k in range(len(steps)):
        progress.advance(f"step {k + 1}")
    return log.getvalue().splitlines()


def test_the_first_estimate_leaves_the_compile_out_of_the_rate():
    """A cold run: 9 steps of 2 s each, the first also compiling for 95 s. After it, 8 steps of 2 s are left: 16 s,
    not the 8 x 97 s that extrapolating the first step's time would promise."""
    first = lines_of([(97.0, 95.0)], 9)[0]
    assert "97.0 s (95 s of it compiling, first use only), about 16 s left" in first, first


def test_without_compiling_the_estimate_is_the_rate_of_the_steps_done():
    lines = lines_of([(3.0, 0.0), (6.0, 0.0)], 4)
    assert lines[0].endswith("3.0 s, about 9 s left: step 1") and lines[1].endswith("6.0 s, about 6 s left: step 2")


def test_the_compile_clock_counts_numba_compiling():
    from numba import njit

    from harness.infra.compiling import spent
    import harness.solver.compile_notice  # noqa: F401  (its clock listens to numba's compile events)
    before = spent()
    njit(lambda x: x * 2.0 + 1.0)(3.0)
    assert spent() > before
