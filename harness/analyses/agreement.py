"""Agreement (an engine against its dialect at equal dt) and deviation (against the paper law, or another engine),
from the results table."""
import numpy as np
import pandas as pd

AGREEMENT_TOLERANCE = 1e-6          # relative, at equal dt (the dialects were matched to the binaries to ~1e-15)
AGREEMENT_METRICS = ("v_n1", "v_t1", "omega1")
DEVIATION_METRICS = ("e_n", "e_t", "beta", "omega_star", "psi2_star", "theta_r_com_deg", "ke_ratio")
KEYS = ["e_n_target", "theta_deg"]


def _pair(frame, left, right):
    """Rows of `left` and `right` (dicts of column filters) matched impact by impact."""
    a = frame.loc[np.logical_and.reduce([frame[k] == v for k, v in left.items()])]
    b = frame.loc[np.logical_and.reduce([frame[k] == v for k, v in right.items()])]
    return a.merge(b, on=KEYS, suffixes=("", "_ref"))


def relative_difference(value, reference, scale):
    """|a - b| / max(|b|, 1e-9 scale): relative, with a floor so that exact zeros (no spin) compare sensibly."""
    return np.abs(value - reference) / np.maximum(np.abs(reference), 1e-9 * scale)


UNDEFINED = "non-finite"        # the status of a row whose rebound is not a number (an engine's or its dialect's)


def agreement(frame, engine):
    """Per metric: max relative difference engine vs reference dialect at equal dt, where, and pass/fail. An impact
    not a number in both (status non-finite) agrees: the dialect predicts what the engine computes; not a number in
    one of them alone is an infinite difference. `nan_in_both` counts the impacts not a number in both."""
    pairs = _pair(frame, {"engine": engine, "dialect": engine}, {"engine": "reference", "dialect": engine})
    pairs = pairs[pairs.status.isin(("ok", UNDEFINED))]
    both = ((pairs.status == UNDEFINED) & (pairs.status_ref == UNDEFINED)).to_numpy()
    one = ((pairs.status == UNDEFINED) != (pairs.status_ref == UNDEFINED)).to_numpy()
    rows = []
    for metric in AGREEMENT_METRICS:
        if pairs.empty:
            rows.append({"engine": engine, "metric": metric, "max_rel_diff": np.nan, "e_n_target": np.nan,
                         "theta_deg": np.nan, "tolerance": AGREEMENT_TOLERANCE, "pass": False, "nan_in_both": 0})
            continue
        scale = pairs.v_n0.abs().max() + pairs.v_t0.abs().max()
        if metric == "omega1":
            scale = scale / pairs.radius.iloc[0]
        diff = relative_difference(pairs[metric].to_numpy(), pairs[metric + "_ref"].to_numpy(), scale)
        diff = np.where(both, 0.0, np.where(one | np.isnan(diff), np.inf, diff))
        worst = int(np.argmax(diff))
        rows.append({"engine": engine, "metric": metric, "max_rel_diff": float(diff[worst]),
                     "e_n_target": float(pairs.e_n_target.iloc[worst]), "theta_deg": float(pairs.theta_deg.iloc[worst]),
                     "tolerance": AGREEMENT_TOLERANCE, "pass": bool(diff[worst] <= AGREEMENT_TOLERANCE),
                     "nan_in_both": int(both.sum())})
    return pd.DataFrame(rows)


def deviation(frame, engine, dialect, against=("reference", "paper")):
    """Per metric and e_n: largest |engine - paper law| (or - another engine) and the impact angle where it is."""
    pairs = _pair(frame, {"engine": engine, "dialect": dialect}, {"engine": against[0], "dialect": against[1]})
    pairs = pairs[pairs.status == "ok"]
    rows = []
    for e_n, group in pairs.groupby("e_n_target", sort=False):
        for metric in DEVIATION_METRICS:
            diff = (group[metric] - group[metric + "_ref"]).to_numpy()
            if np.all(np.isnan(diff)):
                continue
            worst = int(np.nanargmax(np.abs(diff)))
            rows.append({"engine": engine, "dialect": dialect, "e_n_target": e_n, "metric": metric,
                         "max_abs_diff": float(abs(diff[worst])), "signed": float(diff[worst]),
                         "theta_deg": float(group.theta_deg.iloc[worst]),
                         against[0] if against[0] != "reference" else "paper":
                             float(group[metric + "_ref"].iloc[worst]),
                         "engine_value": float(group[metric].iloc[worst])})
    return pd.DataFrame(rows)


def cross_deviations(frame, engines):
    """{(a, b): deviation of engine b against engine a} for every pair of engines that ran, a before b."""
    return {(a, b): deviation(frame, b, b, against=(a, a)) for i, a in enumerate(engines) for b in engines[i + 1:]}
