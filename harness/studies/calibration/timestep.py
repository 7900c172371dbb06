"""Time-step advice: the coarsest steps per contact at which an engine's formulas, with its calibrated inputs, stay
within a tolerance of their own result at a vanishing step on e_n, e_t, Omega*, contact time and peak force
(relative to the sweep's scale, as `harness cost` measures), beside the common 20%-of-Rayleigh-time rule."""
from dataclasses import dataclass

import numpy as np
import pandas as pd

from ...analyses.cost import RAYLEIGH_FRACTION, rayleigh_time, relative_errors
from ...solver.resolution import FixedTimeStep
from ...solver.stability import UnstableTimeStep
from .alternatives import rows_at

LADDER = (5, 7, 10, 14, 20, 28, 40, 56, 80, 113, 160, 226, 320, 453, 640, 905, 1280, 1810, 2560, 3620, 5120)
FINE = 40960            # steps per contact of the formulas' own answer at a vanishing step


@dataclass
class Advice:
    """The ladder's errors, the advised steps per contact (None when no rung meets the tolerance) with its time step,
    and the 20%-of-Rayleigh-time rule's time step with its errors."""
    ladder: pd.DataFrame
    tolerance: float
    steps: int | None
    dt: float | None
    rayleigh_s: float
    rule_dt: float
    rule_errors: dict

    @property
    def fraction_of_rayleigh(self):
        return None if self.dt is None else self.dt / self.rayleigh_s


def advise(dialect, scene, inputs, tolerance, label="formulas"):
    """Errors at every rung against FINE, the coarsest rung from which on every finer one meets `tolerance` on every
    metric, and the 20%-of-Rayleigh rule's errors on the same inputs."""
    truth = rows_at(dialect, scene, inputs, FINE, label)
    rows = []
    for steps in LADDER:
        try:
            frame = rows_at(dialect, scene, inputs, steps, label)
        except UnstableTimeStep:                 # above the scheme's stability limit: no answer at all
            rows.append({"steps_per_contact": steps, "dt_min": np.nan, "dt_max": np.nan, "err_max": np.inf,
                         "note": "above the stability limit"})
            continue
        rows.append({"steps_per_contact": steps, "dt_min": float(frame.dt.min()), "dt_max": float(frame.dt.max()),
                     **relative_errors(frame, truth), "note": ""})
    ladder = pd.DataFrame(rows)
    meets = (ladder.err_max <= tolerance).to_numpy()
    advised = next((i for i in range(len(meets)) if meets[i:].all()), None)
    rayleigh = rayleigh_time(scene)
    try:
        rule_errors = relative_errors(rows_at(dialect, scene, inputs, FixedTimeStep(RAYLEIGH_FRACTION * rayleigh),
                                              label), truth)
    except UnstableTimeStep:
        rule_errors = {"err_max": np.inf, "note": "above the stability limit"}
    return Advice(ladder, tolerance, None if advised is None else int(ladder.steps_per_contact[advised]),
                  None if advised is None else float(ladder.dt_min[advised]), rayleigh,
                  RAYLEIGH_FRACTION * rayleigh, rule_errors)
