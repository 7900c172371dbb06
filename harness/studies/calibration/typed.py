"""What a user types into the engine for a calibration: per target e_n, the engine's whole input at the calibrated
values (as harness runs it), the lines of it that set the contact law (to paste into an input of their own) and the
named values those lines set (every coefficient, the tangential damping among them where the choice sets one)."""
from dataclasses import dataclass, replace

from ...runs.plan import engine_runs


@dataclass(frozen=True)
class Typed:
    """One target's input: its file name and text, its contact lines and the [(name, value)] they set."""
    target: float
    file: str
    text: str
    lines: list
    values: list


def file_name(engine, law_name, target):
    """The name of the engine's input calibrated for `target`."""
    return f"{engine.code}-{law_name}-en{target:g}-calibrated{engine.INPUT_SUFFIX}"


def typed(engine, law, scene, steps, options, inputs):
    """[Typed] of each (target, input e) in `inputs`: the engine's input rendered with `options` at that e."""
    out = []
    for target, value in inputs:
        (run,) = engine_runs(engine, law, replace(scene, e_n=(value,)), steps, options)
        _, text = engine.render(run)
        lines = engine.contact_lines(text)
        out.append(Typed(target, file_name(engine, law.name, target), text, lines, engine.typed_inputs(lines)))
    return out
