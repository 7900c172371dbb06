"""YADE adapter: runs as a Python module without network servers; precision flavours; failure modes."""
import os
import subprocess
import sys
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest
from conftest import PAIR_TARGETS, agreement, assert_head_on_pair_is_wall, fake_executable, needs

from harness.engines import yade
from harness.engines.runner import EngineFailure
from harness.runs.execute import execute
from harness.laws import compose
from harness.scenes.scene import Scene
from harness.solver.simulate import batch_at

needs_yade = needs("yade")
needs_float128 = needs("yade", "float128")

PROBE = r'''
import os, socket, sys
def listening_inodes():
    inodes = set()
    for table in ("/proc/net/tcp", "/proc/net/tcp6"):
        with open(table) as handle:
            for line in handle.readlines()[1:]:
                fields = line.split()
                if fields[3] == "0A":                       # TCP_LISTEN
                    inodes.add(fields[9])
    return inodes
def my_listening_sockets():
    mine = set()
    for fd in os.listdir("/proc/self/fd"):
        try:
            target = os.readlink(f"/proc/self/fd/{fd}")
        except OSError:
            continue
        if target.startswith("socket:["):
            mine.add(target[8:-1])
    return len(mine & listening_inodes())
from yade import *
import atexit, yade.boot
atexit.register(yade.boot.finalize)                        # the probe leaves no /tmp/yade-XXXXXX either
O.bodies.append(utils.sphere((0, 0, 0), 1.0))
O.run(10, True)
if len(sys.argv) > 1:                                      # positive control: the probe does see a listener
    server = socket.socket(); server.bind(("127.0.0.1", 0)); server.listen()
print("LISTENING", my_listening_sockets())
'''


def probe(tmp_path, *args):
    path = tmp_path / "probe.py"
    path.write_text(PROBE)
    proc = subprocess.run([yade.python(), str(path), *args], capture_output=True, text=True, timeout=120,
                          env=yade.environment("double"))
    line = [text for text in proc.stdout.splitlines() if text.startswith("LISTENING")]
    assert line, proc.stdout + proc.stderr
    return int(line[0].split()[1])


@needs_yade
def test_yade_as_a_module_opens_no_listening_socket(tmp_path):
    assert probe(tmp_path, "control") == 1          # the probe can see a listening socket
    assert probe(tmp_path) == 0                     # and YADE imported as harness runs it opens none


def batch_and_script(scene, e_n=0.5, steps=200):
    law = compose("hertz-mindlin")
    batch = batch_at(law, scene, e_n, steps)
    return law, batch, yade.script(law, scene, replace(batch.spec, step_cap=40000))


@needs_yade
@needs_float128
def test_float128_agrees_with_double_on_a_smooth_case(tmp_path):
    """Same script, two precisions: a smooth Hertz-Mindlin impact differs only at round-off of double (~1e-10)."""
    scene = Scene(e_n=(0.5,), angles_deg=(0.0, 30.0, 60.0))
    _, _, text = batch_and_script(scene)
    (tmp_path / "d").mkdir()
    (tmp_path / "q").mkdir()
    double, _, _ = yade.run_script(text, 3, 120, str(tmp_path / "d"), "double")
    quad, _, _ = yade.run_script(text, 3, 120, str(tmp_path / "q"), "float128")
    assert double[:, 0].all() and quad[:, 0].all()              # every sphere left the wall
    scale = np.array([1.0, 1.0, 1.0 / scene.radius])
    rel = np.abs(double[:, 1:] - quad[:, 1:]) / np.maximum(np.abs(quad[:, 1:]), 1e-9 * scale)
    assert rel.max() < 1e-9
    assert rel.max() > 0.0                                      # the flavours really are different arithmetic


def where_yade_made_its_directory(workdir):
    """The path of the directory YADE named in yade_tmpdir.txt, as harness sees it: inside the run's own directory
    where the run had a /tmp of its own (runner.its_own_tmp), else in /tmp itself."""
    from harness.engines.runner import PRIVATE_TMP, its_own_tmp
    made = (workdir / "yade_tmpdir.txt").read_text()
    assert made.startswith("/tmp/yade-")
    return workdir / PRIVATE_TMP / os.path.basename(made) if its_own_tmp() else Path(made)


@needs_yade
def test_a_yade_run_leaves_nothing_in_tmp(tmp_path):
    """YADE makes /tmp/yade-XXXXXX at import whatever TMPDIR says (the script names it in yade_tmpdir.txt); a run
    must not leave it behind."""
    _, _, text = batch_and_script(Scene(e_n=(0.5,), angles_deg=(30.0,)))
    rows, _, _ = yade.run_script(text, 1, 120, str(tmp_path))
    assert rows[0, 0]                                            # the run did happen and the sphere left the wall
    assert not where_yade_made_its_directory(tmp_path).exists()


@needs_yade
def test_a_killed_yade_run_leaves_nothing_in_tmp(tmp_path):
    """YADE removes its /tmp/yade-XXXXXX only when it exits: killed at a timeout, its directory is inside the run's
    own (removed with it), or else harness removes it."""
    from harness.engines.runner import PRIVATE_TMP, its_own_tmp
    _, _, text = batch_and_script(Scene(e_n=(0.5,), angles_deg=(30.0,)))
    with pytest.raises(EngineFailure, match="did not finish"):
        yade.run_script(text + "\nimport time\ntime.sleep(60)\n", 1, 8, str(tmp_path))
    made = where_yade_made_its_directory(tmp_path)
    if its_own_tmp():
        assert made.is_dir() and made.parent == tmp_path / PRIVATE_TMP
    else:
        assert not made.exists()


def test_crash_hang_truncation_give_clear_failures(tmp_path, monkeypatch):
    monkeypatch.setenv(yade.PYTHON_VARIABLE, fake_executable(tmp_path, 'echo "Traceback: boom"; exit 1'))
    with pytest.raises(EngineFailure, match="exit code 1") as failure:
        yade.run_script("pass", 1, 30, str(tmp_path))
    assert "boom" in failure.value.log_tail
    monkeypatch.setenv(yade.PYTHON_VARIABLE, fake_executable(tmp_path, "sleep 60"))
    with pytest.raises(EngineFailure, match="did not finish within 1 s"):
        yade.run_script("pass", 1, 1, str(tmp_path))
    monkeypatch.setenv(yade.PYTHON_VARIABLE, fake_executable(tmp_path, 'printf "0 1 0.1 0.5 0\\n" > result.txt'))
    with pytest.raises(EngineFailure, match="truncated"):
        yade.run_script("pass", 2, 30, str(tmp_path))


@needs_yade
def test_viscel_against_a_wall_uses_half_the_mass():
    """docs/yade-dialect.md: against a Wall, ViscEl's reduced mass is m/2 while the sphere moves with m, so its damping
    ratio
    is g_A(e)/sqrt2 and, with the force clipped at zero, the sphere leaves with Schwager & Poeschel's e of that
    ratio (tests/oracles.py), not with the input e: en 0.5 -> 0.644."""
    import math
    import tempfile
    from oracles import lsd_notension_e
    g_a = -math.log(0.5) / math.sqrt(math.pi ** 2 + math.log(0.5) ** 2)
    scene = Scene(e_n=(0.5,), angles_deg=(0.0,))
    batch = batch_at(yade.dialect("linear-spring-dashpot"), scene, 0.5, 2000)
    with tempfile.TemporaryDirectory() as workdir:
        final, _, _ = yade.ENGINE.run_batch(compose("linear-spring-dashpot"), scene,
                                            replace(batch.spec, step_cap=200000), 300, workdir)
    assert final["v_n1"][0] / scene.speed == pytest.approx(lsd_notension_e(g_a / math.sqrt(2.0)), abs=2e-3)


def test_cundall_strack_is_elastic_whatever_e_n():
    """CundallStrack has no damping: its dialect rebounds a normal impact with e = 1 for any target e_n."""
    from harness.solver.simulate import simulate
    frame = simulate(yade.dialect("linear-spring-dashpot", {"linear": "cundall-strack"}),
                     Scene(e_n=(0.9, 0.3), angles_deg=(0.0,)), steps_per_contact=400)[0]
    assert frame.e_n.to_list() == pytest.approx([1.0, 1.0], abs=1e-5)


def test_unknown_precision_is_a_user_error():
    from harness.infra.errors import UserError
    with pytest.raises(UserError, match="precision must be one of"):
        yade.flavour_path("quad")


@pytest.mark.parametrize("value", ["0.5\")\nimport os; os.system(\"id\")  #", "__import__('os')", float("nan")])
def test_hostile_values_cannot_reach_the_script(value):
    from harness.infra.render import RenderError, render
    with pytest.raises(RenderError):
        render(yade.TEMPLATES, "batch.py.j2", harness_version="0", law="x", law2="Law2_ScGeom_MindlinPhys_Mindlin",
               e_n=value, material="FrictMat", young=1e9, poisson=0.3, rho=1.0, friction_angle=0.3, radius=0.1,
               spheres=[], ig2="Ig2_Wall_Sphere_ScGeom", hertzian=True, ip2="Ip2_FrictMat_FrictMat_MindlinPhys",
               ip2_args=[("en", value)], dt=1e-7, chunk=10, max_chunks=1)


YADE_LAWS = [("hertz-mindlin", {}), ("linear-spring-dashpot", {}),
             ("linear-spring-dashpot", {"linear": "cundall-strack"}), ("walton-braun", {})]


@needs_yade
@pytest.mark.parametrize("name,options", YADE_LAWS)
@pytest.mark.parametrize("e_n", [0.9, 0.5, 0.1])
@pytest.mark.parametrize("omega0", [0.0, -50.0])
def test_engine_agrees_with_its_yade_dialect_at_equal_dt(name, options, e_n, omega0, tmp_path):
    from harness.solver import codes as C
    from harness.solver.simulate import run_kernel
    scene = Scene(e_n=(e_n,), angles_deg=(0.0, 10.0, 30.0, 60.0, 85.0), omega0=omega0)
    batch = batch_at(yade.dialect(name, options), scene, e_n, 200)
    out, _, _ = run_kernel(batch)
    final, _, _ = yade.ENGINE.run_batch(compose(name), scene, replace(batch.spec, step_cap=20000), 120, str(tmp_path),
                                        options)
    assert final["separated"].all()
    engine = np.column_stack([final["v_n1"], final["v_t1"], final["omega1"]])
    reference = out[:, [C.O_VZ, C.O_VX, C.O_W]]
    scale = np.array([1.0, 1.0, 1.0 / scene.radius]) * scene.speed
    assert (np.abs(engine - reference) / np.maximum(np.abs(reference), 1e-9 * scale)).max() < 1e-6


@needs_yade
def test_compare_with_both_engines_prints_the_engine_against_engine_attribution(tmp_path):
    from harness.engines import liggghts
    if not liggghts.ENGINE.available():
        pytest.skip("liggghts is not installed")
    proc = subprocess.run([sys.executable, "-m", "harness", "compare", "--model", "hertz-mindlin", "--engines",
                           "liggghts,yade", "--en", "0.5", "--angles", "0,30,60", "--verbose", "-o", str(tmp_path)],
                          capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    assert "yade against liggghts" in proc.stdout
    assert "attribution (liggghts dialect -> yade dialect" in proc.stdout
    for ingredient in ("damping", "end", "tangential", "integrator", "lever", "slip"):
        assert any(form in proc.stdout for form in (f"\n  {ingredient} ", f"\n {ingredient} ", f" {ingredient}  "))
    import pandas as pd
    frame = pd.read_csv(tmp_path / "results.csv")
    assert ("yade", "yade") in set(zip(frame.engine, frame.dialect))
    assert (frame[frame.engine == "yade"].status == "ok").all()


@needs_yade
def test_precision_gap_double_against_mpfr150_is_round_off():
    """The report's precision figure: double and mpfr150 differ on a smooth impact at round-off level only."""
    from harness.analyses.precision import precision_gap
    from harness.runs.execute import execute
    if not yade.ENGINE.available("mpfr150"):
        pytest.skip("yade-mpfr150 is not installed")
    double, high = yade.precision_runs(compose("hertz-mindlin"), Scene(e_n=(0.5,), angles_deg=(10.0, 30.0, 60.0)))
    assert double.options_dict == {"precision": "double"} and high.options_dict == {"precision": "mpfr150"}
    assert list(double.scene.angles_deg) == [10.0, 60.0]              # the impacts nearest 20 and 60 deg
    gap = precision_gap(execute([double])[0], execute([high])[0], "yade", "mpfr150")
    assert gap["against"] == "mpfr150"
    values = [gap[k] for k in ("v_n1", "v_t1", "omega1")]
    assert max(values) < 1e-9 and max(values) > 0.0


@needs_yade
def test_luding_at_e_n_1_is_refused_with_one_line_not_an_abort():
    """kp = k1 (2/e^2 - 1) = k1 at e_n = 1, which YADE's Ip2_LudingMat_LudingMat_LudingPhys rejects by throwing (the
    interpreter aborted with signal 6): harness refuses it with the reason, and the other e_n still run."""
    from harness.runs.execute import execute
    from harness.runs.plan import engine_runs
    frame, failures = execute(engine_runs(yade.ENGINE, compose("walton-braun"),
                                          Scene(e_n=(0.5, 1.0), angles_deg=(0.0, 45.0)),
                                          200))
    assert [f.message for f in failures] == ["YADE's Luding law needs kp > k1, i.e. e_n < 1; e_n = 1 was not run"]
    by_e_n = frame.groupby("e_n_target").status.unique()
    assert list(by_e_n[0.5]) == ["ok"] and list(by_e_n[1.0]) == ["failed"]


@needs_yade
@pytest.mark.parametrize("pair", sorted(PAIR_TARGETS))
@pytest.mark.parametrize("omega0", [0.0, -20.0])
def test_yade_two_spheres_agree_with_their_dialect_at_equal_dt(pair, omega0):
    """Ig2_Sphere_Sphere_ScGeom + Law2_ScGeom_MindlinPhys_Mindlin between two spheres, hertz-mindlin x 3 e_n x 6
    angles, with and without spin, against targets free or fixed, of the same or another size and material: the real
    module within 1e-6 of its dialect (noRatch slip from R1 + R2, the shear vector turned with the normal, torques
    from R_i - d/2, the dashpot on the plain normal speed: solver/pair.py)."""
    from harness.runs.plan import engine_plan
    from harness.runs.request import scene_from
    scene = scene_from(en=(0.3, 0.6, 0.9), angles=(0.0, 10.0, 30.0, 50.0, 70.0, 85.0), omega0=omega0,
                       target="sphere", **PAIR_TARGETS[pair])
    frame, failures = execute(engine_plan(yade.ENGINE, compose("hertz-mindlin"), scene, 200))
    assert failures == [] and yade.dialect("hertz-mindlin", {}, "sphere").geometry == "pair-vector"
    assert agreement(frame, "yade") < 1e-6


def test_the_yade_pair_stepper_head_on_is_the_wall_stepper():
    """Two code paths, one answer: head-on without spin the normal never turns and nothing slips, so YADE's pair
    stepper on the relative motion equals its wall leapfrog on the equivalent sphere (the pair's own moduli and
    mass), to round-off."""
    assert_head_on_pair_is_wall(yade.dialect("hertz-mindlin", {}, "sphere"),
                                {"geometry": "wall", "slip": "lever", "torque": "lever"})


def test_yade_takes_a_sphere_target_for_hertz_mindlin_only():
    from harness.infra.errors import UserError
    from harness.runs.request import scene_from
    assert yade.ENGINE.target_reason("hertz-mindlin", scene_from(target="sphere", target_fixed=True)) == ""
    assert yade.ENGINE.target_reason("walton-braun", scene_from(target="sphere")) == \
        "its walton-braun inputs have no sphere target yet"
    assert yade.ENGINE.target_reason("walton-braun", scene_from()) == ""
    with pytest.raises(UserError, match="sphere-target inputs run hertz-mindlin only"):
        yade.dialect("linear-spring-dashpot", {}, "sphere")


@needs_yade
@pytest.mark.parametrize("wall", ["rigid", "E=2.1e11,nu=0.29"])
def test_yade_walls_of_another_material_agree_with_the_dialect(wall):
    """A wall of its own FrictMat (a rigid one at young 1e100): Ip2_FrictMat_FrictMat_MindlinPhys mixes E* and G* as
    the scene does, so the module agrees with its dialect on the scene's contact; and the wall changed the rebound."""
    from harness.runs.execute import execute
    from harness.runs.plan import engine_plan, engine_runs
    from harness.runs.request import wall_fields
    kwargs = dict(e_n=(0.3, 0.9), angles_deg=(0.0, 30.0, 60.0), psi1_star=None, omega0=-20.0)
    scene = Scene(**kwargs, **wall_fields(wall))
    frame, failures = execute(engine_plan(yade.ENGINE, compose("hertz-mindlin"), scene, 200))
    assert failures == [] and agreement(frame, "yade") < 1e-6
    same = execute(engine_runs(yade.ENGINE, compose("hertz-mindlin"), Scene(**kwargs), 200))[0]
    engine = frame[frame.engine == "yade"].reset_index(drop=True)
    assert np.abs(same.omega1.to_numpy() - engine.omega1.to_numpy()).max() * scene.radius > 1e-4 * scene.speed
    assert yade.ENGINE.walls("hertz-mindlin") == ("same", "other", "rigid")
    assert yade.ENGINE.walls("walton-braun") == ("same",)


@needs_yade
def test_yade_pairs_observed_contact_agrees_with_the_dialect():
    """Observe mode of the pair script: contact time to the step (one step less than the dialect, which counts the
    step that sees the negative overlap, as against a wall: tests/test_observe.py), peak normal force and overlap
    within the parabola's O(1/N^2) of the dialect's interpolated peaks, with the normal turning."""
    from harness.runs.execute import execute
    from harness.runs.plan import engine_runs, reference_runs
    from harness.runs.request import scene_from
    scene = scene_from(en=(0.5,), angles=(0.0, 40.0, 70.0), omega0=20.0, target="sphere", target_radius=0.04)
    law = compose("hertz-mindlin")
    seen, failures = execute(engine_runs(yade.ENGINE, law, scene, 200, observe=True))
    own, _ = execute(reference_runs(law, scene, 200, yade.dialect("hertz-mindlin", {}, "sphere")))
    assert failures == [] and (seen.status == "ok").all()
    assert np.array_equal(np.round(seen.t_contact / seen.dt), np.round(own.t_contact / own.dt) - 1)
    for column in ("f_n_max", "overlap_max"):
        assert np.max(np.abs(seen[column] / own[column] - 1.0)) < 30.0 / 200 ** 2, column
