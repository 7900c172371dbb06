"""A run: one batch an engine is asked to compute (one law in one dialect at one e_n over every impact of a scene, at
one resolution; runs/plan.py makes them); its spec is what the engine is told, its key a hash of everything that
determines its result."""
import hashlib
import json
import numbers
from dataclasses import asdict, dataclass
from functools import cached_property

from ..solver.batch import batch_of, join
from ..solver.resolution import FixedTimeStep, joined, run_spec

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


UNKEYED_DEFAULTS = {"spheres": None, "gap": 0.0, "at_times": ()}     # at these values a field leaves the key as it was


def scene_identity(scene):
    """The scene's fields that make a run what it is: not `extra`, nor the fields at UNKEYED_DEFAULTS; every number a
    float, so that angles 10 and 10.0 are the same run."""
    return {k: as_floats(v) for k, v in asdict(scene).items()
            if k != "extra" and not (k in UNKEYED_DEFAULTS and v == UNKEYED_DEFAULTS[k])}


def as_floats(value):
    """`value` with every integer (not a boolean) inside it as a float."""
    if isinstance(value, bool) or not isinstance(value, (numbers.Integral, list, tuple, dict)):
        return value
    if isinstance(value, numbers.Integral):
        return float(value)
    if isinstance(value, dict):
        return {k: as_floats(v) for k, v in value.items()}
    return [as_floats(v) for v in value]
