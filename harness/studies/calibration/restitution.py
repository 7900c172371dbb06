"""The restitution input: the e an engine must be given so that its normal impact at the scene speed rebounds at the
target e_n, found by root finding on its dialect in the reference (scipy's brentq) over the e its inputs take; the
e_n those inputs reach, and the one-line refusal of targets no choice of inputs reaches."""
from dataclasses import dataclass, replace

from scipy.optimize import brentq

from ...engines.protocol import InputRange
from ...infra.errors import UserError
from ...solver.simulate import simulate

SEARCHED = InputRange(0.01)         # the e searched where an engine declares no range of its own
XTOL = 1e-7                         # of the input; the e_n it gives is then within ~1e-7 of the target
AT_END = 1e-6                       # a target this close to the e_n an end of the inputs gives is that end's


@dataclass(frozen=True)
class Input:
    """The e an engine is given for one target e_n: None where no input reaches the target, with the reason."""
    target: float
    value: float | None
    achieved: float | None          # the dialect's normal e_n at that input
    reason: str = ""


def normal_e(dialect, scene, e_in, steps):
    """e_n of the dialect's normal impact at the scene speed (no spin, no gravity) when given e_in."""
    probe = replace(scene, e_n=(float(e_in),), angles_deg=(0.0,), psi1_star=None, v_t=None, omega0=0.0, gravity=0.0,
                    spheres=None)
    return float(simulate(dialect, probe, steps_per_contact=steps)[0].e_n.iloc[0])


def reach(dialect, scene, steps, inputs=SEARCHED):
    """(e_n at the lowest input, e_n at the highest) of the dialect's normal impact at the scene speed."""
    return normal_e(dialect, scene, inputs.lowest, steps), normal_e(dialect, scene, inputs.high, steps)


def reaches(ends, target):
    """Whether e_n `target` lies between the e_n the two ends of the inputs give (within AT_END of either)."""
    low, high = min(ends), max(ends)
    return low - AT_END <= target <= high + AT_END


def restitution_input(dialect, scene, target, steps, inputs=SEARCHED, ends=None):
    """The input e in `inputs` whose normal impact gives `target` (`ends`: reach(), when known); where the e_n the
    inputs reach misses it, None and that range."""
    low, high = ends or reach(dialect, scene, steps, inputs)
    for value, achieved in ((inputs.lowest, low), (inputs.high, high)):
        if abs(achieved - target) <= AT_END:
            return Input(target, value, achieved)
    if not reaches((low, high), target):
        return Input(target, None, None, f"its inputs e in {inputs} give e_n {min(low, high):.6g} to "
                                         f"{max(low, high):.6g}")
    value = brentq(lambda e: normal_e(dialect, scene, e, steps) - target, inputs.lowest, inputs.high, xtol=XTOL)
    return Input(target, value, normal_e(dialect, scene, value, steps))


def spans(ends):
    """The e_n ranges [(low, high)] the choices' `ends` cover, overlapping ones merged, lowest first."""
    merged = []
    for low, high in sorted((min(e), max(e)) for e in ends):
        if merged and low <= merged[-1][1] + AT_END:
            merged[-1] = (merged[-1][0], max(merged[-1][1], high))
        else:
            merged.append((low, high))
    return merged


def refuse_unreachable(targets, ends, inputs, engine, law_name, scene, steps):
    """One line, before any work, for the targets no choice of the engine's inputs reaches (each choice's `ends`):
    the same words for every engine."""
    missed = [t for t in targets if not any(reaches(e, t) for e in ends)]
    if not missed:
        return
    covered = " and ".join(f"{low:.6g} to {high:.6g}" for low, high in spans(ends))
    raise UserError(f"{engine} cannot be calibrated to e_n {', '.join(f'{t:g}' for t in missed)} for {law_name}: "
                    f"its inputs e in {inputs} give e_n {covered} on this scene (its normal impact at "
                    f"{scene.speed:g} m/s, {steps:g} steps per contact); ask for targets in that range")
