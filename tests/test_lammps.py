"""LAMMPS as the third engine: the real `lmp` against its dialect in the reference at equal dt, its defects as
measured findings, its input and its failures."""
import math
import os
from dataclasses import replace

import numpy as np

import pytest
from conftest import PAIR_TARGETS, agreement, assert_head_on_pair_is_wall, fake_executable, needs

from harness.engines import lammps
from harness.runs.execute import execute
from harness.laws import compose
from harness.runs.plan import engine_plan, engine_runs
from harness.scenes.scene import Scene
from harness.submodels import calibration as cal

needs_lammps = needs("lammps")
ANGLES = (0.0, 10.0, 30.0, 50.0, 70.0, 85.0)


CASES = ([(name, {}) for name in sorted(lammps.DIALECTS)]
         + [(name, {"tangential": form}) for name in ("hertz-mindlin", "hertz-kuwabara-kono")
            for form in ("mindlin_rescale", "mindlin/force", "mindlin_rescale/force")]
         + [(name, {"style": "history"}) for name in sorted(lammps.HISTORY_STYLES)])


@needs_lammps
@pytest.mark.parametrize("name,options", CASES)
@pytest.mark.parametrize("omega0", [0.0, -20.0])
def test_lammps_agrees_with_its_dialect_at_equal_dt(name, options, omega0):
    """Every supported law and form x 3 e_n x 6 angles, with and without spin: the real binary within 1e-6 of its
    dialect."""
    scene = Scene(e_n=(0.3, 0.6, 0.9), angles_deg=ANGLES, psi1_star=None, omega0=omega0)
    frame, failures = execute(engine_plan(lammps.ENGINE, compose(name), scene, 200, options))
    assert failures == []
    assert agreement(frame, "lammps") < 1e-6


@needs_lammps
def test_tsuji_damping_returns_the_reported_restitution_and_the_dialect_says_why():
    """The report of e = 0.44/0.70/0.93 for targets 0.3/0.6/0.9 reproduced on the Debian build: LAMMPS' polynomial
    A(e) is 1/sqrt2 of the coefficient that gives e for its own dashpot A sqrt(m 4/3 E a) (Hertz with a dashpot
    ~ alpha^1/4 has e independent of stiffness and speed, so the exact coefficient restores the target)."""
    scene = Scene(e_n=(0.3, 0.6, 0.9), angles_deg=(0.0,), psi1_star=None)
    frame, _ = execute(engine_runs(lammps.ENGINE, compose("hertz-mindlin"), scene, 1000))
    assert np.allclose(frame.e_n, [0.44, 0.70, 0.93], atol=0.006)
    from harness.analyses.findings import findings
    from harness.engines import known_cause
    (finding,) = findings(frame, cause=known_cause).to_dict("records")
    assert finding["kind"] == "e_n off target"
    assert "Tsuji polynomial (2021.9.29.2 to 2025.7.22.4) is 1/sqrt2" in finding["detail"]
    for e in (0.3, 0.6, 0.9):
        assert cal.polynomial_tsuji_A(e) / cal.tsuji_tension_A(e) == pytest.approx(1.0 / math.sqrt(2.0), rel=3e-3)
    exact = compose("hertz-mindlin", {"damping": "tsuji:tension", "end": "tension"})
    from harness.solver.simulate import simulate
    assert np.allclose(simulate(exact, scene, steps_per_contact=1000)[0].e_n, [0.3, 0.6, 0.9], atol=2e-4)


def test_the_wall_moduli_are_lammps_own_mixing_not_the_pairs():
    """E_w = E/(2(1 - nu)) and K = E/4 (2 - nu)(1 + nu) where E* = E/(2(1 - nu^2)) and 8 G* = 2E/((2 - nu)(1 + nu)):
    at nu = 0.3 the wall is 1 + nu = 1.3x stiffer normally and (2 - nu)^2 (1 + nu)^2/8 = 0.61x tangentially."""
    scene = Scene()
    law = lammps.dialect("hertz-mindlin", {}, "wall", "2021.9.29.2")
    c = scene.contact
    e_w = law.normal.parameters(c, 0.5, scene.speed).values[0]
    assert e_w / c.E_star == pytest.approx(1.0 + scene.nu)
    assert 8.0 * law.tangential.parameter(c, 0.0) / (8.0 * c.G_star) == pytest.approx((1.7 * 1.3) ** 2 / 8.0)


def test_deck_holds_only_the_expected_commands_and_numbers():
    scene = Scene(e_n=(0.5,), angles_deg=(10.0, 40.0), psi1_star=None)
    run = engine_runs(lammps.ENGINE, compose("hertz-mindlin"), scene, 100)[0]
    name, text = lammps.ENGINE.render(run)
    assert name == "lammps-hertz-mindlin-en0.5.in"
    commands = {line.split()[0] for line in text.splitlines() if line and not line.startswith("#")}
    assert commands <= {"units", "atom_style", "atom_modify", "boundary", "newton", "comm_modify", "region",
                        "create_box", "neighbor", "neigh_modify", "pair_style", "pair_coeff", "timestep", "fix",
                        "create_atoms", "set", "compute", "thermo_style", "thermo", "thermo_modify", "variable",
                        "label", "run", "if", "next", "jump", "print", "write_dump"}
    assert f"hertz/material {scene.E!r} 0.5 {scene.nu!r} damping tsuji tangential mindlin NULL" in text


def test_a_wall_of_another_material_is_refused_with_its_reason():
    scene = Scene(e_n=(0.5,), angles_deg=(10.0,), psi1_star=None, wall="rigid")
    frame, failures = execute(engine_runs(lammps.ENGINE, compose("hertz-mindlin"), scene, 100))
    assert (frame.status == "failed").all() and "own material" in failures[0].message


def test_missing_binary_is_a_reason_not_an_error(tmp_path, monkeypatch):
    monkeypatch.setenv(lammps.BINARY_VARIABLE, str(tmp_path / "nowhere"))
    status = lammps.ENGINE.status("hertz-mindlin")
    assert not status.available
    assert status.reason == f"HARNESS_LAMMPS={str(tmp_path / 'nowhere')!r} is not an executable file"
    assert lammps.ENGINE.status("thornton").available is False


def test_a_crashing_lammps_fails_its_rows_with_the_log_tail(tmp_path, monkeypatch):
    monkeypatch.setenv(lammps.BINARY_VARIABLE, fake_executable(tmp_path, 'echo "ERROR: Illegal fix wall/gran"; exit 1'))
    scene = Scene(e_n=(0.5,), angles_deg=(10.0,), psi1_star=None)
    frame, failures = execute(engine_runs(lammps.ENGINE, compose("hertz-mindlin"), scene, 100))
    assert (frame.status == "failed").all() and "Illegal fix wall/gran" in failures[0].log_tail


@needs_lammps
def test_version_is_read_without_writing_here(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    from harness.engines.base import banner_version
    banner_version.cache_clear()
    assert lammps.ENGINE.version() == "2021.9.29.2" and os.listdir(tmp_path) == []


@needs_lammps
def test_each_mindlin_form_and_style_changes_what_lammps_computes():
    """The options are not decoration: every Mindlin form moves LAMMPS' rebound spin, and so does hertz/history (the
    pair's E* and G*, not the granular wall's); hooke/history is granular hooke + mass_velocity + linear_history
    written otherwise, and the two styles agree to round-off."""
    scene = Scene(e_n=(0.6,), angles_deg=(10.0, 30.0), psi1_star=None, omega0=-20.0)
    spins = {}
    for name, options in CASES:
        frame, _ = execute(engine_runs(lammps.ENGINE, compose(name), scene, 200, options))
        spins[(name, tuple(options.items()))] = frame.omega1.to_numpy()
    for name in ("hertz-mindlin", "hertz-kuwabara-kono"):
        mine = [v for (n, _), v in spins.items() if n == name]
        assert len(mine) >= 4
        assert all(np.abs(a - b).max() > 1e-3 for i, a in enumerate(mine) for b in mine[i + 1:]), name
    granular, history = [v for (n, _), v in spins.items() if n == "linear-spring-dashpot"]
    assert np.abs(granular - history).max() < 1e-9 * 20.0


def test_options_where_their_law_has_none_are_one_line_errors():
    from harness.infra.errors import UserError
    with pytest.raises(UserError, match="no older wall style for hertz-mindlin"):
        lammps.dialect("hertz-mindlin", {"style": "history"})
    with pytest.raises(UserError, match="Mindlin springs are for the granular style's hertz/material laws"):
        lammps.dialect("linear-spring-dashpot", {"tangential": "mindlin_rescale"})


@needs_lammps
@pytest.mark.parametrize("name", sorted(lammps.PAIR_DIALECTS))
@pytest.mark.parametrize("pair", sorted(PAIR_TARGETS))
@pytest.mark.parametrize("omega0", [0.0, 20.0])
def test_lammps_two_spheres_agree_with_their_dialect_at_equal_dt(name, pair, omega0):
    """pair granular between two spheres, every supported law x 3 e_n x 6 angles, with and without spin, against
    targets free or frozen, of the same or another size and material: the real binary within 1e-6 of its dialect
    (the relative motion with the turning normal, solver/pair.py)."""
    from harness.runs.request import scene_from
    scene = scene_from(en=(0.3, 0.6, 0.9), angles=ANGLES, omega0=omega0, target="sphere", **PAIR_TARGETS[pair])
    dialect = lammps.dialect(name, {}, "sphere")
    frame, failures = execute(engine_plan(lammps.ENGINE, compose(name), scene, 200))
    assert failures == []
    assert (dialect.integrator, dialect.coulomb, dialect.geometry) == ("velocity-verlet", "total", "pair")
    assert agreement(frame, "lammps") < 1e-6


def test_the_pair_stepper_head_on_is_the_wall_stepper():
    """Two code paths, one answer: a head-on impact without spin never turns the normal, so the pair stepper
    (solver/pair.py) on the relative motion equals LAMMPS' wall scheme (solver/schemes.py) on the equivalent sphere
    with the pair's own moduli, to round-off."""
    assert_head_on_pair_is_wall(lammps.dialect("hertz-mindlin", {}, "sphere"),
                                {"geometry": "wall", "torque": "lever"})


def test_a_pair_deck_names_both_materials_and_the_pair_mixing():
    """pair_coeff 1 2 carries the E and nu whose own mixing is the pair's E* and G* (LAMMPS' automatic mixing of 1 1
    and 2 2 is unusable in this version), a frozen target is frozen, and the dump has x for the separation."""
    from harness.runs.request import scene_from
    scene = scene_from(en=(0.5,), angles=(30.0,), target="sphere", target_radius=0.01,
                       target_material="E=2.1e11,nu=0.29,rho=7800", target_fixed=True)
    run = engine_runs(lammps.ENGINE, compose("hertz-mindlin"), scene, 200)[0]
    text = lammps.render_batch(run.law, run.scene, replace(run.spec, step_cap=1000))
    coefficients = [line.split() for line in text.splitlines() if line.startswith("pair_coeff")]
    assert [c[1:3] for c in coefficients] == [["1", "1"], ["2", "2"], ["1", "2"]]
    E12, nu12 = float(coefficients[2][4]), float(coefficients[2][6])
    contact = scene.contact
    assert E12 / (2 * (1 - nu12 ** 2)) == pytest.approx(contact.E_star, rel=1e-14)
    assert E12 / (4 * (2 - nu12) * (1 + nu12)) == pytest.approx(contact.G_star, rel=1e-14)
    assert "fix hold targets freeze" in text and "id x z vx vz omegay" in text


@needs_lammps
def test_lammps_pairs_observed_contact_agrees_with_the_dialect():
    """Observe mode of the pair deck: contact time to the step (both from the touch at step 0 to the first step out),
    peak normal force F1.n and overlap R1 + R2 - |r| within the parabola's O(1/N^2) of the dialect's interpolated peaks
    (tests/test_observe.py: up to 30/N^2), here with the normal turning (40 and 70 deg)."""
    from harness.runs.plan import reference_runs
    from harness.runs.request import scene_from
    scene = scene_from(en=(0.5,), angles=(0.0, 40.0, 70.0), omega0=20.0, target="sphere", target_radius=0.04)
    law = compose("hertz-mindlin")
    seen, failures = execute(engine_runs(lammps.ENGINE, law, scene, 200, observe=True))
    own, _ = execute(reference_runs(law, scene, 200, lammps.dialect("hertz-mindlin", {}, "sphere")))
    assert failures == [] and (seen.status == "ok").all()
    assert np.array_equal(np.round(seen.t_contact / seen.dt), np.round(own.t_contact / own.dt))
    for column in ("f_n_max", "overlap_max"):
        assert np.max(np.abs(seen[column] / own[column] - 1.0)) < 30.0 / 200 ** 2, column


WALL_CASES = [("linear-spring-dashpot", {}), ("linear-spring-dashpot", {"style": "history"}),
              ("hertz-kuwabara-kono", {"style": "history"})]


@needs_lammps
@pytest.mark.parametrize("name,options", WALL_CASES)
@pytest.mark.parametrize("wall", ["rigid", "E=2.1e11,nu=0.29"])
def test_lammps_walls_of_another_material_agree_with_the_dialect(name, options, wall):
    """Where the deck gives the wall's stiffnesses as numbers (granular hooke, hooke/history, hertz/history), they
    are the scene's contact's, so any wall runs and agrees with the dialect; the steel wall changed the rebound (a
    rigid one, doubling E* and G* together, leaves these e_n-calibrated laws' rebound as it was: see the deck test)."""
    from harness.runs.request import wall_fields
    kwargs = dict(e_n=(0.3, 0.9), angles_deg=(0.0, 30.0, 60.0), psi1_star=None, omega0=-20.0)
    scene = Scene(**kwargs, **wall_fields(wall))
    frame, failures = execute(engine_plan(lammps.ENGINE, compose(name), scene, 200, options))
    assert failures == [] and agreement(frame, "lammps") < 1e-6
    if wall != "rigid":
        same = execute(engine_runs(lammps.ENGINE, compose(name), Scene(**kwargs), 200, options))[0]
        engine = frame[frame.engine == "lammps"].reset_index(drop=True)
        assert np.abs(same.omega1.to_numpy() - engine.omega1.to_numpy()).max() * scene.radius > 1e-4 * scene.speed


def test_lammps_wall_stiffness_numbers_follow_the_wall_and_hertz_material_keeps_its_own():
    """hertz/history's k_n = 4/3 E* in the deck: E/(1 - nu^2) against a rigid wall, half that against the sphere's
    own material; hertz/material (hertz-mindlin, granular hertz-kuwabara-kono) offers only the latter."""
    from harness.runs.request import wall_fields
    coefficients = {}
    for wall in ("same", "rigid"):
        scene = Scene(e_n=(0.5,), angles_deg=(30.0,), **(wall_fields(wall) if wall != "same" else {}))
        run = engine_runs(lammps.ENGINE, compose("hertz-kuwabara-kono"), scene, 200, {"style": "history"})[0]
        text = lammps.render_batch(run.law, run.scene, replace(run.spec, step_cap=1000), run.options_dict)
        line = next(line for line in text.splitlines() if line.startswith("fix wall all wall/gran hertz/history"))
        coefficients[wall] = float(line.split()[5])
    E, nu = Scene().E, Scene().nu
    assert coefficients["rigid"] == pytest.approx(4.0 / 3.0 * E / (1.0 - nu ** 2), rel=1e-12)
    assert coefficients["same"] == pytest.approx(4.0 / 3.0 * E / (2.0 * (1.0 - nu ** 2)), rel=1e-12)
    assert lammps.ENGINE.walls("hertz-mindlin") == ("same",) and lammps.ENGINE.walls("hertz-kuwabara-kono") == ("same",)
    assert lammps.ENGINE.walls("hertz-kuwabara-kono", {"style": "history"}) == ("same", "other", "rigid")
    assert lammps.ENGINE.walls("linear-spring-dashpot") == ("same", "other", "rigid")
