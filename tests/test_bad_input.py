"""The catalogue of bad input, by category: every case ends in exit code 2, one line on stderr naming the problem,
no traceback, and no file written. Physically meaningless results that do run get a status other than ok."""
import os
from pathlib import Path

import numpy as np
import pytest

from harness.commands import main

SCENE = ["--en", "0.5", "--angles", "10"]

NOT_NUMBERS = ["nan", "inf", "-inf", "abc", "", "1e", "0x10", "1,2,"]
NUMBERS = {   # option -> values outside its physical range (the bound is named in the message) or subnormal
    "--speed": ["0", "-1", "1e-300", "1e-7", "1e300", "3000", "5e-324"],
    "--normal-speed": ["0", "-5", "1e-300", "1e6", "5e-324"],
    "--radius": ["0", "-0.01", "1e-320", "1e-9", "1e300", "100"],
    "--E": ["0", "-1e9", "1e-300", "10", "1e300", "1e15", "5e-324"],
    "--nu": ["0.5", "0.6", "-1", "-2", "1e300", "5e-324", "-1e-310"],
    "--rho": ["0", "-2650", "1e-3", "1e300", "1e7", "3.1e6", "1e-320"],
    "--mu": ["-0.1", "-1e300", "1e300", "20", "5e-324"],
    "--gravity": ["-9.81", "1e30", "1e5", "5e-324"],
    "--omega0": ["1e300", "-1e300", "1e6", "-1e6", "1e-310"],
    "--dt": ["0", "-1e-6", "1e-30", "1e-300", "5e-324"],
    "--steps-per-contact": ["0", "-5", "1.5", "1e9", "1000000000"],
    "--gap": ["-1e-6", "-1", "1e300", "0.3", "5e-324"],
}
LISTS = {
    "--en": ["0", "-0.5", "1.5", "2", "1e-320", "0.5,,0.9", "0.5,abc", "0.5,nan", ",", "5e-324", "0.5,5e-324",
             "1e-4", "0.0009"],
    "--angles": ["90", "-10", "100", "0:90:0", "10:0:5", "0:80", "a:b:c", "nan", "1e300", "0:80:-10", "0:80:5e-324",
                 "0:80:1e-300", "0:80:inf", "0:80:100", "1e-320", "10,1e-320"],
    "--vt": ["-1", "1e300", "nan", "abc", "5000", "5e-324"],
    "--psi": ["-1", "1e300", "nan", "abc", "5e-324"],
    "--at-times": ["-1e-5", "2e-5,1e-5", "1e-5,1e-5", "1e-5,,2e-5", "1e-5,abc"],
}
CHOICES = [   # (extra arguments, what is wrong)
    (["--model", "no-such-law"], "unknown law"),
    (["--model", "thornton", "--with", "normal=nonsense"], "unknown sub-model"),
    (["--model", "thornton", "--with", "nonsense=hertz"], "unknown key"),
    (["--model", "thornton", "--with", "end=tension", "--with", "end=no-tension"], "repeated --with"),
    (["--model", "thornton", "--with", "end"], "no value"),
    (["--model", "hertz-mindlin", "--with", "tangential-damping=normal-ratio:heavy"], "unknown dashpot option"),
    (["--model", "thornton", "--material", "unobtainium"], "unknown material"),
    (["--model", "thornton", "--wall", "jelly"], "unknown wall"),
    (["--model", "thornton", "--speed", "5", "--normal-speed", "5"], "two speeds"),
    (["--model", "thornton", "--psi", "1", "--vt", "1"], "two sweeps"),
    (["--model", "thornton", "--mu", "0", "--psi", "1"], "Psi1* at mu 0"),
    (["--model", "thornton", "--dt", "1e-7", "--steps-per-contact", "100"], "two resolutions"),
    (["--model", "thornton", "--dt", "1e-7", "--converged"], "two resolutions"),
    (["--model", "hertz-kuwabara-kono", "--en", "0.003"], "below the calibration"),
    (["--model", "thornton", "--dt", "1e-3"], "unstable time step"),
    (["--model", "thornton", "--en", "0.5", "--angles", "10", "--bogus"], "unknown option"),
    (["--model", "thornton", "--target", "cube"], "unknown target"),
    (["--model", "thornton", "--target-radius", "0.01"], "a target sphere's option without --target sphere"),
    (["--model", "thornton", "--target-fixed"], "a target sphere's option without --target sphere"),
    (["--model", "thornton", "--target", "sphere", "--target-radius", "0"], "target radius 0"),
    (["--model", "thornton", "--target", "sphere", "--target-material", "E=1e9,nu=0.3"], "target material without rho"),
    (["--model", "thornton", "--target", "sphere", "--target-material", "E=1e9,nu=0.7,rho=1000"], "target nu"),
    (["--model", "thornton", "--target", "sphere", "--target-material", "jelly"], "unknown target material"),
    (["--model", "thornton", "--target", "sphere", "--wall", "rigid"], "a wall for a sphere target"),
    (["--model", "thornton", "--target", "sphere", "--target-fixed", "--target-omega", "3"], "a fixed target spins"),
    (["--model", "thornton", "--target", "sphere", "--target-material", "E=1e9,nu=0.3,rho=1e7"], "target rho"),
    (["--model", "thornton", "--target", "sphere", "--target-material", "E=1e9,nu=0.3,rho=3.1e6"], "target rho"),
    (["--model", "thornton", "--target", "sphere", "--target-radius", "1e-320"], "target radius subnormal"),
    (["--model", "thornton", "--target", "sphere", "--target-radius", "1e308"], "target radius overflows"),
    (["--model", "thornton", "--target", "sphere", "--target-radius", "2e4"], "target radius beyond 1e4 m"),
    (["--model", "thornton", "--target", "sphere", "--target-radius", "1e-8"], "target radius below 1e-7 m"),
    (["--model", "thornton", "--target", "sphere", "--target-material", "E=5e-324,nu=0.3,rho=1000"], "target E"),
    (["--model", "thornton", "--target", "sphere", "--target-material", "E=1e308,nu=0.3,rho=1000"], "target E"),
    (["--model", "thornton", "--target", "sphere", "--target-material", "E=2e14,nu=0.3,rho=1000"], "target E"),
    (["--model", "thornton", "--target", "sphere", "--target-material", "E=10,nu=0.3,rho=1000"], "target E"),
    (["--model", "thornton", "--target", "sphere", "--target-material", "E=inf,nu=0.3,rho=1000"], "target E"),
    (["--model", "thornton", "--target", "sphere", "--target-material", "E=1e9,nu=0.3,rho=5e-324"], "target rho"),
    (["--model", "thornton", "--target", "sphere", "--target-material", "E=1e9,nu=1e-310,rho=1000"], "target nu"),
    (["--model", "thornton", "--target", "sphere", "--target-omega", "5e-324"], "target spin subnormal"),
    (["--model", "thornton", "--target", "sphere", "--target-omega", "1e300"], "target spin beyond 1e3 m/s"),
    (["--model", "hertz-mindlin", "--wall", "E=5e-324,nu=0.3"], "wall E subnormal"),
    (["--model", "hertz-mindlin", "--wall", "E=1e308,nu=0.3"], "wall E overflows"),
    (["--model", "hertz-mindlin", "--wall", "E=2e14,nu=0.3"], "wall E beyond 1e14 Pa"),
    (["--model", "hertz-mindlin", "--wall", "E=1e-5,nu=0.3"], "wall E below 1e3 Pa"),
    (["--model", "hertz-mindlin", "--wall", "E=2e11,nu=-5e-324"], "wall nu subnormal"),
    (["--model", "thornton", "--normal-speed", "5", "--angles", "89.9"], "V_n tan(angle) beyond 1e3 m/s"),
    (["--model", "thornton", "--normal-speed", "600", "--angles", "0,30,60"], "V_n tan(angle) beyond 1e3 m/s"),
    (["--model", "thornton", "--gap", "1e-4", "--converged"], "a gap counts fixed steps"),
    (["--model", "thornton", "--at-times", "1e-5", "--converged"], "states count fixed steps"),
    (["--model"], "missing value"),
    ([], "no model"),
]


def cases():
    for option, values in NUMBERS.items():
        for value in values + NOT_NUMBERS:
            yield pytest.param(["--model", "thornton", *SCENE, f"{option}={value}"], id=f"{option}={value}")
    for option, values in LISTS.items():
        scene = [] if option == "--en" else ["--en", "0.5"]
        for value in values + NOT_NUMBERS[:4]:
            yield pytest.param(["--model", "thornton", *scene, f"{option}={value}"], id=f"{option}={value}")
    for arguments, why in CHOICES:
        yield pytest.param(arguments, id=why + " " + " ".join(arguments))


CATALOGUE = list(cases())
# compare validates through the same request as run: a sample of each category, every choice
SAMPLE = [case for case in CATALOGUE if case.id.endswith("=nan") or case.id.endswith("=0") or " " in case.id]


# engines and their options, which only compare takes: each refused rather than read one way in silence
ENGINES = [
    (["--engines", "liggghts,liggghts"], "an engine named twice"),
    (["--engines", "reference,reference"], "the reference named twice"),
    (["--engines", "liggghts,"], "a trailing comma"),
    (["--engines", ",liggghts"], "a leading comma"),
    (["--engines", "liggghts,,yade"], "an empty item"),
    (["--engines", ","], "no engine"),
    (["--engines", "reference", "--engine-option", "reference:foo=bar"], "an option for the reference"),
    (["--engines", "reference,liggghts", "--engine-option", "reference:precision=double"], "the reference's option"),
    (["--engines", "yade", "--engine-option", "liggghts:limitForce=on"], "an option for an engine not asked for"),
    (["--engines", "liggghts", "--engine-option", "liggghts:limitForce=maybe"], "an undeclared value"),
    (["--engines", "liggghts", "--engine-option", "liggghts:nope=on"], "an undeclared key"),
    (["--engines", "liggghts", "--engine-option", "liggghts:limitForce=on",
      "--engine-option", "liggghts:limitForce=off"], "a key given twice"),
    (["--engines", "LIGGGHTS"], "an unknown engine"),
    (["--engines", "reference", "--store", ""], "an empty store path"),
]


def test_the_catalogue_is_large():
    assert len(CATALOGUE) >= 250 and len(SAMPLE) >= 70


@pytest.mark.parametrize("command, arguments", [pytest.param(command, case.values[0], id=f"{command} {case.id}")
                                                for command, cases_ in (("run", CATALOGUE), ("compare", SAMPLE))
                                                for case in cases_] +
                         [pytest.param("compare", ["--model", "hertz-mindlin", *SCENE, *arguments], id=f"compare {why}")
                          for arguments, why in ENGINES])
def test_bad_input_is_refused_in_one_line(tmp_path, capfd, command, arguments):
    out_path = tmp_path / ("out.csv" if command == "run" else "out")
    extra = ["--engines", "reference"] if command == "compare" and "--model" in arguments[:1] and \
        "--engines" not in arguments else []
    code = main([command, *arguments, *extra, "-o", str(out_path)])
    out, err = capfd.readouterr()
    lines = err.strip().splitlines()
    assert code == 2, (out, err)
    assert len(lines) == 1 and lines[0].startswith("harness: error: "), err
    assert "Traceback" not in err + out
    assert os.listdir(tmp_path) == []


def test_the_density_bound_admits_chung_and_ooi_test_8_and_says_why(tmp_path, capfd):
    """Test 8's target is 1000x as dense as the aluminium alloy (2.7e6 kg/m^3): it runs; just above the bound
    (3e6) is refused with the bound and its reason in one line."""
    target = ["--target", "sphere", "--target-radius", "0.5", "--material", "aluminium-alloy", "--radius", "0.1",
              "--speed", "0.2", "--mu", "0.4", "--en", "0.5", "--vt", "0"]
    assert main(["run", "--model", "hertz-mindlin", *target, "--target-material", "E=7e13,nu=0.33,rho=2.7e6",
                 "-o", str(tmp_path / "ok.csv")]) == 0
    assert main(["run", "--model", "hertz-mindlin", *target, "--target-material", "E=7e13,nu=0.33,rho=3.1e6",
                 "-o", str(tmp_path / "no.csv")]) == 2
    err = capfd.readouterr().err.strip().splitlines()[-1]
    assert "rho must lie in [1, 3e+06] kg/m^3" in err and "test 8" in err and not (tmp_path / "no.csv").exists()


def test_render_refuses_another_engines_option(tmp_path, capfd):
    code = main(["render", "--model", "hertz-mindlin", "--engine", "yade", "--engine-option",
                 "liggghts:limitForce=on", "--en", "0.5", "-o", str(tmp_path / "decks")])
    err = capfd.readouterr().err
    assert code == 2 and "liggghts" in err and len(err.strip().splitlines()) == 1
    assert not (tmp_path / "decks").exists()



def test_render_refuses_the_converged_mode_in_one_line(tmp_path, capfd):
    """An engine runs at a time step: render --converged is one line and exit 2 (it was a traceback, exit 4)."""
    code = main(["render", "--model", "hertz-mindlin", "--engine", "yade", "--en", "0.5", "--converged",
                 "-o", str(tmp_path / "decks")])
    err = capfd.readouterr().err
    assert code == 2 and len(err.strip().splitlines()) == 1 and "--steps-per-contact or --dt" in err
    assert not (tmp_path / "decks").exists()

@pytest.mark.parametrize("damage, message", [
    ("run.json:{not json", "cannot read"), ("run.json:[1, 2]", "damaged or foreign"),
    ("run.json:{\"model\": \"thornton\", \"scene\": {\"radius\": \"big\"}}", "damaged or foreign"),
    ("results.csv:binary", "cannot read results table"), ("results.csv:header", "holds no results"),
    ("results.csv:cut", "cut or damaged"), ("results.csv:foreign", "not a harness results table")])
def test_report_refuses_a_damaged_directory_in_one_line(tmp_path, capfd, damage, message):
    directory = tmp_path / "out"
    assert main(["compare", "--model", "thornton", "--engines", "reference", *SCENE, "-o", str(directory),
                 "--quiet"]) == 0
    capfd.readouterr()
    name, how = damage.split(":", 1)
    path, text = directory / name, (directory / "results.csv").read_text()
    if how == "binary":
        path.write_bytes(bytes(range(256)) * 4)
    elif how == "header":
        path.write_text(text.splitlines()[0] + "\n")
    elif how == "cut":
        path.write_text(text[:len(text.splitlines()[0]) + 40])
    elif how == "foreign":
        path.write_text("a,b\n1,2\n")
    else:
        path.write_text(how)
    code = main(["report", str(directory)])
    err = capfd.readouterr().err
    assert code == 2 and message in err and len(err.strip().splitlines()) == 1 and "Traceback" not in err


def test_a_header_only_or_non_numeric_baseline_is_refused(tmp_path, capfd):
    from harness.studies.baseline import BASELINE_FILE, DEFAULT_BASELINE
    text = Path(DEFAULT_BASELINE, BASELINE_FILE).read_text().splitlines()
    (tmp_path / BASELINE_FILE).write_text(text[0] + "\n")
    assert main(["check", "--baseline", str(tmp_path)]) == 2
    assert "holds no rows" in capfd.readouterr().err
    header = text[0].split(",")
    row = text[1].split(",")
    row[header.index("e_t")] = "not-a-number"
    (tmp_path / BASELINE_FILE).write_text("\n".join([text[0], ",".join(row)] + text[2:]) + "\n")
    assert main(["check", "--baseline", str(tmp_path)]) == 2
    assert "not a number in e_t" in capfd.readouterr().err


# --- results that run but mean nothing -------------------------------------------------------------------------------

@pytest.mark.parametrize("keywords, reason", [
    (dict(E=1e4, speed=100.0), "exceeds the small-strain range"),
    (dict(E=1e3, rho=1e5, speed=50.0), "exceeds the small-strain range"),
])
def test_an_overlap_beyond_small_strain_is_not_ok(keywords, reason):
    import harness
    from harness.data.results import SMALL_STRAIN
    frame = harness.run("hertz-mindlin", en=[0.5], angles=[0, 30], **keywords)
    overlap = frame.overlap_max / frame.radius
    assert (overlap > SMALL_STRAIN).all()                # the premise: a Hertz overlap beyond a = 0.3 R
    assert set(frame.status) == {"invalid"} and frame.message.str.contains(reason).all()
    assert frame.message.str.contains(f"{overlap.iloc[0]:.3g} R").any()


def test_rows_with_a_negative_e_n_or_a_non_finite_energy_are_invalid():
    """The rule applied to rows as an engine could return them (YADE once gave e_n -0.88 in an ok row)."""
    from harness.laws import compose
    from harness.data.results import impact_frame
    from harness.scenes.scene import Scene
    from harness.solver.simulate import batch_at
    scene = Scene(e_n=(0.5,), angles_deg=(10.0, 20.0, 30.0))
    batch = batch_at(compose("thornton"), scene, 0.5, 100)
    v_n1 = np.array([-0.88 * batch.v_n0[0], 0.5 * batch.v_n0[1], np.inf])
    frame = impact_frame(scene, batch, model="thornton", dialect="yade", engine="yade", engine_version="x", dt=batch.dt,
                         steps_per_contact=100, v_n1=v_n1, v_t1=batch.v_t0, omega1=np.zeros(3), wall_s=0.0,
                         status="ok", message="")
    assert frame.status.tolist() == ["invalid", "ok", "invalid"]
    assert "e_n -0.88 < 0" in frame.message[0] and "not finite" in frame.message[2]


@pytest.mark.parametrize("wall", ["E=2e11", "E=2e11,nu=0.3,rho=1", "E=steel,nu=0.3", "E=2e11,nu=0.7", "E=-1,nu=0.3"])
def test_a_numeric_wall_that_is_not_one_is_a_one_line_error(wall, tmp_path, capsys):
    assert main(["run", "--model", "hertz-mindlin", "--wall", wall, "-o", str(tmp_path / "r.csv")]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "wall" in err and not (tmp_path / "r.csv").exists()


def _rows(engine="reference", angles=(10.0, 20.0, 30.0), mu=0.1, **measured):
    """Result rows as a batch of `engine` could return them: every impact rebounding at half its normal speed."""
    from harness.laws import compose
    from harness.data.results import impact_frame
    from harness.scenes.scene import Scene
    from harness.solver.simulate import batch_at
    scene = Scene(e_n=(0.5,), angles_deg=angles, mu=mu)
    batch = batch_at(compose("thornton"), scene, 0.5, 100)
    n = len(angles)
    measured = {k: np.full(n, 1e-5) for k in ("t_contact", "f_n_max", "overlap_max")} | measured
    return impact_frame(scene, batch, model="thornton", dialect=engine, engine=engine, engine_version="x",
                        dt=batch.dt, steps_per_contact=100, v_n1=0.5 * batch.v_n0, v_t1=0.8 * batch.v_t0,
                        omega1=np.zeros(n), wall_s=0.0, status="ok", message="", **measured)


def test_an_ok_row_holds_no_nan_where_its_value_is_defined():
    """A reference row's contact time, peak force and overlap are measured, so a non-finite one is not a result; a
    ratio is NaN only where its denominator is 0 (e_t = v_t1/v_t0 at v_t0 != 0 is not)."""
    from harness.data.results import mark_invalid
    frame = _rows(t_contact=np.array([np.nan, 1e-5, 1e-5]), f_n_max=np.array([1.0, np.inf, 1.0]))
    assert frame.status.tolist() == ["invalid", "invalid", "ok"]
    assert "t_contact" in frame.message[0] and "f_n_max" in frame.message[1]
    frame.loc[2, "e_t"] = np.nan                                  # as a damaged kernel or adapter could leave it
    assert (frame.v_t0 > 0).all() and mark_invalid(frame).status[2] == "invalid" and "e_t" in frame.message[2]


def test_undefined_ratios_and_what_an_engine_does_not_measure_stay_ok():
    """e_t and beta are undefined at V_t = 0 (normal impact), the normalised slips at mu = 0: NaN there is the
    definition, not a failure; an engine run measures no contact time, peak force or overlap (NaN, not measured)."""
    import harness
    normal = harness.run("hertz-mindlin", en=[0.5], angles=[0.0, 30.0], mu=0.0)
    assert normal.status.tolist() == ["ok", "ok"]
    assert np.isnan(normal.e_t[0]) and np.isnan(normal.beta[0]) and np.isfinite(normal.e_t[1])
    assert normal[["psi1_star", "psi2_star", "omega_star", "psi1_maw", "psi2_maw"]].isna().all().all()
    nan = np.full(3, np.nan)
    assert set(_rows(engine="yade", t_contact=nan, f_n_max=nan, overlap_max=nan).status) == {"ok"}
