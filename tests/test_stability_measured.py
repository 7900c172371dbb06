"""The largest stable time step, measured by bisection (harness stability), against the central-difference bound of
an oscillator: 2/w undamped, 2/w (sqrt(1 + z^2) - z) damped (Belytschko, Liu & Moran, Nonlinear Finite Elements,
the central-difference bound), a Hertz contact's at its peak stiffness; an engine against its dialect."""
import json
import math
import subprocess
import sys

import pandas as pd
import pytest

from conftest import needs
from test_stability import duration_k

from harness.engines import get_engine
from harness.laws import compose
from harness.scenes.catalogue import scene_kind
from harness.scenes.scene import Scene
from harness.studies.hard_cases import BASE_SCENE, get_case
from harness.analyses.stability import DRIFT, Probe, scene_probe, verdict
from harness.studies.stability import (PRECISION, Runner, bisect, contact_time_of, estimate_of, impact_cases,
                                       measure, run_case, scene_cases)

HELD = 20000                # steps a resting sphere is held: instability above the bound grows far beyond them
HERTZ_FACTOR = 1.25         # the Hertz stiffness moves over each oscillation and its dashpot lowers the bound


def resting(model, e_n):
    """(case, law): a sphere of the hard cases' material resting on the wall at target e_n, held HELD steps."""
    kind = scene_kind("rest")
    scene = Scene(**BASE_SCENE, e_n=(e_n,), angles_deg=(0.0,))
    return scene_cases(kind, kind.values({"steps": HELD}), scene, (e_n,))[0], compose(model)


def measured(case, law):
    """The bisection's Bracket of the reference running `law` on `case`."""
    return bisect(lambda dt: run_case(case, Runner("reference", law), dt), estimate_of(case, law),
                  ceiling=contact_time_of(case, law))


def sphere_mass(scene):
    return 4.0 / 3.0 * math.pi * scene.radius ** 3 * scene.rho


@pytest.mark.parametrize("start", [1e-3, 0.37, 50.0])
def test_the_bisection_brackets_a_known_threshold_to_its_precision(start):
    """A test that passes exactly below 0.37: from below, at it and from above, the bracket holds 0.37 and is at
    most PRECISION wide; a threshold beyond SEARCH doublings (2^12) leaves the bracket open."""
    bracket = bisect(lambda dt: Probe(dt, dt <= 0.37, ""), start)
    assert bracket.stable.dt <= 0.37 < bracket.unstable.dt <= bracket.stable.dt * (1.0 + PRECISION)
    assert bisect(lambda dt: Probe(dt, dt <= 0.37, ""), 1e-6).unstable is None


def test_a_drifting_rest_or_a_gain_is_unstable_and_a_gain_inside_the_bracket_fails_the_verdict():
    """A resting overlap moving by more than DRIFT of itself, or an energy gain beyond round-off, is not stable; one
    such probe below the stable step fails the verdict."""
    assert scene_probe(1e-6, True, 0.0, 1.0, 0.5 * DRIFT).passed
    assert not scene_probe(1e-6, True, 0.0, 1.0, 2.0 * DRIFT).passed
    assert not scene_probe(1e-6, True, 1e-6, 1.0).passed
    assert not scene_probe(1e-6, False, 0.0, 1.0).passed
    stable, gaining = Probe(2e-6, True, ""), scene_probe(1e-6, True, 1e-6, 1.0)
    assert verdict([stable], None)[0] == "pass"
    assert verdict([stable, gaining], None)[0] == "fail"


def test_a_nearly_undamped_linear_spring_is_stable_up_to_two_over_omega():
    """Linear spring, e_n 0.999 (z = 3e-4): the measured step within the bisection's precision of 2 sqrt(m/k), k the
    paper's linear spring from the Hertz contact time (independent of harness)."""
    case, law = resting("linear-spring-dashpot", 0.999)
    m = sphere_mass(case.scene)
    bound = 2.0 * math.sqrt(m / duration_k(case.scene.contact, case.scene.speed))
    bracket = measured(case, law)
    assert bracket.unstable.dt <= bracket.stable.dt * (1.0 + PRECISION)
    assert abs(bracket.stable.dt - bound) <= PRECISION * bound, (bracket.stable.dt, bound)


def test_a_damped_linear_spring_is_stable_up_to_the_central_difference_bound():
    """Linear spring-dashpot, e_n 0.9: z = -ln e / sqrt(pi^2 + ln^2 e) (the exact calibration), the bound
    2/w (sqrt(1 + z^2) - z) 3.4% below 2/w lies inside the bracket, which 2/w does not."""
    case, law = resting("linear-spring-dashpot", 0.9)
    m = sphere_mass(case.scene)
    w = math.sqrt(duration_k(case.scene.contact, case.scene.speed) / m)
    log_e = math.log(0.9)
    z = -log_e / math.sqrt(math.pi ** 2 + log_e ** 2)
    bound = 2.0 / w * (math.sqrt(1.0 + z * z) - z)
    bracket = measured(case, law)
    assert bracket.stable.dt <= bound <= bracket.unstable.dt * (1.0 + 1e-9), (bracket, bound)
    assert bracket.unstable.dt < 2.0 / w


def test_a_hertz_contact_is_stable_up_to_the_bound_at_its_peak_stiffness():
    """Hertz, e_n 0.9, resting: k = 3/2 (4/3 E* sqrt(R)) delta_max^1/2 at the deepest overlap, that of the drop
    from touching at rest (m g delta = 8/15 E* sqrt(R) delta^5/2); the measured step at most the bisection's
    precision above 2 sqrt(m/k) and within HERTZ_FACTOR below it."""
    case, law = resting("hertz-mindlin", 0.9)
    scene, m, g = case.scene, sphere_mass(case.scene), case.values["g"]
    e_star = scene.E / (2.0 * (1.0 - scene.nu ** 2))
    delta = (15.0 * m * g / (8.0 * e_star * math.sqrt(scene.radius))) ** (2.0 / 3.0)
    bound = 2.0 * math.sqrt(m / (1.5 * 4.0 / 3.0 * e_star * math.sqrt(scene.radius) * math.sqrt(delta)))
    bracket = measured(case, law)
    assert bound / HERTZ_FACTOR <= bracket.stable.dt <= bound * (1.0 + PRECISION), (bracket.stable.dt, bound)


def test_an_energy_gain_inside_the_stable_bracket_fails_the_verdict():
    """LIGGGHTS' Hertz dialect at e_n 1 gains energy at every practical step (first order): 20% of the Rayleigh time
    gains it, and the verdict says so."""
    law = compose("hertz-mindlin")
    dialect = get_engine("liggghts").dialect(law.name, {}, "wall")
    case = impact_cases([get_case("exactly normal")], law, (1.0,))[0]
    row = measure(case, Runner("reference", dialect), accurate=(math.nan, "not asked"))
    assert not row["rayleigh_20_stable"]
    assert row["dt_stable"] < row["dt_rayleigh_20"]
    assert row["verdict"] == "fail" and "Rayleigh" in row["verdict_note"]


@needs("lammps")
def test_lammps_is_stable_up_to_the_step_of_its_dialect_on_the_reference():
    """LAMMPS hertz/material on 'mu = 2' at e_n 0.5: its measured stable step within the bisection's precision of
    its dialect's on the reference (the engine runs at each probed step, above its law's limit too)."""
    law = compose("hertz-mindlin")
    engine = get_engine("lammps")
    dialect = engine.dialect(law.name, {}, "wall")
    case = impact_cases([get_case("mu = 2")], law, (0.5,))[0]
    given = (math.nan, "not asked")
    on_reference = measure(case, Runner("reference", dialect), given)
    in_engine = measure(case, Runner(engine.NAME, dialect, engine), given)
    assert on_reference["dt_unstable"] <= on_reference["dt_stable"] * (1.0 + PRECISION)
    assert abs(in_engine["dt_stable"] - on_reference["dt_stable"]) <= PRECISION * on_reference["dt_stable"]
    assert in_engine["dt_stable"] > estimate_of(case, dialect)       # found above the estimate it started from


def harness(*args):
    return subprocess.run([sys.executable, "-m", "harness", "stability", *args], capture_output=True, text=True,
                          timeout=600)


@pytest.mark.parametrize("args", [
    ["--model", "hertz-mindlin", "--case", "no such case"],
    ["--model", "hertz-mindlin", "--scene", "rest", "--case", "mu = 2"],
    ["--model", "hertz-mindlin", "--scene-param", "steps=10"],
    ["--model", "hertz-mindlin", "--scene", "rest", "--engines", "lammps"],
    ["--model", "hertz-mindlin", "--case", "thornton e_n 0.05"],
    ["--model", "hertz-mindlin", "--engines", "no-such-engine"],
])
def test_bad_input_is_one_line_and_exit_2(args, tmp_path):
    proc = harness(*args, "-o", str(tmp_path / "out"))
    assert proc.returncode == 2, proc.stderr
    assert len(proc.stderr.strip().splitlines()) == 1 and "Traceback" not in proc.stderr


def test_a_named_engine_that_is_missing_is_exit_3_and_the_reference_still_runs(tmp_path):
    import os
    env = {**os.environ, "HARNESS_LAMMPS": str(tmp_path / "no-such-lmp")}
    proc = subprocess.run([sys.executable, "-m", "harness", "stability", "--model", "linear-spring-dashpot",
                           "--case", "mu = 2", "--en", "0.5", "--engines", "lammps", "--json", "-o",
                           str(tmp_path / "out")], capture_output=True, text=True, timeout=600, env=env)
    assert proc.returncode == 3, proc.stderr
    summary = json.loads(proc.stdout)
    assert summary["could_not_run"] == ["lammps"]
    assert [row["engine"] for row in summary["rows"]] == ["reference"]
    assert (tmp_path / "out" / "stability.csv").is_file()


def test_an_engine_that_fails_every_run_exits_3_with_its_log_tail(tmp_path, monkeypatch, capfd):
    """A LIGGGHTS that fails every run (a stand-in script: a crash cannot be had from the real one on demand): no
    stable step, its log tail on stderr and in stability.csv, exit 3; the reference's row is kept."""
    from conftest import fake_executable
    from harness.commands import main
    from harness.engines import liggghts
    monkeypatch.setenv(liggghts.BINARY_VARIABLE, fake_executable(tmp_path, 'echo "ERROR: out of cheese"; exit 1'))
    out = tmp_path / "s"
    assert main(["stability", "--model", "hertz-mindlin", "--case", "mu = 2", "--en", "0.5", "--engines", "liggghts",
                 "-o", str(out)]) == 3
    said = capfd.readouterr()
    assert "out of cheese" in said.err
    table = pd.read_csv(out / "stability.csv")
    assert list(table.engine) == ["reference", "reference", "liggghts"]
    crashed = table.iloc[-1]
    assert math.isnan(crashed.dt_stable) and "out of cheese" in crashed.log_tail and crashed.verdict == "fail"
