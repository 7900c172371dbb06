"""Test configuration: make tests/oracles.py importable as `oracles`; shared helpers and fixtures."""
import sys
from pathlib import Path

import pytest
from hypothesis import settings

sys.path.insert(0, str(Path(__file__).resolve().parent))

# The scene many tests were calibrated on before the paper's scene became the default: the engine notes' example
# (R 5 mm, mu 0.3, impacts at 1 m/s). Tests whose expectations are specific to that scene (a finding measured at
# a given angle, a stick-slip row) pin it; everything else runs on the paper's scene (harness.scenes.scene.Scene()).
EXAMPLE = dict(radius=5e-3, mu=0.3, speed=1.0, material="example-5mm")


# Hypothesis draws the same examples on every run (a CI run cannot fail by the luck of the draw); a defect it finds
# is kept as an explicit test case (tests/test_adaptive_walton_braun.py)
settings.register_profile("repeatable", derandomize=True)
settings.load_profile("repeatable")

# Targets of the two-sphere agreement tests: identical and free, smaller of another material and spinning, frozen
PAIR_TARGETS = {
    "identical": dict(target_material="same", target_omega=0.0),
    "steel, smaller, spinning": dict(target_radius=0.01, target_material="E=2.1e11,nu=0.29,rho=7800",
                                     target_omega=-30.0),
    "frozen": dict(target_radius=0.05, target_fixed=True),
}


def agreement(frame, engine):
    """Worst |engine - dialect| over the rows of each, relative to the largest incident speed V (the spin as
    R omega/V)."""
    import numpy as np
    ref = frame[frame.engine == "reference"].reset_index(drop=True)
    eng = frame[frame.engine == engine].reset_index(drop=True)
    assert len(ref) == len(eng) > 0 and (eng.status == "ok").all() and (ref.status == "ok").all()
    speed = np.hypot(ref.v_n0, ref.v_t0).max()
    worst = [np.max(np.abs(eng[c] - ref[c])) / speed for c in ("v_n1", "v_t1")]
    return max(worst + [np.max(np.abs(eng.omega1 - ref.omega1)) * ref.radius[0] / speed])


def assert_head_on_pair_is_wall(pair, wall_form):
    """Head-on without spin the line of centres never turns: the pair dialect `pair` on the relative motion gives
    what the same law with the submodels `wall_form` gives on the equivalent sphere against a wall, to round-off."""
    import numpy as np
    from harness.laws.law import replace_submodels
    from harness.runs.request import scene_from
    from harness.solver.simulate import simulate
    scene = scene_from(en=(0.3, 0.8), angles=(0.0,), target="sphere", target_radius=0.04)
    a = simulate(pair, scene, steps_per_contact=300)[0]
    b = simulate(replace_submodels(pair, wall_form), scene, steps_per_contact=300)[0]
    for column in ("v_n1", "t_contact", "f_n_max", "overlap_max"):
        assert np.allclose(a[column], b[column], rtol=1e-12, atol=0), column
    assert (a.v_n1 > 0).all()


def nowhere():
    """Every external engine's executable variable, and the directory of other builds, pointing nowhere."""
    import os
    from harness.engines import ENGINES
    from harness.engines.builds import DIRECTORY_VARIABLE
    return {**{engine.VARIABLE: f"/nonexistent/{os.path.basename(engine.EXECUTABLE)}" for engine in ENGINES.values()
               if engine.VARIABLE}, DIRECTORY_VARIABLE: "/nonexistent/engines"}


NOWHERE = nowhere()


def pytest_configure(config):
    """`pytest -m "not engine"`: no engine for this whole session, module-wide fixtures included."""
    if "not engine" in (config.option.markexpr or ""):
        import os
        os.environ.update(NOWHERE)


def needs(engine, flavour=None):
    """Mark a test as running the real `engine` (in `flavour`), skipped where it is not installed."""
    from harness.engines import get_engine
    found = get_engine(engine)
    here = found.available(flavour) if flavour else found.available()

    def mark(test):
        return pytest.mark.engine(pytest.mark.skipif(not here, reason=f"{engine} {flavour or ''} is not installed")
                                  (test))
    return mark


@pytest.fixture(autouse=True)
def engines_only_where_marked(request, monkeypatch):
    """A test not marked `engine` sees no engine (every engine's path points nowhere, for this process and the
    commands it starts): `pytest -m "not engine"` can never run one, and a test that needs one must say so."""
    if "engine" not in request.node.keywords:
        for name, value in NOWHERE.items():
            monkeypatch.setenv(name, value)


def interruptible():
    """Popen's preexec_fn for a child that a test interrupts with SIGINT: the signal back to its default, so that the
    child's Python turns it into KeyboardInterrupt even when this session started with SIGINT ignored (as a
    background job of a non-interactive shell does, and passes on)."""
    import signal
    signal.signal(signal.SIGINT, signal.SIG_DFL)


def fake_executable(directory, body, name="fake-engine"):
    """A small shell script standing in for an engine that crashes, hangs or writes a truncated result."""
    import stat
    path = directory / name
    path.write_text("#!/bin/sh\n" + body + "\n")
    path.chmod(path.stat().st_mode | stat.S_IEXEC)
    return str(path)


@pytest.fixture
def count_kernel_steps(monkeypatch):
    """A function (law, scene, **simulate options) -> (results table, steps the reference kernel took), each step
    one force evaluation: cost counted, not timed."""
    from harness.solver import codes as C
    from harness.solver import simulate as simulation
    kernel = simulation.run_kernel

    def run(law, scene, **options):
        counted = []

        def counting(batch, history_points=0, rows=None):
            out, history, wall = kernel(batch, history_points, rows)
            counted.append(out[:, C.O_STEPS].sum())
            return out, history, wall
        monkeypatch.setattr(simulation, "run_kernel", counting)
        try:
            frame = simulation.simulate(law, scene, **options)[0]
        finally:
            monkeypatch.setattr(simulation, "run_kernel", kernel)
        return frame, float(sum(counted))
    return run


SMALL_CAMPAIGN = dict(laws=["thornton"], e_n=[0.5, 0.9], angles=[10.0, 50.0, 85.0], steps_per_contact=[500])


@pytest.fixture(scope="session")
def small_store(tmp_path_factory):
    """A store of SMALL_CAMPAIGN's 2 tasks, 6 rows (compacted into one data file), built once; copy it to change it."""
    from harness.studies.campaign.driver import run_campaign
    from harness.studies.campaign.executors import InProcess
    from harness.studies.campaign.spec import from_dict
    path = tmp_path_factory.mktemp("small-store") / "store"
    run_campaign(from_dict(SMALL_CAMPAIGN), path, InProcess())
    return path


def snapshot(root):
    """Every path under root with its size and modification time (links not followed): equal snapshots, nothing
    written."""
    import os
    out = {}
    for directory, names, files in os.walk(root):
        for name in names + files:
            path = os.path.join(directory, name)
            info = os.lstat(path)
            out[os.path.relpath(path, root)] = (info.st_size, info.st_mtime_ns)
    return out


def once_per_session(tmp_path_factory, name, compute):
    """compute() run once for the whole test session, every xdist worker included: the first process to take the lock
    runs it and pickles its result, the others (and later calls) unpickle it."""
    import fcntl
    import os
    import pickle
    shared = tmp_path_factory.getbasetemp()
    shared = shared.parent if os.environ.get("PYTEST_XDIST_WORKER") else shared    # this session's, every worker's
    record = shared / f"{name}.pickle"
    with open(shared / f"{name}.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        if not record.exists():
            result = compute()
            partial = record.with_suffix(".partial")
            partial.write_bytes(pickle.dumps(result))
            partial.rename(record)
    return pickle.loads(record.read_bytes())
