"""An engine's alternative inputs for a law: every combination of the values of its declared options that its
inputs accept for the law, one per distinct dialect (precision-only options give none), each given the restitution
input that meets every target e_n, and its rows on the reference (its formulas in place of the engine)."""
import itertools
from dataclasses import dataclass, replace

import pandas as pd

from ..errors import UserError
from ..solver.simulate import simulate
from .restitution import restitution_input


@dataclass
class Alternative:
    """One choice of engine options, the restitution input per target e_n, and its formulas' rows on the scene."""
    options: dict
    dialect: object
    inputs: list
    rows: pd.DataFrame | None = None

    @property
    def label(self):
        return ", ".join(f"{k}={v}" for k, v in self.options.items()) or "default options"

    @property
    def reachable(self):
        return [i for i in self.inputs if i.value is not None]


def alternatives(engine, law_name, target="wall"):
    """[(options, dialect)] of every combination of the engine's option values that composes for the law, one per
    distinct dialect, its default options first."""
    keys = list(engine.OPTIONS)
    out, seen = [], set()
    for values in itertools.product(*(engine.OPTIONS[k].values for k in keys)):
        options = {k: v for k, v, o in zip(keys, values, (engine.OPTIONS[k] for k in keys)) if v != o.values[0]}
        try:
            dialect = engine.dialect(law_name, options, target)
        except UserError:
            continue
        identity = tuple(sorted((k, str(v)) for k, v in dialect.describe().items()))
        if identity not in seen:
            seen.add(identity)
            out.append((options, dialect))
    return out


def refused(engine, law_name, target="wall"):
    """[(option=value, the engine's reason)] of each single option value its inputs refuse for the law here (e.g. a
    damping mode this build lacks)."""
    out = []
    for key, option in engine.OPTIONS.items():
        for value in option.values[1:]:
            try:
                engine.dialect(law_name, {key: value}, target)
            except UserError as exc:
                out.append((f"{key}={value}", str(exc)))
    return out


def rows_at(dialect, scene, inputs, steps, label):
    """The dialect's rows over the scene with each target's input e in place of the target (labelled as the
    target, engine and dialect `label`), for the targets an input reaches."""
    frames = [simulate(dialect, replace(scene, e_n=(i.value,)), steps_per_contact=steps)[0]
              .assign(e_n_target=i.target, engine=label, dialect=label) for i in inputs if i.value is not None]
    return pd.concat(frames, ignore_index=True) if frames else None


def as_given(dialect, scene, steps, label):
    """The dialect's rows with the target e_n given to the engine as it is (no calibration)."""
    return simulate(dialect, scene, steps_per_contact=steps)[0].assign(engine=label, dialect=label)


def evaluate(options, dialect, scene, steps, label):
    """The alternative with its restitution inputs (one per target) and its rows at them."""
    inputs = [restitution_input(dialect, scene, target, steps) for target in scene.e_n]
    return Alternative(options, dialect, inputs, rows_at(dialect, scene, inputs, steps, label))
