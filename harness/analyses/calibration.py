"""What a calibration changed: per stage (the engine's formulas with e as given, with the calibrated inputs, the
engine itself with them) and quantity, the worst and RMS deviation from the paper law over the sweep (v_n1, v_t1
and R omega1 as fractions of V, e_n absolute, the Coulomb ratio |J_t|/(mu J_n) above 1); each choice's price on the
physics checks and the rule that chooses on it."""
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


RULE = ("the most targets reached, then the fewest physics checks failed, then the fewest impacts beyond a check's "
        "tolerance (counted once per check), then the smallest worst case of any check over its tolerance")
CHECKS = ("velocity", "e_n", "coulomb", "energy")


def price(frame, stage, tolerances, gravity=0.0):
    """What a stage's rows do to each physics check against the paper law (analyses.physics): [{check, passed,
    failing (impacts beyond its tolerance), impacts, worst, tolerance, short (its worst case in a phrase)}]."""
    physics = engine_physics(frame, stage, tolerances, None, gravity)
    return [{"check": c["check"], "passed": c["passed"], "failing": c["failing"], "impacts": c["impacts"],
             "worst": c.get("worst"), "tolerance": c["tolerance"], "short": c.get("short", "")}
            for c in physics["checks"]]


def rank(reached, checks):
    """The key RULE orders choices by (the smallest first), from their targets reached and price."""
    failed = [c for c in checks if not c["passed"]]
    worst = max((c["worst"] / max(c["tolerance"], 1e-300) for c in checks if c["worst"] is not None), default=0.0)
    return -reached, len(failed), sum(c["failing"] for c in checks), worst


def choice_table(choices):
    """One row per choice: its options, targets reached, the rule's counts and, per check, the impacts beyond its
    tolerance and its worst case."""
    rows = []
    for choice in choices:
        checks = {c["check"]: c for c in choice["price"]}
        _, failed, beyond, worst = rank(choice["targets reached"], choice["price"])
        row = {"options": choice["options"], "targets reached": choice["targets reached"], "failed checks": failed,
               "impacts beyond": beyond, "worst check / tolerance": worst}
        for name in CHECKS:
            check = checks.get(name, {})
            row[f"{name}: impacts beyond"] = check.get("failing")
            row[f"{name}: worst"] = check.get("worst")
        rows.append({**row, "price": "; ".join(f"{c['check']}: {c['short']}" for c in choice["price"]
                                                if not c["passed"]) or "every check holds",
                     "chosen": choice["chosen"]})
    return pd.DataFrame(rows)
