"""Kratos DEMApplication as an engine: the real package (skipped where it is not installed) against theory and
against itself, its script's inputs, and a stand-in interpreter for the failures (crash, hang, cut-short result)."""
import json
import math
import os
import subprocess
import sys

import numpy as np
import pytest
from conftest import PAIR_TARGETS, agreement, fake_executable, needs

from harness.commands import main
from harness.engines import kratos
from harness.engines.runner import EngineFailure
from harness.runs.execute import execute
from harness.laws import compose
from harness.runs.plan import engine_plan, engine_runs
from harness.infra.render import RenderError, render
from harness.runs.request import scene_from
from harness.scenes.scene import Scene

needs_kratos = needs("kratos")
ENGINE = kratos.ENGINE
ANGLES = (0.0, 10.0, 30.0, 50.0, 70.0, 85.0)


def kratos_rows(law, scene, resolution, observe=False):
    frame, failures = execute(engine_runs(ENGINE, compose(law), scene, resolution, observe=observe))
    assert failures == [] and (frame.status == "ok").all()
    return frame


def the_spec(law, scene, resolution):
    return engine_runs(ENGINE, compose(law), scene, resolution)[0].spec


@needs_kratos
@pytest.mark.parametrize("e_n", [0.25, 0.5, 0.75, 0.9])
def test_a_normal_impact_returns_the_target_restitution(e_n):
    """Kratos' Hertz dashpot is the paper's Appendix B fit: a normal impact at a fine step returns the e whose gamma
    the fit gives, within the fit's own accuracy (~3e-4 over 0.05..0.9, docs/laws.md) and the step's error. The
    oracle is the target e itself, not the adapter's dialect."""
    frame = kratos_rows("hertz-mindlin", Scene(e_n=(e_n,), angles_deg=(0.0,), psi1_star=None), 2000)
    achieved = frame.v_n1 / frame.v_n0
    assert abs(achieved.iloc[0] - e_n) < 1e-3


@needs_kratos
@pytest.mark.parametrize("name", sorted(kratos.DIALECTS))
@pytest.mark.parametrize("wall", ["same", "rigid"])
@pytest.mark.parametrize("omega0", [0.0, -20.0])
def test_kratos_agrees_with_its_dialect_at_equal_dt(name, wall, omega0):
    """Every supported law x 3 e_n x 6 angles, with and without spin, against a wall of the sphere's material and a
    rigid one: the real package within 1e-6 of its dialect (docs/kratos-dialect.md)."""
    scene = scene_from(en=(0.3, 0.6, 0.9), angles=ANGLES, omega0=omega0, wall=wall)
    frame, failures = execute(engine_plan(ENGINE, compose(name), scene, 200))
    assert failures == []
    assert agreement(frame, "kratos") < 1e-6


KRATOS_PAIRS = {"identical": PAIR_TARGETS["identical"],
                "larger, denser, spinning": dict(target_radius=0.05, target_material="E=7e10,nu=0.3,rho=7800",
                                                 target_omega=-30.0)}


@needs_kratos
@pytest.mark.parametrize("name", sorted(kratos.PAIR_DIALECTS))
@pytest.mark.parametrize("pair", sorted(KRATOS_PAIRS))
@pytest.mark.parametrize("omega0", [0.0, 20.0])
def test_kratos_two_spheres_agree_with_their_dialect_at_equal_dt(name, pair, omega0):
    """Two spheres, every supported law x 3 e_n x 6 angles, with and without spin, against a free target of the
    projectile's moduli, identical or larger, denser and spinning: the real package within 1e-6 of its pair
    dialect."""
    scene = scene_from(en=(0.3, 0.6, 0.9), angles=ANGLES, omega0=omega0, target="sphere", **KRATOS_PAIRS[pair])
    frame, failures = execute(engine_plan(ENGINE, compose(name), scene, 200))
    assert failures == []
    assert agreement(frame, "kratos") < 1e-6


@pytest.mark.parametrize("pair,words", [("frozen", "held target's mass"), ("steel, smaller, spinning", "moduli")])
def test_targets_its_pair_dialects_do_not_hold_for_are_refused_with_the_ingredient(pair, words):
    """A frozen target (its mass still in Kratos' damping: e_n 0.40 for a target 0.3, measured) and a target of other
    moduli (each lever R_i - d E_j/(E_i + E_j)) have no Kratos dialect: refused with the ingredient, not run."""
    scene = scene_from(en=(0.5,), angles=(30.0,), target="sphere", **PAIR_TARGETS[pair])
    assert words in ENGINE.target_reason("hertz-mindlin", scene)
    assert ENGINE.target_reason("hertz-mindlin", scene_from(en=(0.5,), angles=(30.0,), target="sphere")) == ""


@needs_kratos
def test_observed_contact_is_hertz_when_elastic():
    """e = 1 (Kratos' gamma 0 above e 0.999): the contact time, peak force and overlap of a normal impact are Hertz's
    closed forms (Johnson): t_c = 2.8683 (m^2/(R E*^2 V))^(1/5), d_max = (15 m V^2/(16 E* sqrt R))^(2/5)."""
    scene = Scene(e_n=(1.0,), angles_deg=(0.0,), psi1_star=None)
    frame = kratos_rows("hertz-mindlin", scene, 2000, observe=True)
    c, speed = scene.contact, scene.speed
    overlap = (15.0 * c.mass * speed ** 2 / (16.0 * c.E_star * math.sqrt(c.radius))) ** 0.4
    force = 4.0 / 3.0 * c.E_star * math.sqrt(c.radius) * overlap ** 1.5
    duration = 2.0 * math.sqrt(math.pi) * math.gamma(1.4) / math.gamma(0.9) * (15.0 / 16.0) ** 0.4 * \
        (c.mass ** 2 / (c.radius * c.E_star ** 2 * speed)) ** 0.2
    assert frame.overlap_max.iloc[0] == pytest.approx(overlap, rel=1e-3)
    assert frame.f_n_max.iloc[0] == pytest.approx(force, rel=2e-3)
    assert frame.t_contact.iloc[0] == pytest.approx(duration, rel=2e-3)
    assert frame.v_n1.iloc[0] == pytest.approx(speed, rel=1e-6)


@needs_kratos
@pytest.mark.parametrize("law", ["hertz-mindlin", "linear-spring-dashpot"])
def test_one_batched_run_gives_what_one_impact_runs_give(law):
    """Impacts batched as far-apart spheres in one Kratos run never interact: each comes back as it does alone."""
    scene = Scene(e_n=(0.5,), angles_deg=ANGLES, psi1_star=None, omega0=-20.0)
    batched = kratos_rows(law, scene, 200)
    for k, angle in enumerate(ANGLES):
        alone = kratos_rows(law, Scene(e_n=(0.5,), angles_deg=(angle,), psi1_star=None, omega0=-20.0), 200)
        for column in ("v_n1", "v_t1", "omega1"):
            assert alone[column].iloc[0] == pytest.approx(batched[column].iloc[k], rel=1e-12, abs=1e-12), column


@needs_kratos
@pytest.mark.parametrize("law", ["hertz-mindlin", "linear-spring-dashpot"])
def test_two_spheres_conserve_momentum(law, tmp_path):
    """A smaller steel sphere hit obliquely: the sum of m v over both spheres of every pair is what the projectile
    brought, to round-off, read from the spheres' own final velocities."""
    scene = scene_from(en=(0.5,), angles=(0.0, 30.0, 70.0), target="sphere",
                       **PAIR_TARGETS["steel, smaller, spinning"])
    spec = the_spec(law, scene, 200)
    ENGINE.run_batch(compose(law), scene, spec, 120, str(tmp_path))
    with open(tmp_path / "batch0" / "result.json") as handle:
        rows = np.array(json.load(handle)["rows"])
    projectile, target = scene.spheres
    m1, m2 = projectile.mass, target.mass
    before_x, before_z = m1 * spec.v_t0, -m1 * spec.v_n0
    after_x = m1 * rows[0::2, 2] + m2 * rows[1::2, 2]
    after_z = m1 * rows[0::2, 3] + m2 * rows[1::2, 3]
    assert np.allclose(after_x, before_x, rtol=0, atol=1e-10 * m1 * scene.speed)
    assert np.allclose(after_z, before_z, rtol=0, atol=1e-10 * m1 * scene.speed)
    assert np.all(rows[1::2, 3] < 0)                  # the target was pushed away


@needs_kratos
def test_the_build_records_the_dem_library_and_the_installed_version():
    build = ENGINE.build()
    assert build["version"] == "10.4.4" and ENGINE.version() == "10.4.4"
    assert build["binary"].endswith("libKratosDEMCore.so") and len(build["sha256"]) == 64


@needs_kratos
def test_a_directory_with_quotes_and_spaces_injects_nothing(tmp_path):
    """The script names no path: it runs in its batch's directory, whatever that directory is called."""
    workdir = tmp_path / "it's a \"dir\" $(touch pwned); x"
    workdir.mkdir()
    scene = Scene(e_n=(0.5,), angles_deg=(30.0,), psi1_star=None)
    final, wall, _ = ENGINE.run_batch(compose("hertz-mindlin"), scene, the_spec("hertz-mindlin", scene, 100), 120,
                                      str(workdir))
    assert final["separated"].all() and wall > 0
    assert not (tmp_path / "pwned").exists() and not os.path.exists("pwned")


HOSTILE = ["1\nimport os; os.system('x')", "0.5); os.system('x'", "nan", float("inf"), "__import__('os')"]


@pytest.mark.parametrize("value", HOSTILE)
def test_hostile_values_cannot_reach_a_script(value):
    with pytest.raises(RenderError):
        render(kratos.TEMPLATES, "batch.py.j2", harness_version="0", law="hertz-mindlin",
               counterpart="DEM_D_Hertz_viscous_Coulomb", e_n=value, mu=0.1, impacts=1, target="wall", dt=1e-7,
               chunk=10, max_chunks=10, named=[], observe=False, spheres=[], materials=[], wall=None)


@pytest.mark.parametrize("word", ["ball\nimport os", "ball\"", "a b"])
def test_material_names_outside_the_vocabulary_are_refused(word):
    with pytest.raises(RenderError):
        render(kratos.TEMPLATES, "batch.py.j2", harness_version="0", law="hertz-mindlin",
               counterpart="DEM_D_Hertz_viscous_Coulomb", e_n=0.5, mu=0.1, impacts=1, target="wall", dt=1e-7,
               chunk=10, max_chunks=10, named=[], observe=False, spheres=[], wall=None,
               materials=[{"name": word, "E": 1e9, "nu": 0.3, "rho": 1.0}])


def test_the_script_is_valid_python_with_every_sphere_and_the_law():
    scene = Scene(e_n=(0.5,), angles_deg=ANGLES, psi1_star=None)
    text = ENGINE.render_batch(compose("hertz-mindlin"), scene, the_spec("hertz-mindlin", scene, 100))
    compile(text, "harness_kratos.py", "exec")
    assert text.count('"ball", False)') == len(ANGLES) and "DEM_D_Hertz_viscous_Coulomb" in text
    assert '"GravityZ": 0.0' in text and '"NeighbourSearchFrequency": 1' in text


def test_the_script_gives_kratos_the_scenes_moduli_and_its_dialect_takes_kratos_stiffness():
    """Kratos' linear k_n = E* pi 0.31225 R against a wall (DEM_D_Linear_viscous_Coulomb): the script passes the
    scene's E and nu unchanged, and the dialect's k_n is that formula of them."""
    scene = Scene(e_n=(0.5,), angles_deg=(0.0,), psi1_star=None)
    law = ENGINE.dialect("linear-spring-dashpot", {}, "wall")
    text = ENGINE.render_batch(law, scene, the_spec("linear-spring-dashpot", scene, 100))
    young = float(text.split('"ball": {"YOUNG_MODULUS": ')[1].split(",")[0])
    assert young == scene.E
    e_star = scene.E / (2.0 * (1.0 - scene.nu ** 2))
    k_n = law.normal.parameters(scene.contact, 0.5, scene.speed).values[0]
    assert e_star * math.pi * 0.31225 * scene.radius == pytest.approx(k_n, rel=1e-12)


def test_a_crashing_kratos_gives_its_exit_code_and_log_tail(tmp_path, monkeypatch):
    crash = 'echo "RuntimeError: Error: bad mdpa"; exit 3'
    monkeypatch.setenv(kratos.PYTHON_VARIABLE, fake_executable(tmp_path, crash))
    scene = Scene(e_n=(0.5,), angles_deg=(10.0,), psi1_star=None)
    with pytest.raises(EngineFailure, match="exit code 3") as failure:
        ENGINE.run_batch(compose("hertz-mindlin"), scene, the_spec("hertz-mindlin", scene, 100), 30, str(tmp_path))
    assert "bad mdpa" in failure.value.log_tail
    frame, failures = execute(engine_runs(ENGINE, compose("hertz-mindlin"), scene, 100))
    assert (frame.status == "failed").all() and "bad mdpa" in failures[0].log_tail


def test_a_hung_kratos_is_killed_at_the_timeout_and_leaves_no_process(tmp_path, monkeypatch):
    marker = tmp_path / "pid"
    monkeypatch.setenv(kratos.PYTHON_VARIABLE, fake_executable(tmp_path, f'echo started; echo $$ > "{marker}"; '
                                                                         'sleep 60'))
    scene = Scene(e_n=(0.5,), angles_deg=(10.0,), psi1_star=None)
    with pytest.raises(EngineFailure, match="did not finish within 1 s") as failure:
        ENGINE.run_batch(compose("hertz-mindlin"), scene, the_spec("hertz-mindlin", scene, 100), 1, str(tmp_path))
    assert "started" in failure.value.log_tail
    with pytest.raises(ProcessLookupError):
        os.kill(int(marker.read_text()), 0)


@pytest.mark.parametrize("body, message", [
    ('printf \'{"rows": [[0, 0.03, 0.1, 0.5, 0.2]], "compl\' > result.json', "malformed"),
    ('printf \'{"rows": [[0, 0.03, 0.1, 0.5, 0.2]]}\' > result.json', "truncated"),
    ('printf \'{"rows": [[0, 0.03, 0.1, 0.5, 0.2]], "complete": true}\' > result.json', "holds 1 sphere for 2"),
    ("true", "wrote no result file"),
])
def test_a_damaged_result_is_named_and_keeps_the_log(tmp_path, monkeypatch, body, message):
    monkeypatch.setenv(kratos.PYTHON_VARIABLE, fake_executable(tmp_path, 'echo "Kratos (fake) ran"; ' + body))
    scene = Scene(e_n=(0.5,), angles_deg=(10.0, 20.0), psi1_star=None)
    with pytest.raises(EngineFailure, match=message) as failure:
        ENGINE.run_batch(compose("hertz-mindlin"), scene, the_spec("hertz-mindlin", scene, 100), 30, str(tmp_path))
    assert "Kratos (fake) ran" in failure.value.log_tail


def test_a_missing_kratos_is_a_reason_and_named_alone_exits_3(tmp_path, capsys):
    """Not marked `engine`: Kratos is nowhere here. Its status says how to install it; `--engines kratos` exits 3."""
    status = ENGINE.status("hertz-mindlin")
    assert not status.available and kratos.PYTHON_VARIABLE in status.reason
    code = main(["compare", "--model", "hertz-mindlin", "--engines", "kratos", "--en", "0.5", "--angles", "10",
                 "-o", str(tmp_path / "out"), "--quiet"])
    assert code == 3


def test_without_a_variable_or_prefix_the_reason_names_the_installer(monkeypatch, tmp_path):
    monkeypatch.delenv(kratos.PYTHON_VARIABLE, raising=False)
    monkeypatch.setenv("HARNESS_ENGINES_DIR", str(tmp_path))
    assert ENGINE.binary() == "" and not ENGINE.available()
    assert "tools/install_kratos.sh" in ENGINE.missing_reason()


@needs_kratos
def test_compare_on_the_papers_scene_gives_kratos_an_agreement_and_a_physics_verdict(tmp_path):
    """The acceptance command: Kratos agrees with its dialect (exit 0), and both verdicts name it."""
    done = subprocess.run([sys.executable, "-m", "harness", "compare", "--model", "hertz-mindlin", "--engines",
                           "kratos", "-o", str(tmp_path / "out")], capture_output=True, text=True, timeout=900)
    assert done.returncode == 0, done.stderr[-2000:]
    out = done.stdout
    verdicts = out.split("does each engine reproduce the paper law")[1]
    physics, agreement = verdicts.split("agreement with its own formulas")[:2]
    assert "kratos 10.4.4" in physics and "kratos 10.4.4" in agreement.split("largest deviation")[0]
    assert (tmp_path / "out" / "report.html").exists()
