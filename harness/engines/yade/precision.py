"""YADE checks its own arithmetic: a few impacts run in double and in mpfr150 at the same time step, as two runs of
the plan (the double one shares the comparison's interpreter); analyses.precision compares them."""
from dataclasses import replace

import numpy as np

from .dialect import dialect
from .flavours import available

SAMPLE_ANGLES = (20.0, 60.0)      # deg: a sticking and a sliding impact, neither grazing (whose contact is long)
STEPS_PER_CONTACT = 100           # coarse: mpfr150 costs ~100x double per step, and the gap shows at any dt
HIGH = "mpfr150"


def precision_runs(law, scene, dialect_of=None, given=None):
    """(double run, mpfr150 run) of the impacts of the first e_n nearest SAMPLE_ANGLES at a coarse time step, or ()
    where the high-precision flavour is not installed; with a user's own input `given` (its text), both run it and
    `dialect_of(law name, options, target)` (the engine's) composes it."""
    from ..run import Run         # loads the solver: here, not when the engines are listed
    if not available(HIGH):
        return ()
    angles = np.asarray(scene.impacts(scene.e_n[0])[3])
    picked = sorted({float(angles[int(np.argmin(np.abs(angles - a)))]) for a in SAMPLE_ANGLES})
    held = "normal" if scene.angles_deg is None else scene.speed_is     # Psi1* and V_t sweeps hold V_n
    sample = replace(scene, e_n=scene.e_n[:1], angles_deg=tuple(picked), psi1_star=None, v_t=None, speed_is=held)
    if given is None:
        return tuple(Run("yade", law, dialect(law.name, {"precision": flavour}), sample, STEPS_PER_CONTACT,
                         (("precision", flavour),)) for flavour in ("double", HIGH))
    target = "sphere" if scene.spheres else "wall"
    return tuple(Run("yade", law, dialect_of(law.name, {"precision": flavour, "input": given}, target), sample,
                     STEPS_PER_CONTACT, (("input", given), ("precision", flavour))) for flavour in ("double", HIGH))
