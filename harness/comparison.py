"""Comparisons from the results table: agreement (engine vs its dialect), deviation (vs the paper), findings."""
import numpy as np
import pandas as pd

from .invariants import ENERGY_TOLERANCE, cause, invariant_breaks

AGREEMENT_TOLERANCE = 1e-6          # relative, at equal dt (MODELS 5: engines were matched to ~1e-15)
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


def agreement(frame, engine):
    """Per metric: max relative difference engine vs reference dialect at equal dt, where, and pass/fail."""
    pairs = _pair(frame, {"engine": engine, "dialect": engine}, {"engine": "reference", "dialect": engine})
    pairs = pairs[pairs.status == "ok"]
    rows = []
    for metric in AGREEMENT_METRICS:
        if pairs.empty:
            rows.append({"engine": engine, "metric": metric, "max_rel_diff": np.nan, "e_n_target": np.nan,
                         "theta_deg": np.nan, "tolerance": AGREEMENT_TOLERANCE, "pass": False})
            continue
        scale = pairs.v_n0.abs().max() + pairs.v_t0.abs().max()
        if metric == "omega1":
            scale = scale / pairs.radius.iloc[0]
        diff = relative_difference(pairs[metric].to_numpy(), pairs[metric + "_ref"].to_numpy(), scale)
        worst = int(np.nanargmax(diff))
        rows.append({"engine": engine, "metric": metric, "max_rel_diff": float(diff[worst]),
                     "e_n_target": float(pairs.e_n_target.iloc[worst]), "theta_deg": float(pairs.theta_deg.iloc[worst]),
                     "tolerance": AGREEMENT_TOLERANCE, "pass": bool(diff[worst] <= AGREEMENT_TOLERANCE)})
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
                         against[0] if against[0] != "reference" else "paper": float(group[metric + "_ref"].iloc[worst]),
                         "engine_value": float(group[metric].iloc[worst])})
    return pd.DataFrame(rows)


def tangential_energy_ratio(frame):
    """(m v_t1^2 + I omega1^2)/(m v_t0^2 + I omega0^2): a contact can only take energy out of these motions."""
    mass = 4.0 / 3.0 * np.pi * frame.radius ** 3 * frame.rho
    inertia = 0.4 * mass * frame.radius ** 2
    before = mass * frame.v_t0 ** 2 + inertia * frame.omega0 ** 2
    after = mass * frame.v_t1 ** 2 + inertia * frame.omega1 ** 2
    return (after / before.where(before > 0)).astype(float)


def _because(row, kind):
    known = cause(row.dialect, row.model, kind)
    return f"; known cause: {known}" if known else ""


def findings(frame):
    """Engine behaviour worth a user's attention: kinetic energy gained (in all, or in the tangential and
    rotational motion, which friction can only slow), the other invariant breaks of harness.invariants that a row's
    status does not already say (non-finite values, long contact, normal-impact e_n off its target, a tangential
    force without friction), failed runs."""
    out = []
    frame = frame.reset_index(drop=True)          # invariant breaks point at rows by label
    frame = frame.assign(kt_ratio=tangential_energy_ratio(frame))
    for kind, column, what in (("energy gain", "ke_ratio", "kinetic energy"),
                               ("tangential energy gain", "kt_ratio", "tangential + rotational kinetic energy")):
        gain = frame[(frame[column] > 1.0 + ENERGY_TOLERANCE) & (frame.status == "ok")]
        for (engine, dialect), group in gain.groupby(["engine", "dialect"], sort=False):
            worst = group.loc[group[column].idxmax()]
            out.append({"engine": engine, "dialect": dialect, "kind": kind,
                        "detail": f"{len(group)} impacts end with more {what} than they began with; worst ratio "
                                  f"{worst[column]:.6f} at e_n = {worst.e_n_target:g}, angle {worst.theta_deg:g} deg "
                                  f"(v_t1 = {worst.v_t1:.4f} m/s from v_t0 = {worst.v_t0:.4f})"
                                  + _because(worst, "energy gain")})
    breaks = invariant_breaks(frame)
    breaks = breaks[breaks.kind.isin(("non-finite result", "long contact", "e_n off target", "friction at mu = 0"))
                    & (frame.loc[breaks.row, "status"].to_numpy() == "ok")]
    for (engine, dialect, _, kind), group in breaks.groupby(["engine", "dialect", "model", "kind"], sort=False):
        rows = frame.loc[group.row]
        out.append({"engine": engine, "dialect": dialect, "kind": kind,
                    "detail": _break_detail(kind, group, rows) + _because(rows.iloc[0], kind)})
    failed = frame[frame.status != "ok"]
    for (engine, dialect, status), group in failed.groupby(["engine", "dialect", "status"], sort=False):
        out.append({"engine": engine, "dialect": dialect, "kind": status,
                    "detail": f"{len(group)} impacts: {group.message.iloc[0]}"})
    return pd.DataFrame(out, columns=["engine", "dialect", "kind", "detail"])


def _break_detail(kind, group, rows):
    """One line for a group of invariant breaks of one kind."""
    if kind == "e_n off target":
        miss = (group.value - group.limit).abs() / group.limit
        worst = group.loc[miss.idxmax()]
        return (f"{len(group)} normal impacts end with e_n more than 1% from the target; worst {worst.value:.4g} for "
                f"{worst.limit:g}")
    if kind == "long contact":
        worst = group.loc[(group.value / group.limit).idxmax()]
        return (f"{len(group)} impacts stay in contact longer than the bound; worst {worst.value:.3g} s against "
                f"{worst.limit:.3g} s at e_n = {worst.e_n_target:g}, angle {worst.theta_deg:g} deg")
    if kind == "friction at mu = 0":
        worst = rows.loc[group.loc[group.value.idxmax()].row]
        return (f"{len(group)} impacts with mu = 0 change their tangential velocity or spin; worst v_t1 = "
                f"{worst.v_t1:.6g} m/s from {worst.v_t0:.6g}, omega1 = {worst.omega1:.4g} rad/s at angle "
                f"{worst.theta_deg:g} deg")
    worst = rows.iloc[0]
    return (f"{len(group)} impacts end with non-finite values, first at e_n = {worst.e_n_target:g}, angle "
            f"{worst.theta_deg:g} deg")
