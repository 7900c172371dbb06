"""Kratos DEMApplication as an engine: the real package (skipped where it is not installed) against theory and
against itself, its script's inputs, and a stand-in interpreter for the failures (crash, hang, cut-short result)."""
import json
import math
import os
import subprocess
import sys

import numpy as np
import pytest
from conftest import PAIR_TARGETS, fake_executable, needs

from harness.commands import main
from harness.engines import kratos
from harness.engines.runner import EngineFailure
from harness.execute import execute
from harness.laws import compose
from harness.plan import engine_runs
from harness.render import RenderError, render
from harness.request import scene_from
from harness.scene import Scene

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
               chunk=10, max_chunks=10, observe=False, spheres=[], materials=[], wall=None)


@pytest.mark.parametrize("word", ["ball\nimport os", "ball\"", "a b"])
def test_material_names_outside_the_vocabulary_are_refused(word):
    with pytest.raises(RenderError):
        render(kratos.TEMPLATES, "batch.py.j2", harness_version="0", law="hertz-mindlin",
               counterpart="DEM_D_Hertz_viscous_Coulomb", e_n=0.5, mu=0.1, impacts=1, target="wall", dt=1e-7,
               chunk=10, max_chunks=10, observe=False, spheres=[], wall=None,
               materials=[{"name": word, "E": 1e9, "nu": 0.3, "rho": 1.0}])


def test_the_script_is_valid_python_with_every_sphere_and_the_law():
    scene = Scene(e_n=(0.5,), angles_deg=ANGLES, psi1_star=None)
    text = ENGINE.render_batch(compose("hertz-mindlin"), scene, the_spec("hertz-mindlin", scene, 100))
    compile(text, "harness_kratos.py", "exec")
    assert text.count('"ball", False)') == len(ANGLES) and "DEM_D_Hertz_viscous_Coulomb" in text
    assert '"GravityZ": 0.0' in text and '"NeighbourSearchFrequency": 1' in text


def test_the_linear_law_gets_the_moduli_that_make_kratos_stiffness_the_laws():
    """Kratos' linear k_n = beta E* pi 0.31225 R (beta 1 at a wall): the script's E makes it the law's k_n."""
    scene = Scene(e_n=(0.5,), angles_deg=(0.0,), psi1_star=None)
    law = compose("linear-spring-dashpot")
    text = ENGINE.render_batch(law, scene, the_spec("linear-spring-dashpot", scene, 100))
    young = float(text.split('"ball": {"YOUNG_MODULUS": ')[1].split(",")[0])
    e_star = young / (2.0 * (1.0 - scene.nu ** 2))
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
    ('printf \'{"rows": [[0, 0.03, 0.1, 0.5, 0.2]], "complete": true}\' > result.json', "holds 1 spheres for 2"),
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
def test_while_its_dialects_are_provisional_kratos_runs_only_when_named(tmp_path, capsys):
    """Every engine (none named): Kratos is skipped with its reason; named, it runs."""
    code = main(["compare", "--model", "hertz-mindlin", "--en", "0.5", "--angles", "10", "-o", str(tmp_path / "all")])
    out = capsys.readouterr().out
    assert "skipped kratos: runs only when named (--engines kratos)" in out and code in (0, 1, 3)
    main(["compare", "--model", "hertz-mindlin", "--engines", "kratos", "--en", "0.5", "--angles", "10", "-o",
          str(tmp_path / "named")])
    assert "kratos 10.4.4" in capsys.readouterr().out


@needs_kratos
def test_compare_on_the_papers_scene_gives_kratos_an_agreement_and_a_physics_verdict(tmp_path):
    """The acceptance command. Its exit code says whether Kratos agrees with its dialect: 0 when it does, 1 while
    the dialect is provisional (docs/kratos-dialect.md); either way both verdicts name kratos."""
    done = subprocess.run([sys.executable, "-m", "harness", "compare", "--model", "hertz-mindlin", "--engines",
                           "kratos", "-o", str(tmp_path / "out")], capture_output=True, text=True, timeout=900)
    assert done.returncode in (0, 1), done.stderr[-2000:]
    out = done.stdout
    verdicts = out.split("does each engine reproduce the paper law")[1]
    physics, agreement = verdicts.split("agreement with its own formulas")[:2]
    assert "kratos 10.4.4" in physics and "kratos 10.4.4" in agreement.split("largest deviation")[0]
    assert (tmp_path / "out" / "report.html").exists()
