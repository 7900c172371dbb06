"""The run plan: what a request asks for, as runs. A run is one batch: one engine running one law in one dialect at
one e_n over every impact of a scene, at one resolution; its key is a hash of everything that determines its
result; its spec is what an engine is told (time step, step cap, impacts, output cadence), computed once
(engines/run.py). compare, cost, check and the hard-case tests all execute plans (execute.py)."""
from dataclasses import replace

from ..engines.run import Run
from ..solver.resolution import CONVERGED


def specs_of(runs):
    """The specs of the runs (but the converged ones), computed now: a time step above a stability limit is refused
    before anything runs."""
    return [run.spec for run in runs if run.resolution != CONVERGED]


def target_of(scene):
    """What the sphere hits: 'sphere' or 'wall'."""
    return "sphere" if scene.spheres else "wall"


def per_e_n(scene):
    """The scene once per e_n (a run's scene)."""
    return [replace(scene, e_n=(e_n,)) for e_n in scene.e_n]


def reference_runs(law, scene, resolution, dialect=None):
    """The reference solver running `dialect` (default: the law itself, the paper's) at every e_n."""
    return [Run("reference", law, dialect or law, s, resolution) for s in per_e_n(scene)]


def wants_states(scene):
    """A gap or times to record states at: the engines then observe the contact too (peak overlap and force)."""
    return scene.gap > 0.0 or bool(scene.at_times)


def engine_runs(engine, law, scene, resolution, options=None, observe=False):
    """An engine running its dialect of `law` at every e_n (observing its contact where the scene wants states)."""
    options = tuple(sorted(dict(options or {}).items()))
    observe = observe or wants_states(scene)
    dialect = engine.dialect(law.name, dict(options), target_of(scene))
    return [Run(engine.NAME, law, dialect, s, resolution, options, observe) for s in per_e_n(scene)]


def engine_plan(engine, law, scene, resolution, options=None):
    """What checks one engine: its dialect on the reference solver, then the engine itself, at equal dt."""
    dialect = engine.dialect(law.name, dict(options or {}), target_of(scene))
    return reference_runs(law, scene, resolution, dialect) + engine_runs(engine, law, scene, resolution, options)


def compare_plan(law, scene, resolution, engines, engine_resolution=None):
    """The paper law on the reference at `resolution`, then each engine ({engine module: options}) with its dialect
    at `engine_resolution` (engines have no converged mode: the paper law's resolution unless that is CONVERGED)."""
    runs = reference_runs(law, scene, resolution)
    for engine, options in engines.items():
        runs += engine_plan(engine, law, scene, engine_resolution or resolution, options)
    return runs
