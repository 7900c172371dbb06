"""What a calibration changed: per stage (the engine's formulas with e as given, with the calibrated inputs, the
engine itself with them) and quantity, the worst and RMS deviation from the paper law over the sweep (v_n1, v_t1
and R omega1 as fractions of V, e_n absolute, the Coulomb ratio |J_t|/(mu J_n) above 1), and the physics checks."""
import numpy as np
import pandas as pd

from .invariants import coulomb_ratio
from .physics import engine_physics, paired

QUANTITIES = ("v_n1", "v_t1", "omega1", "e_n", "coulomb excess")


def deviations(pairs, gravity=0.0):
    """{quantity: per-impact deviation from the paper law} of paired rows."""
    speed = np.hypot(pairs.v_n0, pairs.v_t0).to_numpy(dtype=float)
    out = {m: (pairs[m] - pairs[m + "_paper"]).to_numpy(dtype=float) * (pairs.radius.to_numpy(dtype=float)
                                                                         if m == "omega1" else 1.0) / speed
           for m in ("v_n1", "v_t1", "omega1")}
    out["e_n"] = (pairs.e_n - pairs.e_n_paper).to_numpy(dtype=float)
    out["coulomb excess"] = np.fmax(coulomb_ratio(pairs, gravity) - 1.0, 0.0)
    return out


def stage_table(frame, stages, gravity=0.0):
    """One row per (stage, quantity): worst |deviation|, where, and the RMS over the impacts; `stages` are the
    engine labels of the frame's rows to compare with its paper law rows."""
    rows = []
    for stage in stages:
        pairs = paired(frame, stage)
        if pairs.empty:
            continue
        for quantity, values in deviations(pairs, gravity).items():
            finite = np.isfinite(values)
            if not finite.any():
                continue
            worst = int(np.nanargmax(np.abs(values)))
            rows.append({"stage": stage, "quantity": quantity, "worst": float(abs(values[worst])),
                         "rms": float(np.sqrt(np.mean(values[finite] ** 2))),
                         "e_n_target": float(pairs.e_n_target.iloc[worst]),
                         "theta_deg": float(pairs.theta_deg.iloc[worst]), "impacts": int(finite.sum())})
    return pd.DataFrame(rows)


def stage_physics(frame, stage, tolerances, attribution=None, gravity=0.0):
    """The physics verdict of one stage's rows against the paper law (analyses.physics)."""
    return engine_physics(frame, stage, tolerances, attribution, gravity)


def score(frame, stage, tolerances, gravity=0.0):
    """How far a stage is from the paper law, for choosing among alternatives: (failed checks, the worst case of
    any check over its tolerance, the worst velocity deviation over its tolerance)."""
    physics = engine_physics(frame, stage, tolerances, None, gravity)
    worst = {c["check"]: c.get("worst", 0.0) / max(c["tolerance"], 1e-300) for c in physics["checks"]}
    return len(physics["failing"]), max(worst.values(), default=0.0), worst.get("velocity", 0.0)
