"""LIGGGHTS adapter: real runs agree with the LIGGGHTS dialect at equal dt; failure modes give clear messages;
decks cannot be injected into."""
import os
import subprocess
import sys
from dataclasses import replace

import numpy as np
import pytest
from conftest import EXAMPLE, PAIR_TARGETS, agreement, fake_executable, needs

from harness.engines import liggghts
from harness.engines.runner import EngineFailure, run_engine
from harness.runs.execute import execute
from harness.laws import compose
from harness.runs.plan import engine_runs
from harness.infra.render import RenderError, render
from harness.scenes.scene import Scene
from harness.solver import codes as C
from harness.solver.simulate import batch_at, run_kernel

needs_liggghts = needs("liggghts")
SCENE = Scene(e_n=(0.9, 0.5, 0.1), angles_deg=(0.0, 10.0, 30.0, 50.0, 70.0, 85.0))


def engine_and_dialect(name, scene, e_n, steps=200, tmp_path=None, options=None):
    law = liggghts.dialect(name, options)
    batch = batch_at(law, scene, e_n, steps)
    out, _, _ = run_kernel(batch)
    final, _, _ = liggghts.ENGINE.run_batch(compose(name), scene, batch.spec, 300, str(tmp_path), options)
    engine = np.column_stack([final["v_n1"], final["v_t1"], final["omega1"]])
    reference = out[:, [C.O_VZ, C.O_VX, C.O_W]]
    return engine, reference, final


@needs_liggghts
@pytest.mark.parametrize("name", [n for n in liggghts.DIALECTS])
@pytest.mark.parametrize("e_n", [0.9, 0.5, 0.1])
def test_engine_agrees_with_its_dialect_at_equal_dt(name, e_n, tmp_path):
    engine, reference, final = engine_and_dialect(name, SCENE, e_n, tmp_path=tmp_path)
    assert final["separated"].all()
    scale = np.array([1.0, 1.0, 1.0 / SCENE.radius]) * SCENE.speed
    rel = np.abs(engine - reference) / np.maximum(np.abs(reference), 1e-9 * scale)
    assert rel.max() < 1e-6, rel



@needs_liggghts
def test_hysteresis_at_e_n_1_is_elastic_not_absent(tmp_path):
    """e_n = 1 gives k2max = k1; LIGGGHTS' d_lim = k2max/(k2max - k1) phi 2R must not become 0/0 (NaN force, dropped:
    every sphere passed through the wall with v_n1 = -V). Elastic: e_n = 1 (docs/laws.md, e = sqrt(K1/K2)), and the
    dialect agrees."""
    engine, reference, final = engine_and_dialect("walton-braun", SCENE, 1.0, tmp_path=tmp_path)
    assert final["separated"].all()
    assert final["v_n1"] / SCENE.impacts(1.0)[0] == pytest.approx(np.ones(len(SCENE.angles_deg)), abs=1e-6)
    scale = np.array([1.0, 1.0, 1.0 / SCENE.radius]) * SCENE.speed
    assert (np.abs(engine - reference) / np.maximum(np.abs(reference), 1e-9 * scale)).max() < 1e-6


@needs_liggghts
def test_soft_and_stiff_materials_run_and_negative_poisson_is_refused_clearly(tmp_path):
    """E = 1e6 Pa (LIGGGHTS' sanity check wants >= 5e6 unless soft_particles yes, which changes nothing else) and
    E = 1e12 Pa run and agree with the dialect; nu < 0, which LIGGGHTS refuses, is a one-line failed run."""
    for E in (1e6, 1e12):
        scene = Scene(E=E, e_n=(0.5,), angles_deg=(0.0, 30.0, 60.0))
        engine, reference, final = engine_and_dialect("hertz-mindlin", scene, 0.5, tmp_path=tmp_path)
        assert final["separated"].all()
        scale = np.array([1.0, 1.0, 1.0 / scene.radius]) * scene.speed
        assert (np.abs(engine - reference) / np.maximum(np.abs(reference), 1e-9 * scale)).max() < 1e-6, E
    frame, failures = execute(engine_runs(liggghts.ENGINE, compose("hertz-mindlin"), Scene(nu=-0.5, e_n=(0.5,)), 100))
    assert [f.message for f in failures] == ["LIGGGHTS accepts poissonsRatio in [0, 0.5] only; nu = -0.5 was not run"]
    assert (frame.status == "failed").all()


@needs_liggghts
def test_hooke_pushes_tangentially_even_without_friction_and_the_dialect_follows(tmp_path):
    """coefficientFriction 0: at first touch LIGGGHTS' shear history is zero, which passes its Coulomb test
    (k_t |xi| <= mu |F_n|, 0 <= 0), so the tangential dashpot c_t v_t acts for a step: the sphere is slowed along
    the wall and spun although mu = 0. The dialect keeps its tangential model at mu = 0 to show the same."""
    scene = Scene(mu=0.0, e_n=(0.5,), angles_deg=(45.0, 89.5))
    engine, reference, final = engine_and_dialect("linear-spring-dashpot", scene, 0.5, steps=1000, tmp_path=tmp_path)
    scale = np.array([1.0, 1.0, 1.0 / scene.radius]) * scene.speed
    assert (np.abs(engine - reference) / np.maximum(np.abs(reference), 1e-9 * scale)).max() < 1e-6
    v_t0 = scene.impacts(0.5)[1]
    assert (final["v_t1"] < v_t0 * (1 - 1e-4)).all() and (final["omega1"] > 0.1).all()

OPTION_CASES = [("linear-spring-dashpot", {"limitForce": "on"}),
                ("linear-spring-dashpot", {"tangential_damping": "off"}),
                ("linear-spring-dashpot", {"ktToKnUser": "on"}),
                ("linear-spring-dashpot", {"tangential": "no_history"}),
                ("hertz-mindlin", {"limitForce": "on"}), ("hertz-mindlin", {"tangential": "no_history"}),
                ("hertz-mindlin", {"tangential_damping": "off"}), ("thornton", {"tangential_damping": "off"})]


@needs_liggghts
@pytest.mark.parametrize("name,options", OPTION_CASES)
def test_options_change_engine_and_dialect_alike(name, options, tmp_path):
    """Each LIGGGHTS option, with spin against the motion: still agreement; and the option changed the result."""
    scene = Scene(e_n=(0.3,), angles_deg=(0.0, 10.0, 30.0, 60.0, 85.0), omega0=-50.0)
    engine, reference, _ = engine_and_dialect(name, scene, 0.3, tmp_path=tmp_path, options=options)
    scale = np.array([1.0, 1.0, 1.0 / scene.radius]) * scene.speed
    assert (np.abs(engine - reference) / np.maximum(np.abs(reference), 1e-9 * scale)).max() < 1e-6
    default, _, _ = engine_and_dialect(name, scene, 0.3, tmp_path=tmp_path)
    ignored = name == "thornton"          # thornton_ning ignores tangential_damping (docs/liggghts-dialect.md)
    assert np.array_equal(default, engine) == ignored


def test_bad_liggghts_options_are_user_errors():
    from harness.infra.errors import UserError
    for name, options in (("hertz-mindlin", {"limitForce": "maybe"}), ("hertz-mindlin", {"speed": "on"}),
                          ("thornton", {"tangential": "no_history"})):
        with pytest.raises(UserError):
            liggghts.dialect(name, options)


@needs_liggghts
def test_lost_atoms_are_a_clear_failure(tmp_path):
    """A sphere thrown out of the domain: LIGGGHTS stops on 'Lost atoms' (thermo_modify lost error)."""
    law = compose("hertz-mindlin")
    scene = Scene(e_n=(0.5,), angles_deg=(0.0,))
    batch = batch_at(liggghts.dialect("hertz-mindlin"), scene, 0.5, 100)
    deck = liggghts.deck(law, scene, replace(replace(batch.spec, step_cap=100000), v_t0=np.array([5e3])))
    with pytest.raises(EngineFailure) as failure:
        liggghts.run_deck(deck.text, deck.n_atoms, 120, str(tmp_path))
    assert "Lost atoms" in failure.value.log_tail


def test_crash_gives_exit_code_and_log_tail(tmp_path, monkeypatch):
    monkeypatch.setenv(liggghts.BINARY_VARIABLE, fake_executable(tmp_path, 'echo "ERROR: something broke"; exit 3'))
    with pytest.raises(EngineFailure, match="exit code 3") as failure:
        liggghts.run_deck("# deck", 1, 30, str(tmp_path))
    assert "something broke" in failure.value.log_tail


def test_hang_is_killed_at_the_timeout(tmp_path, monkeypatch):
    monkeypatch.setenv(liggghts.BINARY_VARIABLE, fake_executable(tmp_path, "echo started; sleep 60"))
    with pytest.raises(EngineFailure, match="did not finish within 1 s") as failure:
        liggghts.run_deck("# deck", 1, 1, str(tmp_path))
    assert "started" in failure.value.log_tail


DUMP_HEAD = "ITEM: TIMESTEP\\n0\\nITEM: NUMBER OF ATOMS\\n{n}\\nITEM: BOX BOUNDS pp pp fm\\n0 1\\n0 1\\n0 1\\n" \
            "ITEM: ATOMS id z vx vz omegay\\n"
ROW = "{i} 0.03 0.1 0.5 0.2\\n"


@pytest.mark.parametrize("dump, spheres, message", [
    (DUMP_HEAD.format(n=2) + ROW.format(i=1) + "2 0.03 0.1 0.5 0.", 2, "cut short: 1 complete rows of 2, the last "
                                                                       "unterminated"),
    (DUMP_HEAD.format(n=3) + ROW.format(i=1), 3, "cut short: 1 complete rows of 3"),
    (DUMP_HEAD.format(n=3) + ROW.format(i=1) + ROW.format(i=2) + ROW.format(i=3), 2, "holds 3 spheres where the deck "
                                                                                    "made 2"),
    ("ITEM: ATOMS id z vx vz omegay\\n1 0.005 0 0.5 0\\n", 1, "malformed"),
])
def test_a_damaged_dump_is_named_and_keeps_the_log(tmp_path, monkeypatch, dump, spheres, message):
    """A dump cut inside its last number, one short of its header, one with an extra sphere, one without a header:
    each refused with what is wrong, and the failure carries the engine's log."""
    body = f'echo "LIGGGHTS (fake) ran"; printf "{dump}" > final.dump'
    monkeypatch.setenv(liggghts.BINARY_VARIABLE, fake_executable(tmp_path, body))
    with pytest.raises(EngineFailure, match=message.replace("(", r"\(")) as failure:
        liggghts.run_deck("# deck", spheres, 30, str(tmp_path))
    assert "LIGGGHTS (fake) ran" in failure.value.log_tail


def test_a_complete_dump_is_read():
    import tempfile
    with tempfile.TemporaryDirectory() as directory:
        path = os.path.join(directory, "final.dump")
        with open(path, "w") as handle:
            handle.write((DUMP_HEAD.format(n=2) + ROW.format(i=2) + ROW.format(i=1)).replace("\\n", "\n"))
        assert liggghts.read_dump(path, 2).tolist() == [[0.03, 0.1, 0.5, 0.2]] * 2


@needs_liggghts
def test_version_is_the_installed_packages():
    """The version harness records in every row is the Debian package's upstream version (dpkg, not the binary)."""
    import shutil
    if shutil.which("dpkg-query") is None:
        pytest.skip("no dpkg-query to ask")
    package = subprocess.run(["dpkg-query", "-W", "-f=${Version}", "liggghts"], capture_output=True, text=True)
    if package.returncode != 0:
        pytest.skip("liggghts is not a Debian package here")
    assert liggghts.ENGINE.version() == package.stdout.split("+")[0].split("-")[0]


def test_missing_binary_is_reported_not_raised(tmp_path, monkeypatch):
    monkeypatch.setenv(liggghts.BINARY_VARIABLE, str(tmp_path / "nowhere"))
    status = liggghts.ENGINE.status("hertz-mindlin")
    nowhere = str(tmp_path / "nowhere")
    assert not status.available and status.reason == f"HARNESS_LIGGGHTS={nowhere!r} is not an executable file"
    with pytest.raises(EngineFailure, match="not found"):
        run_engine([str(tmp_path / "nowhere")], str(tmp_path), 5)


def test_failed_engine_run_keeps_reference_results_and_log_in_compare(tmp_path):
    """A crashing engine: compare still writes the reference rows and prints the engine's log tail."""
    fake = fake_executable(tmp_path, 'echo "ERROR: fake crash for the test"; exit 1')
    env = {**os.environ, liggghts.BINARY_VARIABLE: fake}
    proc = subprocess.run([sys.executable, "-m", "harness", "compare", "--model", "hertz-mindlin", "--en", "0.5",
                           "--angles", "0,45", "--engines", "liggghts", "-o", str(tmp_path / "out")],
                          capture_output=True, text=True, env=env, timeout=600)
    assert proc.returncode == 3                             # the engine asked for by name did not run
    assert "fake crash for the test" in proc.stdout
    import pandas as pd
    frame = pd.read_csv(tmp_path / "out" / "results.csv")
    assert set(frame[frame.engine == "reference"].status) == {"ok"}
    assert set(frame[frame.engine == "liggghts"].status) == {"failed"}


HOSTILE = ["1\nshell rm -rf /", "$(reboot)", "0.5\" ; print \"x", "${lowest}", "1 # comment", "nan", float("inf")]


@pytest.mark.parametrize("value", HOSTILE)
def test_hostile_values_cannot_reach_a_deck(value):
    with pytest.raises(Exception) as scene_error:
        Scene(mu=value)
    assert type(scene_error.value).__name__ == "UserError"
    batch = batch_at(liggghts.dialect("hertz-mindlin"), SCENE, 0.5, 100)
    with pytest.raises(RenderError):
        render(liggghts.TEMPLATES, "batch.in.j2", harness_version="0", law="hertz-mindlin", model="hertz", e_n=value,
               atoms=[], x_lo=0.0, x_hi=1.0, box_half=1.0, z_lo=0.0, z_hi=1.0, skin=0.1, E=1e9, nu=0.3, mu=0.3,
               properties=[], tangential="history", options=[], dt=batch.dt, radius=0.1, rho=1.0, chunk=10,
               max_chunks=10)


@pytest.mark.parametrize("word", ["hertz\nshell ls", "hertz tangential", "$x", "a\"b"])
def test_keywords_outside_the_vocabulary_are_refused(word):
    with pytest.raises(RenderError):
        render(liggghts.TEMPLATES, "batch.in.j2", harness_version="0", law="x", model=word, e_n=0.5, atoms=[], x_lo=0.0,
               x_hi=1.0, box_half=1.0, z_lo=0.0, z_hi=1.0, skin=0.1, E=1e9, nu=0.3, mu=0.3, properties=[],
               tangential="history", options=[], dt=1e-7, radius=0.1, rho=1.0, chunk=10, max_chunks=10)


def test_rendered_deck_holds_only_the_expected_commands():
    """Every line of a real deck starts with a known LIGGGHTS command or is a comment."""
    law = compose("hertz-mindlin")
    batch = batch_at(liggghts.dialect("hertz-mindlin"), SCENE, 0.5, 100)
    text = liggghts.deck(law, SCENE, replace(batch.spec, step_cap=1000)).text
    allowed = {"atom_style", "atom_modify", "boundary", "newton", "communicate", "units", "hard_particles",
               "soft_particles", "region",
               "create_box", "neighbor", "neigh_modify", "fix", "pair_style", "pair_coeff", "timestep",
               "create_atoms", "set", "thermo_style", "thermo", "thermo_modify", "variable", "label", "run", "if",
               "next", "jump", "print", "dump", "dump_modify"}
    for line in text.splitlines():
        if line.strip() and not line.startswith("#"):
            assert line.split()[0] in allowed, line
    assert "%.17g" in text and "thermo_modify lost error" in text


@needs_liggghts
def test_thornton_ning_energy_gain_is_reported_as_a_finding():
    """LIGGGHTS thornton_ning's tangential damping has the wrong sign (docs/liggghts-dialect.md): the sphere leaves with
    more
    tangential + rotational energy than it had; compare must say so, for the engine itself."""
    from harness.analyses.findings import findings
    scene = Scene(**EXAMPLE, e_n=(0.5,), angles_deg=(10.0, 20.0, 60.0))   # mu 0.3: at 10 deg it sticks
    frame, failures = execute(engine_runs(liggghts.ENGINE, compose("thornton"), scene, 200))
    assert not failures
    found = findings(frame)
    gains = found[(found.engine == "liggghts") & (found.kind == "tangential energy gain")]
    assert len(gains) == 1 and "angle 10 deg" in gains.detail.iloc[0]
    row = frame.iloc[0]
    assert row.v_t1 > row.v_t0                      # friction sped the sphere up: impossible for a passive contact


@needs_liggghts
def test_compare_cli_prints_agreement_deviation_attribution(tmp_path):
    proc = subprocess.run([sys.executable, "-m", "harness", "compare", "--model", "linear-spring-dashpot",
                           "--en", "0.5", "--angles", "0,30,60", "--engines", "liggghts", "--verbose",
                           "-o", str(tmp_path)],
                          capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    out = proc.stdout
    assert "agreement (engine vs its dialect" in out and "agreement: ok" in out
    for ingredient in ("tangential-damping", "integrator", "lever", "end"):
        assert f"  {ingredient} " in out or f" {ingredient}  " in out
    import pandas as pd
    frame = pd.read_csv(tmp_path / "results.csv")
    assert set(zip(frame.engine, frame.dialect)) == {("reference", "paper"), ("reference", "liggghts"),
                                                     ("liggghts", "liggghts")}
    assert (frame[frame.engine == "liggghts"].engine_version.astype(str) == liggghts.ENGINE.version()).all()


@needs_liggghts
def test_render_writes_runnable_decks_and_refuses_what_liggghts_cannot_take(tmp_path):
    proc = subprocess.run([sys.executable, "-m", "harness", "render", "--model", "hertz-mindlin", "--engine",
                           "liggghts", "--en", "0.9,0.5", "--angles", "0,30,60", "-o", str(tmp_path / "decks")],
                          capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    decks = sorted((tmp_path / "decks").iterdir())
    assert [d.name for d in decks] == ["liggghts-hertz-mindlin-en0.5.in", "liggghts-hertz-mindlin-en0.9.in"]
    final, _, _ = liggghts.run_deck(decks[0].read_text(), 3, 120, str(tmp_path))
    assert np.all(final[:, 0] > SCENE.radius)                   # every sphere has left the wall
    low = subprocess.run([sys.executable, "-m", "harness", "render", "--model", "hertz-mindlin", "--engine",
                          "liggghts", "--en", "0.03", "-o", str(tmp_path / "low")], capture_output=True, text=True,
                         timeout=120)
    assert low.returncode == 2 and "coefficientRestitution in (0.05, 1]" in low.stderr
    assert not (tmp_path / "low").exists()


@needs_liggghts
@pytest.mark.parametrize("name", ["hertz-mindlin", "linear-spring-dashpot", "walton-braun"])
@pytest.mark.parametrize("wall", ["rigid", "E=2.1e11,nu=0.29"])
def test_walls_of_another_material_run_and_agree_with_the_dialect(name, wall):
    """A second atom type for the wall (a rigid one at youngsModulus 1e300): LIGGGHTS mixes E* and G* as the scene
    does, so the engine agrees with its dialect on the scene's contact; and the wall changed the rebound."""
    from harness.runs.plan import engine_plan
    from harness.runs.request import wall_fields
    scene = Scene(e_n=(0.3, 0.9), angles_deg=(0.0, 30.0, 60.0), psi1_star=None, omega0=-20.0, **wall_fields(wall))
    frame, failures = execute(engine_plan(liggghts.ENGINE, compose(name), scene, 200))
    assert failures == []
    ref, eng = (frame[frame.engine == e].reset_index(drop=True) for e in ("reference", "liggghts"))
    assert np.abs(eng[["v_n1", "v_t1"]].to_numpy() - ref[["v_n1", "v_t1"]].to_numpy()).max() < 1e-6 * scene.speed
    same = execute(engine_runs(liggghts.ENGINE, compose(name), Scene(e_n=(0.3, 0.9), angles_deg=(0.0, 30.0, 60.0),
                                                               psi1_star=None, omega0=-20.0), 200))[0]
    assert np.abs(same.omega1.to_numpy() - eng.omega1.to_numpy()).max() > 1e-3


@needs_liggghts
def test_models_with_per_type_properties_skip_other_walls_with_the_reason():
    from harness.runs.availability import statuses
    from harness.runs.request import Request
    request = Request.from_keywords("thornton", engines=["liggghts"], wall="rigid")
    (status,) = statuses(request)
    assert not status.available and status.reason == "its thornton inputs use a wall of the sphere's own material"
    assert liggghts.ENGINE.walls("hertz-mindlin") == ("same", "other", "rigid")


@needs_liggghts
@pytest.mark.parametrize("name", sorted(liggghts.PAIR_DIALECTS))
@pytest.mark.parametrize("pair", sorted(PAIR_TARGETS))
@pytest.mark.parametrize("omega0", [0.0, -20.0])
def test_liggghts_two_spheres_agree_with_their_dialect_at_equal_dt(name, pair, omega0):
    """pair gran between two spheres, hertz, hooke and hooke/hysteresis x 3 e_n x 6 angles, with and without spin:
    the real binary within 1e-6 of its dialect (slip and torque from each sphere's own R_i - d/2, both spins stepped;
    the normal turning, solver/pair.py; hooke's characteristicVelocity from the pair's R*, m* and E*)."""
    from harness.runs.plan import engine_plan
    from harness.runs.request import scene_from
    scene = scene_from(en=(0.3, 0.6, 0.9), angles=(0.0, 10.0, 30.0, 50.0, 70.0, 85.0), omega0=omega0,
                       target="sphere", **PAIR_TARGETS[pair])
    frame, failures = execute(engine_plan(liggghts.ENGINE, compose(name), scene, 200))
    assert failures == []
    assert agreement(frame, "liggghts") < 1e-6


def test_liggghts_takes_a_sphere_target_for_all_but_thornton_ning():
    from harness.runs.request import scene_from
    law = "hertz-mindlin"
    assert liggghts.ENGINE.target_reason(law, scene_from(target="sphere")) == ""
    assert liggghts.ENGINE.target_reason(law, scene_from(target="sphere", target_radius=0.01, target_fixed=True)) == ""
    assert "no sphere target" in liggghts.ENGINE.target_reason("thornton", scene_from(target="sphere"))
    assert liggghts.ENGINE.target_reason("walton-braun", scene_from(target="sphere")) == ""
    assert liggghts.ENGINE.target_reason("linear-spring-dashpot", scene_from(target="sphere")) == ""
    assert liggghts.ENGINE.target_reason(law, scene_from()) == ""
