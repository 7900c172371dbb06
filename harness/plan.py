"""The run plan: what a request asks for, as runs. A run is one batch: one engine running one law in one dialect at
one e_n over every impact of a scene, at one resolution; its key is a hash of everything that determines its
result; its spec is what an engine is told (time step, step cap, impacts, output cadence), computed once here.
compare, cost, check and the hard-case tests all execute plans (execute.py)."""
import hashlib
import json
import numbers
from dataclasses import asdict, dataclass, replace
from functools import cached_property

from .resolution import CONVERGED, MAX_STEPS_PER_CONTACT, FixedTimeStep, RunSpec, joined, run_spec  # noqa: F401
from .solver.batch import batch_of, join

SCHEMA = 1                    # of the results table and of the key: a change makes every key new


@dataclass(frozen=True)
class Run:
    """One batch of the plan."""
    engine: str
    law: object                 # the law asked for (its name picks an engine's model)
    dialect: object             # the formulas that run: the paper law, or an engine's dialect
    scene: object               # with exactly one e_n
    resolution: object          # steps per contact, FixedTimeStep or CONVERGED
    options: tuple = ()         # the engine's options, (key, value) sorted
    observe: bool = False       # an engine also reports contact time, peak force and overlap
    together: tuple = ()        # scenes of the same material and e_n whose impacts join this run's
    step_cap: int | None = None  # an engine stops every impact after this many steps (a start-up timing), not its own

    @property
    def e_n(self):
        return self.scene.e_n[0]

    @property
    def options_dict(self):
        return dict(self.options)

    @cached_property
    def scene_specs(self):
        """The RunSpec of each of its scenes (the run's own, then those run together), from the dialect and the
        scene: the time step, checked against the stability limit, and the step cap."""
        return tuple(run_spec(self.dialect, s, self.e_n, self.resolution, self.step_cap)
                     for s in (self.scene,) + self.together)

    @cached_property
    def spec(self):
        """What the engine is told (RunSpec), computed once from the dialect and the scenes."""
        return self.scene_specs[0] if not self.together else joined(self.scene_specs)

    def batch(self):
        """The kernel rows of this run's spec (their time step is the engine's too: agreement is at equal dt)."""
        batches = [batch_of(self.dialect, s, spec) for s, spec in zip((self.scene,) + self.together,
                                                                       self.scene_specs)]
        return batches[0] if not self.together else join(batches)

    def key(self, engine_version):
        """sha256 of the engine and its version, the dialect's sub-models, the scene, the resolution and options."""
        resolution = (self.resolution.seconds if isinstance(self.resolution, FixedTimeStep) else self.resolution)
        identity = {"schema": SCHEMA, "engine": self.engine, "version": engine_version, "law": self.law.name,
                    "dialect": self.dialect.dialect, "submodels": self.dialect.describe(),
                    "scenes": [scene_identity(s) for s in (self.scene,) + self.together],
                    "resolution": [type(self.resolution).__name__, resolution], "options": list(self.options),
                    "observe": self.observe, **({"step_cap": self.step_cap} if self.step_cap is not None else {})}
        return hashlib.sha256(json.dumps(identity, sort_keys=True, default=repr).encode()).hexdigest()[:20]


def specs_of(runs):
    """The specs of the runs (but the converged ones), computed now: a time step above a stability limit is refused
    before anything runs."""
    return [run.spec for run in runs if run.resolution != CONVERGED]


def scene_identity(scene):
    """The scene's fields that make a run what it is: not `extra`, nor `spheres` of a wall impact (None); every
    number a float, so that angles 10 and 10.0 are the same run."""
    return {k: as_floats(v) for k, v in asdict(scene).items() if k != "extra" and not (k == "spheres" and v is None)}


def as_floats(value):
    """`value` with every integer (not a boolean) inside it as a float."""
    if isinstance(value, bool) or not isinstance(value, (numbers.Integral, list, tuple, dict)):
        return value
    if isinstance(value, numbers.Integral):
        return float(value)
    if isinstance(value, dict):
        return {k: as_floats(v) for k, v in value.items()}
    return [as_floats(v) for v in value]


def target_of(scene):
    """What the sphere hits: 'sphere' or 'wall'."""
    return "sphere" if scene.spheres else "wall"


def per_e_n(scene):
    """The scene once per e_n (a run's scene)."""
    return [replace(scene, e_n=(e_n,)) for e_n in scene.e_n]


def reference_runs(law, scene, resolution, dialect=None):
    """The reference solver running `dialect` (default: the law itself, the paper's) at every e_n."""
    return [Run("reference", law, dialect or law, s, resolution) for s in per_e_n(scene)]


def engine_runs(engine, law, scene, resolution, options=None, observe=False):
    """An engine running its dialect of `law` at every e_n."""
    options = tuple(sorted(dict(options or {}).items()))
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
