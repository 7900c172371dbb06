"""A calibration of one engine for one law on one scene: its alternatives on the reference (each option choice with
its restitution inputs and its price on the physics checks), the one a stated rule chooses, what to type into the
engine for it, the engine run with it (and at the advised time step) to confirm, what no input can fix and why
(attribution), and how the calibrated input moves with e_n, speed and radius."""
from dataclasses import dataclass, field, replace

import numpy as np
import pandas as pd

from ...analyses.attribution import attribute
from ...analyses.calibration import RULE, choice_table, price, rank, stage_table
from ...analyses.cost import relative_errors
from ...analyses.physics import IMPACT, Tolerances, engine_physics
from ...runs.execute import execute
from ...runs.plan import engine_runs
from ...solver.simulate import simulate
from .alternatives import alternatives, as_given, evaluate, refused, rows_at, takes_ratio, with_ratio
from .restitution import SEARCHED, reach, refuse_unreachable, restitution_input
from .timestep import FINE, advise
from .typed import typed

GIVEN, CALIBRATED, RUN = "formulas, e as given", "formulas, calibrated", "engine, calibrated"
YOURS = "your input"                   # the stage before calibration when the user gave their own (--engine-input)
SPEEDS, RADII = (0.5, 1.0, 2.0), (0.5, 1.0, 2.0)       # the scene's speed and radius times these: the variation


@dataclass(repr=False)
class Calibration:
    """Everything `harness calibrate` reports, data first (views draw it); its repr is a few lines."""
    engine: str
    law: object
    scene: object
    steps: int
    tolerances: Tolerances
    timestep_tolerance: float
    frame: pd.DataFrame                 # paper law, the stages of the chosen alternative, the engine run
    choices: list                       # per option choice: options, targets reached, price, chosen (RULE)
    chosen: object                      # the Alternative chosen
    inputs: pd.DataFrame                # per target e_n: the input e, the e_n it gives, or why none does
    typed: list                         # per target e_n reached: what to type (typed.Typed)
    stages: pd.DataFrame                # per stage and quantity: worst and RMS deviation from the paper law
    physics: dict                       # stage -> physics verdict
    attribution: pd.DataFrame           # what remains: the calibrated formulas against the paper law
    agreement: float | None             # the engine run against its calibrated formulas (max |diff| / V)
    advice: object                      # calibration.timestep.Advice
    confirmed: dict | None              # the engine at the advised step against the formulas at a vanishing step
    variation: pd.DataFrame             # the input e against e_n, speed and radius
    refused: list = field(default_factory=list)      # (option=value, why this build refuses it)
    failures: list = field(default_factory=list)
    skipped: str = ""                   # why the engine did not run, when it did not
    version: str = ""                   # of the engine build calibrated
    rule: str = RULE                    # how the choice was made from the choices' prices
    yours: dict | None = None           # the user's own input (--engine-input): text, composition, flags

    @property
    def alternatives(self):
        """The choices as a table (alternatives.csv)."""
        return choice_table(self.choices)

    def __repr__(self):
        states = ", ".join(f"{stage}: {p['state']}" for stage, p in self.physics.items())
        return (f"<Calibration of {self.law.name} for {self.engine}: advised steps per contact {self.advice.steps}"
                f"\n chosen {self.chosen.label}\n {states}" + (f"\n skipped: {self.skipped}" if self.skipped else "")
                + "\n .inputs .stages .physics .advice .confirmed .variation>")


def calibrate(engine, law, scene, steps=1000, tolerances=None, timestep_tolerance=1e-2, run_engine=True, fixed=None,
              yours=None):
    """Calibrate `engine` (an Engine) for `law` on `scene` (angles or tangential speeds; one e_n per target), each
    choice of its options with the options `fixed` (a --with's); targets no choice reaches are refused first. With
    `yours` (the user's own input: text, composition, flags and its `dialect`), the stage before calibration is that
    input as written, at every target, in place of the engine's formulas with e as given."""
    tolerances = Tolerances.of(tolerances)
    target = "sphere" if scene.spheres else "wall"
    searched = engine.restitution_inputs(law.name)
    choices = alternatives(engine, law.name, target, fixed)
    ends = [reach(dialect, scene, steps, searched) for _, dialect in choices]
    status = engine.status(law.name, choices[0][0])
    version = engine.version() if status.available else ""
    refuse_unreachable(scene.e_n, ends, searched, f"{engine.code} {version}".strip(), law.name, scene, steps)
    paper = simulate(law, scene, steps_per_contact=steps)[0]
    before = YOURS if yours else GIVEN
    given = as_given(yours["dialect"] if yours else choices[0][1], scene, steps, before)
    table, chosen = choose(engine, law, scene, steps, tolerances, paper, choices, ends, searched)
    frame = pd.concat([paper, given, chosen.rows], ignore_index=True)
    remaining, remaining_rows = attribute(law, chosen.dialect, scene,
                                          lambda law_, s: simulate(law_, s, steps_per_contact=steps)[0], tolerances)
    advice = advise(chosen.dialect, scene, chosen.inputs, timestep_tolerance)
    to_type = typed(engine, law, scene, steps, chosen.options, [(i.target, i.value) for i in chosen.reachable])
    failures, agreement, confirmed, skipped = [], None, None, ""
    status = engine.status(law.name, chosen.options)
    if run_engine and status.available:
        ran, failures = run_at_inputs(engine, law, scene, chosen, steps)
        if not ran.empty:
            frame = pd.concat([frame, ran], ignore_index=True)
            agreement = max_difference(ran[ran.status == "ok"], chosen.rows)
        if advice.steps is not None:
            confirmed = confirm(engine, law, scene, chosen, advice, failures)
    elif run_engine:
        skipped = status.reason
    stages = [before, CALIBRATED] + ([RUN] if (frame.engine == RUN).any() else [])
    physics = {s: engine_physics(frame, s, tolerances, None if s == before else remaining, scene.gravity,
                                 None if s == before else remaining_rows) for s in stages}
    return Calibration(engine.NAME, law, scene, steps, tolerances, timestep_tolerance, frame, table, chosen,
                       inputs_table(chosen), to_type, stage_table(frame, stages, scene.gravity), physics, remaining,
                       agreement, advice, confirmed, variation(chosen.dialect, scene, steps, searched),
                       refused(engine, law.name, target), failures, skipped, version,
                       yours={k: v for k, v in yours.items() if k != "dialect"} if yours else None)


def choose(engine, law, scene, steps, tolerances, paper, choices, ends, searched):
    """Every choice of options with its restitution inputs (and, where its inputs take one, the tangential damping
    ratio tuned), priced on the physics checks against the paper law's rows: (their records, the one RULE puts
    first)."""
    tried, prices = [], []
    for (options, dialect), end in zip(choices, ends):
        evaluated = evaluate(options, dialect, scene, steps, CALIBRATED, paper, searched, end)
        if evaluated.rows is None:
            continue
        tuned = ([with_ratio(evaluated, engine, law.name, scene, steps, CALIBRATED)]
                 if takes_ratio(engine, law.name, options) else [])
        for alternative in [evaluated] + tuned:
            tried.append(alternative)
            prices.append(price(pd.concat([paper, alternative.rows], ignore_index=True), CALIBRATED, tolerances,
                                scene.gravity))
    best = min(range(len(tried)), key=lambda i: (rank(len(tried[i].reachable), prices[i]), i))
    return [{"options": a.label, "option values": a.options, "targets reached": len(a.reachable), "price": p,
             "chosen": i == best} for i, (a, p) in enumerate(zip(tried, prices))], tried[best]


def inputs_table(alternative):
    return pd.DataFrame([{"e_n_target": i.target, "input_e": i.value, "normal_e_n": i.achieved,
                          "note": i.reason} for i in alternative.inputs])


def run_at_inputs(engine, law, scene, alternative, steps, observe=False, label=RUN):
    """The engine's rows with the chosen options at each target's input e, labelled as the target (engine and
    dialect `label`), and its failed runs."""
    runs = [run for i in alternative.reachable
            for run in engine_runs(engine, law, replace(scene, e_n=(i.value,)), steps, alternative.options, observe)]
    frame, failures = execute(runs)
    if frame.empty:
        return frame, failures
    targets = {i.value: i.target for i in alternative.reachable}
    frame = frame.assign(e_n_target=frame.e_n_target.map(lambda e: targets.get(e, e)), engine=label, dialect=label)
    return frame, failures


def max_difference(engine_rows, formula_rows):
    """max over v_n1, v_t1, R omega1 of |engine - its formulas| / V at the same impacts and inputs (None if none)."""
    pairs = engine_rows.merge(formula_rows, on=IMPACT, suffixes=("", "_f"))
    if pairs.empty:
        return None
    speed = np.hypot(pairs.v_n0, pairs.v_t0)
    diffs = [(pairs[m] - pairs[m + "_f"]).abs() * (pairs.radius if m == "omega1" else 1.0) / speed
             for m in ("v_n1", "v_t1", "omega1")]
    return float(np.nanmax(np.vstack(diffs)))


def confirm(engine, law, scene, alternative, advice, failures):
    """The engine at the advised steps per contact (observed: contact time and peak force) against its formulas
    at a vanishing step: the errors, and whether each meets the tolerance."""
    ran, failed = run_at_inputs(engine, law, scene, alternative, advice.steps, observe=True)
    failures += failed
    if ran.empty:
        return None
    truth = rows_at(alternative.dialect, scene, alternative.inputs, FINE, RUN)
    ran = ran.sort_values(["e_n_target", "theta_deg"]).reset_index(drop=True)
    truth = truth.sort_values(["e_n_target", "theta_deg"]).reset_index(drop=True)
    errors = relative_errors(ran, truth)
    return {"steps_per_contact": advice.steps, **errors, "meets": bool(errors["err_max"] <= advice.tolerance)}


def variation(dialect, scene, steps, searched=SEARCHED):
    """The input e for each target e_n at the scene's speed and radius times 0.5, 1 and 2 (the formulas alone)."""
    rows = []
    for speed in SPEEDS:
        for radius in RADII:
            varied = replace(scene, speed=scene.speed * speed, radius=scene.radius * radius)
            for target in scene.e_n:
                needed = restitution_input(dialect, varied, target, steps, searched)
                rows.append({"speed_m_s": varied.speed, "radius_m": varied.radius, "e_n_target": target,
                             "input_e": needed.value, "note": needed.reason})
    return pd.DataFrame(rows)
