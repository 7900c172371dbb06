"""The physics verdict: does an engine reproduce the paper law? Made-up engine results that break each tolerance in
turn (and only it), the attribution's ingredient, the three states, the terminal, JSON and report, and the real LAMMPS
(whose Tsuji damping misses e_n) with and without --require paper."""
import json
from types import SimpleNamespace

import numpy as np
import pandas as pd
import pytest
from conftest import needs

from harness.analyses.physics import DEVIATES, NOT_CHECKED, REPRODUCES, Tolerances, engine_physics
from harness.analyses.verdict import verdict
from harness.commands import main
from harness.comparison import Comparison
from harness.errors import UserError
from harness.laws import compose
from harness.results import impact_frame
from harness.scene import Scene
from harness.views.html import write_report
from harness.views.terminal import print_summary, verdict_line

ANGLES = (10.0, 45.0, 80.0)
E_N, MU = 0.5, 0.1


def rigid_body(scene, e_n):
    """A rigid sphere's rebound (the made-up paper law): v_n1 = e V_n; rolling (v_t1 = 5/7 V_t = R omega1) below
    tan(theta) = 3.5 mu (1 + e), else sliding throughout: v_t1 = V_t - mu (1 + e) V_n, R omega1 = 5/2 mu (1 + e) V_n."""
    v_n0, v_t0, omega0, theta = scene.impacts(e_n)
    slides = v_t0 >= 3.5 * scene.mu * (1.0 + e_n) * v_n0
    v_t1 = np.where(slides, v_t0 - scene.mu * (1.0 + e_n) * v_n0, 5.0 / 7.0 * v_t0)
    omega1 = np.where(slides, 2.5 * scene.mu * (1.0 + e_n) * v_n0, v_t1) / scene.radius
    return SimpleNamespace(e_n=e_n, theta_deg=theta, v_n0=v_n0, v_t0=v_t0, omega0=omega0), e_n * v_n0, v_t1, omega1


def rows(scene, batch, engine, dialect, v_n1, v_t1, omega1, status="ok"):
    return impact_frame(scene, batch, model="hertz-mindlin", dialect=dialect, engine=engine, engine_version="1",
                        dt=1e-8, steps_per_contact=1000, v_n1=v_n1, v_t1=v_t1, omega1=omega1, wall_s=0.0,
                        status=status, message="", t_contact=1e-5, f_n_max=1.0, overlap_max=1e-6)


def made_up(change=None, scene=None, e_n=E_N, status="ok", at=80.0):
    """The paper law's rows and an engine 'fake' whose rows are the paper law's, changed by change(v) at `at` deg
    (80: sliding throughout, where any change of v_t1 or e_n also moves |J_t| off mu J_n; 10: rolling)."""
    scene = scene or Scene(e_n=(e_n,), angles_deg=ANGLES, mu=MU)
    batch, v_n1, v_t1, omega1 = rigid_body(scene, e_n)
    paper = rows(scene, batch, "reference", "paper", v_n1, v_t1, omega1)
    engine = {"v_n1": v_n1.copy(), "v_t1": v_t1.copy(), "omega1": omega1.copy()}
    if change:
        change(engine, batch, np.flatnonzero(batch.theta_deg == at)[0])
    return scene, pd.concat([paper, rows(scene, batch, "fake", "fake", **engine, status=status)], ignore_index=True)


def speed_of(batch, i):
    return float(np.hypot(batch.v_n0[i], batch.v_t0[i]))


def faster_slide(v, b, i):                # v_t1 2% of V above the paper law's
    v["v_t1"][i] += 0.02 * speed_of(b, i)


def livelier(v, b, i):                    # e_n 0.015 above, at 80 deg: 0.26% of V in v_n1, still sliding (J_t = mu J_n)
    v["v_n1"][i] += 0.015 * b.v_n0[i]
    v["v_t1"][i] -= MU * 0.015 * b.v_n0[i]


def over_friction(v, b, i):               # |J_t| = 1.005 mu J_n: v_t1 1.3e-4 V below
    v["v_t1"][i] -= 0.005 * MU * (1.0 + E_N) * b.v_n0[i]


def energy_gain(v, b, i):                 # v_t1 1e-4 above an elastic frictionless rebound
    v["v_t1"][i] *= 1.0 + 1e-4


FRICTIONLESS_ELASTIC = Scene(e_n=(1.0,), angles_deg=ANGLES, mu=0.0)


def physics(frame, tolerances=Tolerances(), attribution=None):
    return engine_physics(frame, "fake", tolerances, attribution)


def test_the_coulomb_bound_holds_from_below_where_the_paper_law_slides_throughout():
    """v_t1 2% of V faster at 80 deg, where the rigid sphere slides throughout: the engine takes less tangential
    impulse than mu J_n (by 0.02 V / (mu (1 + e) V_n) = 0.136 of it), and the check says so from below."""
    _, frame = made_up(faster_slide)
    coulomb = next(c for c in physics(frame)["checks"] if c["check"] == "coulomb")
    v_n0 = 5.0 * np.cos(np.radians(80.0))
    assert not coulomb["passed"] and coulomb["theta_deg"] == 80.0
    assert coulomb["worst"] == pytest.approx(0.02 * 5.0 / (MU * (1.0 + E_N) * v_n0), rel=1e-9)
    assert "where the paper law slides throughout" in coulomb["text"]


def test_the_paper_law_itself_reproduces_it():
    _, frame = made_up()
    result = physics(frame)
    assert result["state"] == REPRODUCES and result["impacts"] == 3 and all(c["passed"] for c in result["checks"])


@pytest.mark.parametrize("change, scene, at, check, relaxed", [
    (faster_slide, None, 10.0, "velocity", {"velocity": 0.03}),
    (livelier, None, 80.0, "e_n", {"e_n": 0.02}),
    (over_friction, None, 80.0, "coulomb", {"coulomb": 0.01}),
    (energy_gain, FRICTIONLESS_ELASTIC, 80.0, "energy", {"energy": 1e-3}),
])
def test_each_tolerance_broken_alone_is_the_one_reported(change, scene, at, check, relaxed):
    _, frame = made_up(change, scene, e_n=1.0 if scene else E_N, at=at)
    result = physics(frame)
    assert result["state"] == DEVIATES and result["failing"] == [check]
    (failed,) = [c for c in result["checks"] if not c["passed"]]
    assert failed["theta_deg"] == at and failed["failing"] == 1 and failed["worst"] > failed["tolerance"]
    assert physics(frame, Tolerances.of(relaxed))["state"] == REPRODUCES        # the user's tolerance decides


def test_the_worst_case_is_measured_in_the_checks_own_units():
    scene, frame = made_up(faster_slide)
    velocity = [c for c in physics(frame)["checks"] if c["check"] == "velocity"][0]
    assert velocity["metric"] == "v_t1" and velocity["worst"] == pytest.approx(0.02, rel=1e-9)
    _, frame = made_up(over_friction)
    coulomb = [c for c in physics(frame)["checks"] if c["check"] == "coulomb"][0]
    assert coulomb["worst"] == pytest.approx(0.005, rel=1e-6)
    _, frame = made_up(livelier)
    assert [c for c in physics(frame)["checks"] if c["check"] == "e_n"][0]["worst"] == pytest.approx(0.015, rel=1e-9)


def test_the_cause_is_the_ingredient_that_moves_the_quantity_towards_the_paper_law():
    _, frame = made_up(faster_slide, at=10.0)    # the engine's v_t1 is above the paper law's: towards is negative
    attribution = pd.DataFrame([
        {"ingredient": "damping", "dialect": "a", "target": "b", "d_v_t1": +0.5},     # away, although larger
        {"ingredient": "integrator", "dialect": "leapfrog", "target": "paper", "d_v_t1": -0.3},
    ])
    (failed,) = [c for c in physics(frame, attribution=attribution)["checks"] if not c["passed"]]
    assert failed["cause"].startswith("integrator (leapfrog in the engine, paper in the paper law)")
    away = attribution.assign(d_v_t1=[0.5, 0.3])
    (failed,) = [c for c in physics(frame, attribution=away)["checks"] if not c["passed"]]
    assert failed["cause"].startswith("no single ingredient")


def test_not_checked_when_no_impact_of_the_engine_ran_or_no_paper_law():
    _, frame = made_up(status="failed")
    assert physics(frame)["state"] == NOT_CHECKED
    _, frame = made_up()
    assert physics(frame[frame.engine != "reference"])["state"] == NOT_CHECKED


@pytest.mark.parametrize("given", [["speed=0.1"], ["velocity"], ["velocity=x"], ["velocity=-1"], ["e_n=inf"],
                                   ["energy=1", "energy=2"]])
def test_bad_tolerances_are_user_errors(given):
    with pytest.raises(UserError):
        Tolerances.of(given)


def comparison(frame, scene):
    return Comparison(compose("hertz-mindlin"), scene, frame, command="harness compare (made up)")


def test_terminal_json_and_report_lead_with_the_physics_verdict(tmp_path, capsys):
    scene, frame = made_up(over_friction)
    record = verdict(comparison(frame, scene))
    json.dumps(record)                                          # the --json document
    assert record["physics"] == DEVIATES and record["verdict"] == "not compared"
    assert record["engines"][0]["physics"]["failing"] == ["coulomb"]
    print_summary(record, comparison(frame, scene), ["results.csv"])
    out = " ".join(capsys.readouterr().out.split())                 # as read, whatever the terminal's width
    assert "fake 1" in out and "DEVIATES" in out and "|J_t| 1.005 mu J_n at e_n 0.5, 80 deg (1 of 3 impacts)" in out
    assert verdict_line(record).startswith("paper law: deviates in fake;")
    html = (tmp_path / "report.html")
    write_report(str(tmp_path), comparison(frame, scene))
    text = html.read_text()
    assert 'class="summary deviates"' in text and "fake does not reproduce the paper law on this scene" in text
    scene, frame = made_up()
    record = verdict(comparison(frame, scene))
    assert record["physics"] == REPRODUCES and verdict_line(record).startswith("paper law: reproduced by fake")


def test_findings_wrap_between_words_and_keep_every_number(capsys, monkeypatch):
    monkeypatch.setenv("COLUMNS", "80")
    detail = ("126 impacts with |J_t| > mu J_n, worst by 58.7% at e_n 0.25, 71 deg (v_t1 4.405 m/s from 4.728, "
              "omega0 0 rad/s); known cause: its formulas in the reference do the same; its velocity-Verlet step")
    record = {"model": "m", "engines": [], "e_n": [0.25], "impacts": 1, "skipped": [], "tolerances": {},
              "findings": [{"engine": "liggghts", "dialect": "liggghts", "kind": "Coulomb bound", "detail": detail}]}
    print_summary(record, SimpleNamespace(failures=[], versions=pd.DataFrame(), builds={}), ["x"])
    lines = capsys.readouterr().out.splitlines()[1:-1]
    assert all(len(line) <= 80 and not line.endswith("...") for line in lines)
    assert " ".join(line.strip() for line in lines) == f"finding: liggghts (liggghts): Coulomb bound: {detail}"


@needs("lammps")
def test_lammps_misses_e_n_so_require_paper_exits_1(tmp_path, capsys):
    """LAMMPS' Tsuji damping rebounds at e_n 0.39 for a target of 0.25 (docs/lammps-dialect.md), at every angle."""
    args = ["compare", "--model", "hertz-mindlin", "--engines", "lammps", "--en", "0.25", "--angles", "30,60"]
    assert main([*args, "-o", str(tmp_path / "a"), "--json"]) == 0           # the agreement holds
    record = json.loads(capsys.readouterr().out)
    (lammps,) = record["engines"]
    e_n = [c for c in lammps["physics"]["checks"] if c["check"] == "e_n"][0]
    results = pd.read_csv(tmp_path / "a" / "results.csv")
    engine_e_n = results[results.engine == "lammps"].e_n
    assert record["physics"] == DEVIATES and not e_n["passed"] and e_n["failing"] == 2
    assert e_n["worst"] == pytest.approx((engine_e_n - 0.25).abs().max(), abs=1e-3) and engine_e_n.min() > 0.38
    assert "damping" in e_n["cause"]
    assert main([*args, "-o", str(tmp_path / "b"), "--require", "paper", "--quiet"]) == 1
    assert capsys.readouterr().out.startswith("paper law: deviates in lammps; agreement: ok for lammps")
    report = (tmp_path / "b" / "report.html").read_text()
    assert 'class="summary deviates"' in report and "lammps does not reproduce the paper law" in report


@pytest.mark.parametrize("bad", [["--tolerance", "speed=0.1"], ["--tolerance", "velocity"],
                                 ["--tolerance", "velocity=nan"], ["--tolerance", "e_n=1", "--tolerance", "e_n=2"],
                                 ["--require", "engines"]])
def test_compare_refuses_a_bad_tolerance_in_one_line_and_writes_nothing(tmp_path, capfd, bad):
    code = main(["compare", "--model", "hertz-mindlin", "--engines", "reference", "--en", "0.5", "--angles", "10",
                 *bad, "-o", str(tmp_path / "out")])
    err = capfd.readouterr().err.strip().splitlines()
    assert code == 2 and len(err) == 1 and err[0].startswith("harness: error: ") and not (tmp_path / "out").exists()


def test_a_stepping_field_no_stepper_takes_alone_is_switched_with_the_others_and_measured():
    """LAMMPS' hertz-mindlin dialect steps with velocity Verlet and caps spring + dashpot together; the paper scheme
    applies its own Coulomb test only. Switching the integrator alone composes nothing, so its row switches the
    Coulomb rule too and measures it: equal to simulating that law directly, and said in the note."""
    from dataclasses import replace

    from harness.analyses.attribution import attribution
    from harness.engines import ENGINES
    from harness.laws import compose
    from harness.scene import Scene
    from harness.solver.simulate import simulate

    dialect, paper = ENGINES["lammps"].dialect("hertz-mindlin", {}), compose("hertz-mindlin")
    scene = Scene(e_n=(0.5,), angles_deg=(20.0, 60.0))
    run = lambda law, s: simulate(law, s, steps_per_contact=500)[0]     # noqa: E731
    table = attribution(paper, dialect, scene, run).set_index("ingredient")
    row = table.loc["integrator"]
    assert "switched with its coulomb" in row.note
    both = run(replace(dialect, integrator=paper.integrator, coulomb=paper.coulomb), scene)
    change = (both.omega_star - run(dialect, scene).omega_star).to_numpy()
    assert row.d_omega_star == pytest.approx(change[np.argmax(np.abs(change))], abs=1e-12)
    assert abs(row.d_omega_star) > 1e-3 and np.isfinite(table.loc["coulomb"].d_e_t)


def test_the_coulomb_bound_is_checked_from_below_where_the_paper_law_slides_throughout():
    """Hand-made impacts at mu 0.1, V_n 1 m/s: the paper law rebounds at v_n1 0.5 with |J_t| = mu J_n (0.15 m/s
    taken off v_t0 2); an engine that takes 0.12 off transmits 0.8 mu J_n, one that takes 0.15 off is not flagged,
    and an impact the paper law sticks on (it takes less than mu J_n) is not compared."""
    from harness.analyses.findings import under_friction
    common = dict(model="m", e_n_target=0.5, v_n0=1.0, omega0=0.0, mu=0.1, radius=0.01, E=1e9, nu=0.3, rho=2500.0,
                  v_n1=0.5, status="ok", t_contact=np.nan)
    rows = []
    for theta, v_t0, paper_dv in ((60.0, 2.0, 0.15), (5.0, 0.0875, 0.05)):
        for engine, dialect, dv in (("reference", "paper", paper_dv), ("lmp", "lmp", 0.12), ("ok", "ok", 0.15)):
            rows.append({**common, "engine": engine, "dialect": dialect, "theta_deg": theta, "v_t0": v_t0,
                         "v_t1": v_t0 - (dv if theta == 60.0 or engine == "reference" else 0.04)})
    found = under_friction(pd.DataFrame(rows))
    assert [(f["engine"], f["kind"]) for f in found] == [("lmp", "Coulomb bound from below")]
    assert found[0]["detail"].startswith("1 impact the paper law slides throughout transmits less than mu J_n; worst "
                                         "|J_t| 0.800 mu J_n at e_n 0.5, 60 deg")


def test_a_build_of_a_release_its_dialects_were_not_checked_on_is_flagged():
    from harness.engines import ENGINES
    liggghts = ENGINES["liggghts"]
    other = type(liggghts)()
    other.version = lambda: "3.9.1"
    assert other.dialect_note() == "liggghts's dialects were checked on 3.8.0, not on 3.9.1"
    other.version = lambda: "3.8.0"
    assert other.dialect_note() == ""
