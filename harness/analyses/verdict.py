"""The verdicts of a comparison as data: per engine whether it reproduces the paper law on this scene (physics) and
whether it agrees with its own formulas (agreement), its worst cases, its largest deviations from the paper law in
physical units, and what was skipped, failed or found. The terminal, `--json` and the report's summary box all read
this one record."""
import numpy as np

from .agreement import AGREEMENT_TOLERANCE, KEYS

PHYSICAL = (("v_n1", "m/s", "V"), ("v_t1", "m/s", "V"), ("omega1", "rad/s", "V/R"))   # metric, unit, scale
AGREE, DISAGREE, NOT_COMPARED = "agree", "disagree", "not compared"


def physical_deviations(frame, engine):
    """Per rebound quantity: the largest |engine - paper law| over the impacts, in its unit and relative to the
    incident speed (R omega1/V for the spin), with the impact where it is."""
    ours = frame[(frame.engine == engine) & (frame.dialect == engine) & (frame.status == "ok")]
    paper = frame[(frame.engine == "reference") & (frame.dialect == "paper") & (frame.status == "ok")]
    pairs = ours.merge(paper, on=KEYS, suffixes=("", "_paper"))
    out = []
    if pairs.empty:
        return out
    speed = np.hypot(pairs.v_n0, pairs.v_t0).to_numpy()
    for metric, unit, scale in PHYSICAL:
        diff = (pairs[metric] - pairs[metric + "_paper"]).to_numpy()
        relative = diff / speed * (pairs.radius.to_numpy() if metric == "omega1" else 1.0)
        if np.all(np.isnan(relative)):
            continue
        worst = int(np.nanargmax(np.abs(relative)))
        out.append({"metric": metric, "difference": float(diff[worst]), "unit": unit,
                    "relative": float(relative[worst]), "relative_to": scale,
                    "paper": float(pairs[metric + "_paper"].iloc[worst]), "engine": float(pairs[metric].iloc[worst]),
                    "e_n_target": float(pairs.e_n_target.iloc[worst]), "theta_deg": float(pairs.theta_deg.iloc[worst])})
    return out


def engine_record(comparison, engine):
    frame = comparison.results
    rows = comparison.agreement[comparison.agreement.engine == engine]
    worst = rows.loc[rows.max_rel_diff.fillna(np.inf).idxmax()] if not rows.empty else None
    version = frame[frame.engine == engine].engine_version.astype(str).iloc[0]
    compared = bool(len(rows)) and bool(rows.max_rel_diff.notna().all())
    return {"engine": engine, "version": version, "compared": compared,
            "agrees": compared and bool(rows["pass"].all()),
            "tolerance": AGREEMENT_TOLERANCE,
            "worst": None if worst is None else {"metric": worst.metric, "relative": float(worst.max_rel_diff),
                                                  "e_n_target": float(worst.e_n_target),
                                                  "theta_deg": float(worst.theta_deg)},
            "deviation": physical_deviations(frame, engine),
            "physics": comparison.physics[engine]}


def verdict(comparison):
    """The record: model, physics (reproduces, deviates, not checked) and its tolerances, verdict (the agreement:
    agree, disagree, not compared), engines, skipped, failed, unavailable, findings."""
    engines = [engine_record(comparison, e) for e in comparison.engines]
    compared = [e for e in engines if e["compared"]]
    outcome = DISAGREE if any(not e["agrees"] for e in compared) else AGREE if compared else NOT_COMPARED
    frame = comparison.results
    return {"model": comparison.law.name, "physics": comparison.reproduces,
            "tolerances": comparison.tolerances.as_dict(), "verdict": outcome,
            "impacts": int(((frame.engine == "reference") & (frame.dialect == "paper")).sum()),
            "e_n": [float(e) for e in comparison.scene.e_n], "engines": engines,
            "skipped": [{"engine": name, "reason": reason} for name, reason in comparison.skipped],
            "failed": [{"engine": f.engine, "e_n": float(f.e_n), "message": f.message} for f in comparison.failures],
            "unavailable": comparison.unavailable,
            "findings": comparison.findings.to_dict("records")}
