"""The engine registry: every engine, the reference solver included, is a subclass of the Engine base class, which
declares every hook the rest of harness asks an engine for."""
import ast
import pathlib

import pytest

import harness
from harness.engines import ENGINES, EXTERNAL, get_engine
from harness.engines.base import Engine
from harness.engines.protocol import Option, Status
from harness.infra.errors import UserError
from harness.laws import LAWS

ENGINE_NAMES = ("engine", "adapter", "found")      # what callers call an engine object


def hooks_called_outside_engines():
    """{attribute: file} of every attribute harness reads from an engine object outside harness/engines:
    `engine.X`, `adapter.X`, `ENGINES[...].X`, `get_engine(...).X`."""
    package = pathlib.Path(harness.__file__).parent
    found = {}
    for path in package.rglob("*.py"):
        if "engines" in path.relative_to(package).parts:
            continue
        for node in ast.walk(ast.parse(path.read_text())):
            if not isinstance(node, ast.Attribute):
                continue
            value = node.value
            named = isinstance(value, ast.Name) and value.id in ENGINE_NAMES
            indexed = isinstance(value, ast.Subscript) and isinstance(value.value, ast.Name) and \
                value.value.id == "ENGINES"
            called = isinstance(value, ast.Call) and isinstance(value.func, ast.Name) and value.func.id == "get_engine"
            if named or indexed or called:
                found.setdefault(node.attr, str(path.relative_to(package)))
    return found


def test_every_hook_harness_asks_an_engine_for_is_declared_on_the_base_class():
    """A new engine that overrides what differs has every hook a command uses (and run_batch, which the benchmarks
    time engines with)."""
    called = hooks_called_outside_engines()
    assert {"run", "dialect", "status", "walls", "target_reason", "render"} <= set(called)
    assert callable(getattr(Engine, "run_batch", None))
    missing = {name: where for name, where in called.items()
               if not hasattr(Engine, name) and not hasattr(str, name)}     # `engine` is at times an engine's name
    assert not missing, missing


@pytest.mark.parametrize("name", list(ENGINES))
def test_every_engine_is_an_engine(name):
    engine = ENGINES[name]
    assert isinstance(engine, Engine) and type(engine) is not Engine
    assert engine.NAME == name
    assert all(isinstance(o, Option) and o.default == o.values[0] for o in engine.OPTIONS.values())
    assert set(engine.COUNTERPARTS) <= set(LAWS)
    assert engine.COLOUR and engine.DASHES
    for law in LAWS:
        status = engine.status(law)
        assert isinstance(status, Status) and status.name == name
        if status.available:
            assert engine.supports(law) and engine.dialect(law, {}).name == law
        else:
            assert status.reason, (name, law)


def test_the_reference_is_an_engine_that_runs_every_law():
    reference = ENGINES["reference"]
    assert reference.available() and all(reference.supports(law) for law in LAWS)
    assert "reference" not in EXTERNAL and set(EXTERNAL) == set(ENGINES) - {"reference"}


@pytest.mark.parametrize("name", EXTERNAL)
def test_undeclared_options_are_one_line_user_errors(name):
    engine = ENGINES[name]
    law = next(iter(engine.COUNTERPARTS))
    with pytest.raises(UserError, match=f"unknown {name} option 'colour'"):
        engine.dialect(law, {"colour": "red"})
    if not engine.OPTIONS:
        return
    key, option = next(iter(engine.OPTIONS.items()))
    with pytest.raises(UserError, match=f"{name} option {key} takes {' or '.join(option.values)}"):
        engine.dialect(law, {key: "no-such-value"})


def test_an_unknown_engine_names_the_known_ones():
    with pytest.raises(UserError, match="unknown engine 'abaqus'; known: reference, liggghts, yade"):
        get_engine("abaqus")


@pytest.mark.parametrize("name", [pytest.param(n, marks=[pytest.mark.engine, pytest.mark.skipif(
    not ENGINES[n].available(), reason=f"{n} is not installed")]) for n in ("liggghts", "lammps")])
def test_decks_sharing_one_process_each_get_their_own_step_budget(name):
    """`clear` keeps LIGGGHTS' and LAMMPS' loop variables: a deck's `variable chunk loop` would carry on an earlier
    deck's count and stop before its spheres separate. 120 decks of one two-sphere impact in one process (each uses
    ~10 of its ~400 chunks, so without the deletion the later ones run out) all return the same, separated rebound."""
    from harness.scenes.bodies import Sphere
    from harness.laws import compose
    from harness.runs.plan import engine_runs
    from harness.scenes.scene import Scene
    from harness.solver.two_spheres import reduce
    engine = ENGINES[name]
    scene = Scene(e_n=(0.5,), angles_deg=None, v_t=(0.0,), speed=0.4, radius=0.1, E=7e10, nu=0.33, rho=2700.0)
    (run,) = engine_runs(engine, compose("hertz-mindlin"), reduce(scene, Sphere(0.1, 7e10, 0.33, 2700.0)), 100)
    done = engine.run([run] * 120)
    frames = [frame for frame, failure in done if failure is None]
    assert len(frames) == 120 and all((frame.status == "ok").all() for frame in frames)
    assert len({round(float(frame.e_n.iat[0]), 12) for frame in frames}) == 1


def test_a_run_spec_covers_its_step_cap_in_tenths_of_a_contact():
    """The spec's cadence: a check every tenth of a contact (at least 10 steps), and enough checks to reach the cap;
    a start-up run's own cap is part of its key, a plain run's key does not change."""
    from dataclasses import replace
    from harness.laws import compose
    from harness.runs.plan import engine_runs
    from harness.scenes.scene import Scene
    scene = Scene(e_n=(0.5,), angles_deg=(0.0, 40.0))
    for steps in (20, 1000, 4567):
        (run,) = engine_runs(ENGINES["liggghts"], compose("hertz-mindlin"), scene, steps)
        spec = run.spec
        assert spec.chunk == max(10, steps // 10) and spec.steps_per_contact == pytest.approx(steps)
        assert spec.chunks * spec.chunk > spec.step_cap >= (spec.chunks - 1) * spec.chunk
        assert spec.step_cap > 20 * steps and spec.impacts == 2       # at least 20 contact times (solver/batch.py)
        capped = replace(run, step_cap=1)
        assert capped.spec.step_cap == 1 and capped.spec.chunks == 1 and capped.spec.dt == spec.dt
        assert capped.key("v") != run.key("v") and replace(run).key("v") == run.key("v")


@pytest.mark.parametrize("name", [pytest.param(n, marks=[pytest.mark.engine, pytest.mark.skipif(
    not ENGINES[n].available(), reason=f"{n} is not installed")]) for n in EXTERNAL])
def test_the_step_cap_of_a_run_reaches_the_engine(name):
    """Capped at its first check (a tenth of a contact at 1000 steps per contact) no sphere can have left the wall;
    with the plan's own cap every one does: the engine stepped as far as the spec said."""
    from dataclasses import replace
    from harness.laws import compose
    from harness.runs.plan import engine_runs
    from harness.scenes.scene import Scene
    engine = ENGINES[name]
    (run,) = engine_runs(engine, compose("hertz-mindlin"), Scene(e_n=(0.5,), angles_deg=(0.0, 30.0)), 1000)
    (capped, failure), (full, _) = engine.run([replace(run, step_cap=1), run])
    assert failure is None and (capped.status == "no-separation").all()
    assert (full.status == "ok").all()
