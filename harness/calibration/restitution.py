"""The restitution input: the e an engine must be given so that its normal impact at the scene speed rebounds at the
target e_n, found by root finding on its dialect in the reference (scipy's brentq), or why no input reaches it."""
from dataclasses import dataclass, replace

from scipy.optimize import brentq

from ..solver.simulate import simulate

LOWEST, HIGHEST = 0.01, 1.0         # the inputs an engine takes: 0 < e <= 1
XTOL = 1e-7                         # of the input; the e_n it gives is then within ~1e-7 of the target


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


def restitution_input(dialect, scene, target, steps):
    """The input e in [0.01, 1] whose normal impact gives `target`; where the inputs' e_n range misses it, None and
    the range they reach."""
    low, high = normal_e(dialect, scene, LOWEST, steps), normal_e(dialect, scene, HIGHEST, steps)
    if abs(low - target) < 1e-12:
        return Input(target, LOWEST, low)
    if not min(low, high) <= target <= max(low, high):
        return Input(target, None, None, f"its inputs 0.01 to 1 give e_n {min(low, high):.4g} to {max(low, high):.4g}")
    value = brentq(lambda e: normal_e(dialect, scene, e, steps) - target, LOWEST, HIGHEST, xtol=XTOL)
    return Input(target, value, normal_e(dialect, scene, value, steps))
