"""Observe mode of the engine adapters: per-impact contact time, peak normal force and peak overlap as each engine
sees them, checked against the engine's reference dialect at equal dt; unobserved decks and scripts unchanged.

Oracles (the reference dialect reproduces the engine's steps to round-off, docs/liggghts-dialect.md,
docs/yade-dialect.md):
- the engine reports the largest per-step value; so does the dialect's per-step history (same samples, to 1e-8);
- `simulate` takes the peak from the parabola through the largest sample y1 and its neighbours y0, y2, which
  exceeds y1 by (y0 - y2)^2 / (8 |y0 - 2 y1 + y2|) <= |y0 - 2 y1 + y2| / 8 ~ |F''| dt^2 / 8, i.e. O(1/N^2)
  relative (at N = 200 about 0.3..2/N^2, up to 30/N^2 where a stiff unloading branch follows the peak);
- contact time is a whole number of steps in both (within dt = t_c/N of the continuous time, O(1/N)): the engine's
  runs from the touch at step 0 to the first position out of contact. The LIGGGHTS dialect ends at that same
  step; the YADE (leapfrog) dialect counts one step more, the step that sees the negative overlap. So they
  differ by exactly 0 and -1 steps, within the one step the step quantisation allows.
"""
import difflib
from dataclasses import replace

import numpy as np
import pytest

from harness.engines import lammps, liggghts, yade
from harness.engines import ENGINES
from harness.engines.runner import EngineFailure
from harness.laws import compose
from harness.scenes.scene import Scene
from harness.solver import codes as C
from harness.solver import layout as L
from harness.solver.simulate import batch_at, run_kernel, simulate

STEPS = 200
ROUND_OFF = 1e-8     # engine vs dialect at equal dt, relative (docs/liggghts-dialect.md, yade-dialect.md: 1e-15..4e-9)
ANGLES = (0.0, 30.0, 60.0)
CASES = ([("liggghts", name, {}, e_n) for name in liggghts.DIALECTS for e_n in (0.5, 0.1)]
         + [("yade", name, {}, e_n) for name in yade.DIALECTS for e_n in (0.5, 0.1)]
         + [("yade", "linear-spring-dashpot", {"linear": "cundall-strack"}, 0.5)]
         + [("lammps", name, {}, e_n) for name in lammps.DIALECTS for e_n in (0.5, 0.1)])
CONTACT_OFFSET = {"liggghts": 0, "yade": -1, "lammps": 0}     # engine minus dialect contact time, in steps (see above)


def peak_and_bound(samples):
    """Largest sample per row and the parabola bound |y0 - 2 y1 + y2|/8 around it (0 at either end)."""
    index = np.nanargmax(samples, axis=1)
    rows = np.arange(len(samples))
    inner = (index > 0) & (index < samples.shape[1] - 1)
    left, right = samples[rows, np.maximum(index - 1, 0)], samples[rows, np.minimum(index + 1, samples.shape[1] - 1)]
    bound = np.where(inner, np.abs(left - 2.0 * samples[rows, index] + right) / 8.0, 0.0)
    return samples[rows, index], bound, index


def dialect_samples(batch, steps):
    """The dialect's normal force and overlap at every step (history stride 1 over 3 contact times); the force
    row starts with the force at first touch (a constant dashpot acts from overlap 0, docs/liggghts-dialect.md,
    docs/yade-dialect.md)."""
    out, history, _ = run_kernel(batch, history_points=3 * steps)
    recorded = ~np.isnan(history[:, :, 0])
    force = np.where(recorded, history[:, :, 2], np.nan)
    overlap = np.where(recorded, history[:, :, 1], np.nan)
    p = batch.params
    touch = np.where(p[:, L.DAMPING_POWER] == 0.0, -p[:, L.DAMPING_C0] * p[:, L.VZ0], 0.0)
    return out, np.column_stack([touch, force]), overlap


def observed_run(engine, name, options, e_n, workdir, observe=True):
    """One observed batch of the engine, with its dialect's batch and reference rows at the same steps."""
    adapter = ENGINES[engine]
    if not adapter.available():
        pytest.skip(f"{engine} is not installed")
    law = adapter.dialect(name, options)
    scene = Scene(e_n=(e_n,), angles_deg=ANGLES, omega0=-50.0)
    batch = batch_at(law, scene, e_n, STEPS)
    final, wall, _ = adapter.run_batch(compose(name), scene, batch.spec, 300, str(workdir), options,
                                       observe=observe)
    return scene, batch, final, wall, simulate(law, scene, steps_per_contact=STEPS)[0]


@pytest.mark.engine
@pytest.mark.parametrize("engine,name,options,e_n", CASES)
def test_observed_peaks_and_contact_time_agree_with_the_dialect(engine, name, options, e_n, tmp_path):
    scene, batch, final, _, reference = observed_run(engine, name, options, e_n, tmp_path)
    out, force, overlap = dialect_samples(batch, STEPS)
    assert final["separated"].all()
    velocities = np.column_stack([final["v_n1"], final["v_t1"], final["omega1"]])
    expected = out[:, [C.O_VZ, C.O_VX, C.O_W]]
    scale = np.array([1.0, 1.0, 1.0 / scene.radius]) * scene.speed
    assert (np.abs(velocities - expected) / np.maximum(np.abs(expected), 1e-9 * scale)).max() < 1e-6
    for metric, samples in (("f_n_max", force), ("overlap_max", overlap)):
        sampled, bound, index = peak_and_bound(samples)
        assert np.all(index < samples.shape[1] - 1)                      # the peak lies inside the history
        seen, parabola = final[metric], reference[metric].to_numpy()
        assert seen == pytest.approx(sampled, rel=ROUND_OFF), metric
        slack = ROUND_OFF * parabola
        assert np.all(parabola - seen >= -slack) and np.all(parabola - seen <= bound + slack), metric
        assert np.all(bound <= 100.0 / STEPS ** 2 * parabola)            # the bound is O(1/N^2), not vacuous
    steps = final["t_contact"] / batch.dt
    assert steps == pytest.approx(np.round(steps), abs=1e-6)             # a whole number of steps
    offset = (final["t_contact"] - reference.t_contact.to_numpy()) / batch.dt
    assert offset == pytest.approx(np.full(len(offset), CONTACT_OFFSET[engine]), abs=1e-6)


@pytest.mark.engine
@pytest.mark.parametrize("engine", ["liggghts", "yade", "lammps"])
def test_observing_does_not_change_the_run(engine, tmp_path):
    """Same velocities bit for bit with and without observe; unobserved rows carry no observations."""
    (tmp_path / "plain").mkdir()
    (tmp_path / "seen").mkdir()
    _, _, plain, _, _ = observed_run(engine, "hertz-mindlin", {}, 0.5, tmp_path / "plain", observe=False)
    _, _, seen, _, _ = observed_run(engine, "hertz-mindlin", {}, 0.5, tmp_path / "seen")
    for key in ("v_n1", "v_t1", "omega1", "separated"):
        assert np.array_equal(plain[key], seen[key])
    assert "t_contact" not in plain and np.all(np.isfinite(seen["t_contact"]))
    assert sorted(p.name for p in (tmp_path / "plain").iterdir()) == sorted(
        p.name for p in (tmp_path / "seen").iterdir() if not p.name.startswith("observe"))


RENDER_CASES = ([(liggghts, name, {}) for name in liggghts.DIALECTS]
                + [(liggghts, "hertz-mindlin", {"limitForce": "on"})]
                + [(yade, name, {}) for name in yade.DIALECTS]
                + [(yade, "linear-spring-dashpot", {"linear": "cundall-strack"})]
                + [(lammps, name, {}) for name in lammps.DIALECTS])


@pytest.mark.parametrize("adapter,name,options", RENDER_CASES)
def test_observe_only_adds_lines_to_the_rendered_input(adapter, name, options):
    """observe=False renders what the adapter rendered before (the default); observe=True only inserts lines."""
    scene = Scene(e_n=(0.5,), angles_deg=ANGLES)
    batch = batch_at(adapter.dialect(name, options), scene, 0.5, 100)
    args = (compose(name), scene, replace(batch.spec, step_cap=10000), options)
    default, plain, seen = adapter.render_batch(*args), adapter.render_batch(*args, observe=False), \
        adapter.render_batch(*args, observe=True)
    assert plain == default and seen != plain and "observe" not in plain
    matcher = difflib.SequenceMatcher(a=plain.splitlines(keepends=True), b=seen.splitlines(keepends=True),
                                      autojunk=False)
    changes = [op for op in matcher.get_opcodes() if op[0] != "equal"]
    assert changes and all(op[0] == "insert" for op in changes)


def write_dump(path, frames):
    """An observe dump in LIGGGHTS' layout: frames of (step, [(id, z, fz), ...])."""
    lines = []
    for step, rows in frames:
        lines += ["ITEM: TIMESTEP", str(step), "ITEM: NUMBER OF ATOMS", str(len(rows)), "ITEM: BOX BOUNDS ff ff ff",
                  "-1 1", "-1 1", "-1 1", "ITEM: ATOMS id z fz "]
        lines += [f"{ident} {z!r} {fz!r} " for ident, z, fz in rows]
    path.write_text("\n".join(lines) + "\n")


def test_liggghts_observation_keeps_the_first_contact_only(tmp_path):
    """Sphere 1 in contact at steps 0..3 (step 2 written twice); sphere 2 at 0..1 and again at 5..6: its second
    contact (larger force and overlap) is not part of the first one."""
    radius, dt = 0.005, 1e-7
    frames = [(0, [(1, 0.005, 10.0), (2, 0.005, 5.0)]), (1, [(1, 0.004, 30.0), (2, 0.0045, 7.0)]),
              (2, [(1, 0.003, 40.0)]), (2, [(1, 0.003, 40.0)]), (3, [(1, 0.0035, 20.0)]), (4, []),
              (5, [(2, 0.001, 99.0)]), (6, [(2, 0.002, 98.0)])]
    write_dump(tmp_path / "observe.dump", frames)
    seen = liggghts.read_observation(str(tmp_path / "observe.dump"), 2, radius, dt)
    assert seen["t_contact"] == pytest.approx([4 * dt, 2 * dt])
    assert seen["f_n_max"].tolist() == [40.0, 7.0]
    assert seen["overlap_max"].tolist() == [radius - 0.003, radius - 0.0045]


def test_malformed_or_missing_observations_are_clear_failures(tmp_path):
    with pytest.raises(EngineFailure, match="wrote no observe dump"):
        liggghts.read_observation(str(tmp_path / "absent"), 1, 0.005, 1e-7)
    (tmp_path / "bad.dump").write_text("ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n2\n")
    with pytest.raises(EngineFailure, match="malformed"):
        liggghts.read_observation(str(tmp_path / "bad.dump"), 2, 0.005, 1e-7)
    write_dump(tmp_path / "one.dump", [(0, [(1, 0.005, 1.0)])])
    with pytest.raises(EngineFailure, match="lacks some sphere ids"):
        liggghts.read_observation(str(tmp_path / "one.dump"), 2, 0.005, 1e-7)
    (tmp_path / "observe.txt").write_text("0 0 9 1.5 2e-6\n1 -1 -1 nan nan\nEND\n")
    with pytest.raises(EngineFailure, match="observed no contact"):
        yade.read_observation(str(tmp_path / "observe.txt"), 2, 1e-7)
    (tmp_path / "observe.txt").write_text("0 0 9 1.5 2e-6\n")
    with pytest.raises(EngineFailure, match="observe file is truncated"):
        yade.read_observation(str(tmp_path / "observe.txt"), 1, 1e-7)


@pytest.mark.engine
@pytest.mark.parametrize("engine", ["liggghts", "yade"])
def test_sweep_fills_the_observed_columns_only_when_asked(engine):
    """Runs planned with observe=True, two e_n sharing one engine process: t_contact, f_n_max, overlap_max of the
    engine rows match the dialect within the quantisation bounds above (contact steps exactly, with the engine's
    offset); observe=False leaves them NaN."""
    from harness.runs.execute import execute
    from harness.runs.plan import engine_runs
    adapter = ENGINES[engine]
    if not adapter.available():
        pytest.skip(f"{engine} is not installed")
    scene = Scene(e_n=(0.5, 0.9), angles_deg=(0.0, 45.0))
    law = compose("hertz-mindlin")
    reference = simulate(adapter.dialect(law.name), scene, steps_per_contact=STEPS)[0]
    seen, failures = execute(engine_runs(adapter, law, scene, STEPS, observe=True))
    plain = execute(engine_runs(adapter, law, scene, STEPS))[0]
    assert failures == [] and (seen.status == "ok").all()
    for column in ("f_n_max", "overlap_max"):
        assert seen[column].to_numpy() == pytest.approx(reference[column].to_numpy(), rel=2.0 / STEPS ** 2)
    steps = np.round(seen.t_contact.to_numpy() / seen.dt.to_numpy())
    expected = np.ceil(reference.t_contact.to_numpy() / reference.dt.to_numpy() - 1e-9) + CONTACT_OFFSET[engine]
    assert np.array_equal(steps, expected), (steps, expected)
    assert plain[["t_contact", "f_n_max", "overlap_max"]].isna().all().all()
