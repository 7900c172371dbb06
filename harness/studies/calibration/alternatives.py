"""An engine's alternative inputs for a law: every combination of the values of its declared options that its
inputs accept for the law (with the options a --with fixes in each), one per distinct dialect (precision-only options
give none), each given the restitution input that meets every target e_n, and its rows on the reference (its formulas
in place of the engine)."""
import itertools
from dataclasses import dataclass, replace

import pandas as pd
from scipy.optimize import minimize_scalar

from ...analyses.physics import IMPACT
from ...infra.errors import UserError
from ...solver.simulate import simulate
from .restitution import SEARCHED, restitution_input


@dataclass
class Alternative:
    """One choice of engine options, the restitution input per target e_n, and its formulas' rows on the scene."""
    options: dict
    dialect: object
    inputs: list
    rows: pd.DataFrame | None = None
    paper: pd.DataFrame | None = None     # the paper law's rows it is measured against

    @property
    def label(self):
        """Its options as a user reads them: KEY=VALUE, the tangential damping ratio a --with sets named as such."""
        return ", ".join(f"tangential damping ratio {float(v):.4g}" if k == TANGENTIAL_DAMPING and v != "none" else
                         f"{k}={v}" for k, v in self.options.items()) or "default options"

    @property
    def reachable(self):
        return [i for i in self.inputs if i.value is not None]


def alternatives(engine, law_name, target="wall", fixed=None):
    """[(options, dialect)] of every combination of the engine's option values that composes for the law, each with
    the options `fixed` (those a --with maps to, Engine.with_options), one per distinct dialect, its default options
    first."""
    fixed = dict(fixed or {})
    keys = [k for k in engine.OPTIONS if k not in fixed]
    out, seen = [], set()
    for values in itertools.product(*(engine.OPTIONS[k].values for k in keys)):
        options = {k: v for k, v, o in zip(keys, values, (engine.OPTIONS[k] for k in keys)) if v != o.values[0]}
        options.update(fixed)
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


TANGENTIAL_DAMPING = "with:tangential-damping"    # the option that sets a tangential damping ratio g_t (WITH)
RATIO_RANGE = (0.0, 1.5)


def takes_ratio(engine, law_name, options, target="wall"):
    """Whether the engine's inputs follow a tangential damping ratio g_t of their own (an engine whose WITH maps the
    tangential dashpot to the option `with:tangential-damping`, and whose law then carries it) that `options` (a
    --with) do not set already."""
    if TANGENTIAL_DAMPING in options or not any(TANGENTIAL_DAMPING in mapped for mapped in engine.WITH.values()):
        return False
    try:
        dialect = engine.dialect(law_name, {**options, TANGENTIAL_DAMPING: "0.3"}, target)
    except UserError:
        return False
    return dialect.describe()["tangential-damping"] == "0.3"


def with_ratio(alternative, engine, law_name, scene, steps, label, target="wall"):
    """The alternative with the tangential damping ratio g_t in RATIO_RANGE (its inputs e unchanged: a normal
    impact has no tangential dashpot) that minimises the worst velocity deviation from the paper law over the
    sweep (scipy's bounded minimize_scalar), measured against `paper` rows in alternative.rows' frame."""
    paper = alternative.paper

    def worst(ratio):
        options = {**alternative.options, TANGENTIAL_DAMPING: f"{ratio:.6f}"}
        rows = rows_at(engine.dialect(law_name, options, target), scene, alternative.inputs, steps, label)
        return worst_velocity(paper, rows)
    best = minimize_scalar(worst, bounds=RATIO_RANGE, method="bounded", options={"xatol": 1e-4})
    options = {**alternative.options, TANGENTIAL_DAMPING: f"{best.x:.6f}"}
    dialect = engine.dialect(law_name, options, target)
    return Alternative(options, dialect, alternative.inputs, rows_at(dialect, scene, alternative.inputs, steps, label),
                       paper)


def worst_velocity(paper, rows):
    """max over impacts and v_n1, v_t1, R omega1 of |rows - paper| / V at the same impacts."""
    pairs = rows.merge(paper, on=IMPACT, suffixes=("", "_paper"))
    speed = (pairs.v_n0 ** 2 + pairs.v_t0 ** 2) ** 0.5
    return float(max(((pairs[m] - pairs[m + "_paper"]).abs() * (pairs.radius if m == "omega1" else 1.0) / speed)
                     .max() for m in ("v_n1", "v_t1", "omega1")))


def rows_at(dialect, scene, inputs, steps, label):
    """The dialect's rows over the scene with each target's input e in place of the target (labelled as the
    target, engine and dialect `label`), for the targets an input reaches."""
    frames = [simulate(dialect, replace(scene, e_n=(i.value,)), steps_per_contact=steps)[0]
              .assign(e_n_target=i.target, engine=label, dialect=label) for i in inputs if i.value is not None]
    return pd.concat(frames, ignore_index=True) if frames else None


def as_given(dialect, scene, steps, label):
    """The dialect's rows with the target e_n given to the engine as it is (no calibration)."""
    return simulate(dialect, scene, steps_per_contact=steps)[0].assign(engine=label, dialect=label)


def evaluate(options, dialect, scene, steps, label, paper=None, searched=SEARCHED, ends=None):
    """The alternative with its restitution inputs (one per target, searched over `searched`; `ends`: the e_n its
    ends give, when known) and its rows at them."""
    inputs = [restitution_input(dialect, scene, target, steps, searched, ends) for target in scene.e_n]
    return Alternative(options, dialect, inputs, rows_at(dialect, scene, inputs, steps, label), paper)
