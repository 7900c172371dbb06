"""`harness run --scene NAME` on the reference solver: each scene through the command, checks.csv's rows against
closed forms computed here (Newton's parabola, restitution e_n and e_n^(2k) h0 apex heights, Hertz's static overlap,
Routh's slip time and rolling speed, a column's i m g + P),
a check that must fail seen failing, and bad input as one line and exit 2."""
import dataclasses
import json
import math

import numpy as np
import pandas as pd
import pytest

from harness.commands import main

COLUMNS = ["check", "engine", "case", "quantity", "value", "expected", "error", "tolerance", "passed", "note"]
GLASS = ["--E", "70e9", "--nu", "0.3", "--rho", "2650"]
E, NU, RHO, G = 70e9, 0.3, 2650.0, 9.81


def scene_run(tmp_path, capfd, *args):
    """(exit code, stdout lines, checks.csv, series.csv) of `harness run ARGS -o tmp_path/out`."""
    out = tmp_path / "out"
    code = main(["run", *args, "-o", str(out)])
    lines = capfd.readouterr().out.splitlines()
    checks = pd.read_csv(out / "checks.csv") if (out / "checks.csv").exists() else None
    series = pd.read_csv(out / "series.csv") if (out / "series.csv").exists() else None
    return code, lines, checks, series


def test_free_fall_follows_the_parabola_to_1e_9(tmp_path, capfd):
    """A throw upwards from 0.5 m: the recorded heights are z0 + v0 t - g t^2/2 to 1e-9 and the check says so."""
    code, lines, checks, series = scene_run(
        tmp_path, capfd, "--model", "hertz-mindlin", "--scene", "free-fall", "--scene-param", "height=0.5",
        "--scene-param", "v0=1.5", "--scene-param", "duration=0.3", "--radius", "0.01", "--en", "0.5", *GLASS)
    assert code == 0, lines
    assert list(checks.columns) == COLUMNS
    assert list(series.columns) == ["engine", "case", "t", "body", "x", "z", "vx", "vz", "w"]
    assert set(series.engine) == {"reference"}
    t = series.t.to_numpy()
    assert t[0] == 0.0 and t[-1] == pytest.approx(0.3, rel=1e-12) and len(t) > 100
    assert series.z.to_numpy() == pytest.approx(0.5 + 1.5 * t - 0.5 * G * t * t, rel=1e-9)
    assert series.vz.to_numpy() == pytest.approx(1.5 - G * t, rel=1e-9, abs=1e-9)
    (row,) = checks.itertuples()
    when = float(row.case.split("t = ")[1].split(" s")[0])
    assert row.expected == pytest.approx(0.5 + 1.5 * when - 0.5 * G * when ** 2, rel=1e-6)
    assert row.error <= 1e-9 and row.passed and row.engine == "reference" and row.tolerance == 1e-9
    assert lines[0].startswith("passed height [e_n = 0.5, t = ") and lines[-1].endswith(str(tmp_path / "out"))


def bounce(tmp_path, capfd, steps_per_contact):
    return scene_run(tmp_path, capfd, "--model", "linear-spring-dashpot", "--with", "end=tension", "--scene", "bounce",
                     "--scene-param", "height=0.01", "--scene-param", "bounces=2", "--radius", "1e-4", "--en", "0.9",
                     "--steps-per-contact", str(steps_per_contact), *GLASS)


def test_bounce_rebounds_at_e_n_and_reaches_e_n_to_the_2k_of_the_drop(tmp_path, capfd):
    """A linear spring-dashpot ending at zero overlap, calibrated to e_n 0.9: each rebound speed ratio is 0.9 and the
    k-th apex 0.9^(2k) of the 1 cm drop, to the catalogue's 1e-3, less what gravity takes during the contact (g t_c / v
    ~ 1e-6 here: the closed form holds it, so it sits just below 0.9)."""
    code, lines, checks, _ = bounce(tmp_path, capfd, 1000)
    assert code == 0, lines
    ratios = checks[checks.check == "rebound-speed-ratio"]
    apexes = checks[checks.check == "apex-height"]
    assert list(ratios.case) == ["e_n = 0.9, bounce 1", "e_n = 0.9, bounce 2"]
    assert ratios.expected.to_numpy() == pytest.approx([0.9, 0.9], rel=3e-6)
    assert (ratios.expected.to_numpy() < 0.9).all()
    assert (np.abs(ratios.value.to_numpy() - 0.9) <= 1e-3).all()
    assert apexes.expected.to_numpy() == pytest.approx([0.9 ** 2 * 0.01, 0.9 ** 4 * 0.01], rel=1e-5)
    assert (np.abs(apexes.value.to_numpy() / apexes.expected.to_numpy() - 1.0) <= 1e-3).all()
    assert checks.passed.all()
    assert sum(line.startswith("passed ") for line in lines) == 4


def test_a_step_too_coarse_for_the_tolerance_fails_the_check_and_exits_1(tmp_path, capfd):
    """At 5 steps per contact the rebound ratio misses 0.9 by more than 1e-3: the rows say passed False."""
    code, lines, checks, _ = bounce(tmp_path, capfd, 5)
    ratios = checks[checks.check == "rebound-speed-ratio"]
    assert (np.abs(ratios.value - 0.9) > 1e-3).all()
    assert not checks.passed.any() and code == 1
    assert lines[0].startswith("FAILED rebound-speed-ratio [e_n = 0.9, bounce 1]")
    assert "0 of 4 checks passed" in lines[-1]


def hertz_overlap(radius):
    """delta = (3 m g/(4 E* sqrt(R)))^(2/3), E* = E/(2 (1 - nu^2)) for a sphere on a wall of its material."""
    mass = 4.0 / 3.0 * math.pi * radius ** 3 * RHO
    return (3.0 * mass * G / (4.0 * E / (2.0 * (1.0 - NU ** 2)) * math.sqrt(radius))) ** (2.0 / 3.0)


def test_rest_holds_hertz_static_overlap_and_json_says_so(tmp_path, capfd):
    code, lines, checks, _ = scene_run(
        tmp_path, capfd, "--model", "hertz-mindlin", "--scene", "rest", "--scene-param", "steps=2000",
        "--radius", "5e-3", "--en", "0.5", "--steps-per-contact", "20", "--json", *GLASS)
    assert code == 0
    printed = json.loads("\n".join(lines))
    assert printed["not_applicable"] == {"linear-static-overlap": "hertz-mindlin's normal force is hertz, not linear"}
    (row,) = printed["checks"]
    assert list(row) == COLUMNS
    assert row["expected"] == pytest.approx(hertz_overlap(5e-3), rel=1e-12)
    assert row["value"] == pytest.approx(hertz_overlap(5e-3), rel=1e-6)
    assert row["passed"] is True
    assert checks.to_dict(orient="records")[0]["value"] == row["value"]


def test_slide_to_roll_ends_its_slip_at_routh_s_time_and_speed(tmp_path, capfd):
    """Backspin w0 = -40 rad/s on a 5 mm sphere sliding at 1 m/s, mu 0.3: slip ends at 2 (v0 - R w0)/(7 mu g) with
    v = (5 v0 + 2 R w0)/7 (Routh); while it slides, v = v0 - mu g t in the series."""
    code, lines, checks, series = scene_run(
        tmp_path, capfd, "--model", "hertz-mindlin", "--scene", "slide-to-roll", "--scene-param", "w0=-40",
        "--radius", "5e-3", "--mu", "0.3", "--en", "0.5", "--steps-per-contact", "50", *GLASS)
    assert code == 0, lines
    t_s, v_f = 2.0 * (1.0 + 5e-3 * 40.0) / (7.0 * 0.3 * G), (5.0 - 2.0 * 5e-3 * 40.0) / 7.0
    rows = checks.set_index("check")
    assert rows.loc["slip-end-time", "expected"] == pytest.approx(t_s, rel=1e-12)
    assert rows.loc["rolling-speed", "expected"] == pytest.approx(v_f, rel=1e-12)
    assert rows.loc["slip-end-time", "value"] == pytest.approx(t_s, rel=1e-2)
    assert rows.loc["rolling-speed", "value"] == pytest.approx(v_f, rel=1e-2)
    assert checks.passed.all()
    sliding = series[series.t < 0.9 * t_s]
    assert sliding.vx.to_numpy() == pytest.approx(1.0 - 0.3 * G * sliding.t.to_numpy(), rel=1e-3)


@pytest.mark.parametrize("model, walls, preload", [("hertz-mindlin", 1, 0.0), ("linear-spring-dashpot", 2, 0.5)])
def test_a_stack_carries_i_m_g_and_the_preload_below_the_ith_sphere(tmp_path, capfd, model, walls, preload):
    """Three 5 mm glass spheres in a column: the contact below the i-th from the top carries i m g, plus the top
    wall's preload P between two walls (statics)."""
    code, lines, checks, series = scene_run(
        tmp_path, capfd, "--model", model, "--scene", "stack", "--scene-param", f"walls={walls}",
        "--scene-param", f"preload={preload}", "--radius", "5e-3", "--en", "0.5", "--steps-per-contact", "50", *GLASS)
    assert code == 0, lines
    weight = 4.0 / 3.0 * math.pi * 5e-3 ** 3 * RHO * G
    expected = [i * weight + preload for i in (1, 2, 3)]
    assert list(checks.case) == [f"e_n = 0.5, below sphere {i} from the top" for i in (1, 2, 3)]
    assert checks.expected.to_numpy() == pytest.approx(expected, rel=1e-12)
    assert checks.value.to_numpy() == pytest.approx(expected, rel=1e-3)
    assert checks.passed.all() and sorted(set(series.body)) == [0, 1, 2]


def test_a_wrong_closed_form_flips_passed(tmp_path):
    """The same rest run, measured against a closed form 1% off, fails; against the catalogue's, passes."""
    from harness.api.scene_requests import scene_request
    from harness.studies.scenes import run_scene
    request, kind, values = scene_request("hertz-mindlin", "rest", {"steps": 100}, en=[0.5], radius=5e-3, E=E,
                                          nu=NU, rho=RHO, steps_per_contact=20)
    right = run_scene(request.law, kind, values, request.scene, request.resolution)
    hertz = kind.CHECKS[0]
    off = dataclasses.replace(hertz, closed_form=lambda **given: 1.01 * hertz.closed_form(**given))
    wrong = run_scene(request.law, dataclasses.replace(kind, CHECKS=(off,)), values, request.scene,
                      request.resolution)
    assert right.checks.passed.tolist() == [True] and wrong.checks.passed.tolist() == [False]
    assert wrong.checks.error[0] == pytest.approx(1.0 - 1.0 / 1.01, rel=1e-4)


def test_the_python_api_runs_a_scene_as_the_command_does():
    import harness
    done = harness.run("hertz-mindlin", scene="free-fall", scene_params={"height": 0.5, "duration": 0.05},
                       en=[0.5], radius=0.01)
    assert done.checks.passed.tolist() == [True]
    assert done.series.z.iloc[-1] == pytest.approx(0.5 - 0.5 * G * 0.05 ** 2, rel=1e-9)
    assert repr(done) == "SceneRun(free-fall: 1 of 1 checks passed; .series 201 rows, .checks)"


@pytest.mark.parametrize("args, says", [
    (["--scene", "nope"], "unknown scene 'nope'"),
    (["--scene", "stack", "--scene-param", "preload=1"], "scene stack: preload = 1.0 needs walls = 2"),
    (["--scene", "bounce", "--scene-param", "bounces=abc"], "scene bounce: bounces = 'abc' is not an integer"),
    (["--scene", "bounce", "--scene-param", "bounces=0"], "scene bounce: bounces = 0 is not an integer >= 1"),
    (["--scene", "bounce", "--scene-param", "colour=red"], "scene bounce has no parameter colour"),
    (["--scene", "bounce", "--scene-param", "height"], "--scene-param expects KEY=VALUE"),
    (["--scene", "bounce", "--angles", "10"], "--angles describes the impact scene"),
    (["--scene", "rest", "--gravity", "9.81"], "scene rest takes --scene-param g"),
    (["--scene", "rest", "--en", "1"], "scene rest settles the sphere with the law's damping"),
    (["--model", "thornton", "--scene", "rest"], "laws with a Hertz or linear normal force; thornton's is thornton"),
    (["--scene", "free-fall", "--scene-param", "height=0.02"], "scene free-fall: the sphere (radius 0.025 m) reaches"),
    (["--scene", "free-fall", "--converged"], "take --steps-per-contact or --dt, not --converged"),
    (["--scene", "slide-to-roll", "--mu", "0"], "scene slide-to-roll ends its slip by friction: give --mu above 0"),
    (["--scene", "slide-to-roll", "--scene-param", "w0=40"], "v0 = R w0 (1 m/s) rolls from the start"),
    (["--scene-param", "target=sphere"], "scene impact takes its own options"),
    (["--json"], "--json prints a scene's checks"),
])
def test_bad_scene_input_is_one_line_and_exit_2(tmp_path, capfd, args, says):
    model = [] if "--model" in args else ["--model", "hertz-mindlin"]
    code = main(["run", *model, *args, "-o", str(tmp_path / "out")])
    err = capfd.readouterr().err
    assert code == 2, err
    assert err.startswith("harness: error: ") and says in err and len(err.strip().splitlines()) == 1, err
    assert list(tmp_path.iterdir()) == []


def test_a_scene_no_command_runs_is_one_line_and_exit_2(tmp_path, capfd, monkeypatch):
    from harness.scenes import catalogue
    monkeypatch.setitem(catalogue.SCENES, "stack", dataclasses.replace(catalogue.SCENES["stack"], RUNS=False))
    code = main(["run", "--model", "hertz-mindlin", "--scene", "stack", "-o", str(tmp_path / "out")])
    err = capfd.readouterr().err
    assert code == 2 and err == "harness: error: scene stack is described (harness scenes) but no command runs it yet\n"
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("engines, says", [
    ("liggghts", "compare runs the impact scene: `harness run --scene bounce --engines ...`"),
    ("reference", "compare runs the impact scene: `harness run --scene bounce --engines ...`"),
])
def test_compare_refuses_a_scene_in_one_line(tmp_path, capfd, engines, says):
    code = main(["compare", "--model", "hertz-mindlin", "--scene", "bounce", "--engines", engines,
                 "-o", str(tmp_path / "out")])
    err = capfd.readouterr().err
    assert code == 2 and err.startswith(f"harness: error: {says}") and len(err.strip().splitlines()) == 1, err
    assert list(tmp_path.iterdir()) == []
