"""Engine behaviour worth a user's attention, from the results table: energy gained, the invariant breaks a row's
status does not already say, failed runs."""
import numpy as np
import pandas as pd

from ..infra.wording import counted, verb
from .invariants import ENERGY_TOLERANCE, coulomb_ratio, invariant_breaks

SLIDING_TOLERANCE = 1e-3    # |J_t| = mu J_n within 0.1%: the paper law slides throughout (the physics verdict's bound)
SAME_IMPACT = ["model", "e_n_target", "theta_deg", "v_n0", "v_t0", "omega0", "mu", "radius", "E", "nu", "rho"]


def tangential_energy_ratio(frame):
    """(m v_t1^2 + I omega1^2)/(m v_t0^2 + I omega0^2): a contact can only take energy out of these motions."""
    mass = 4.0 / 3.0 * np.pi * frame.radius ** 3 * frame.rho
    inertia = 0.4 * mass * frame.radius ** 2
    before = mass * frame.v_t0 ** 2 + inertia * frame.omega0 ** 2
    after = mass * frame.v_t1 ** 2 + inertia * frame.omega1 ** 2
    return (after / before.where(before > 0)).astype(float)


def _because(row, kind, cause):
    known = cause(row.dialect, row.model, kind)
    return f"; known cause: {known}" if known else ""


def no_cause(dialect, model, kind):
    return ""


def findings(frame, gravity=0.0, cause=no_cause):
    """Engine behaviour worth a user's attention: kinetic energy gained (in all, or in the tangential and
    rotational motion, which friction can only slow), the other invariant breaks of harness.invariants that a row's
    status does not already say (non-finite values, long contact, normal-impact e_n off its target, a tangential
    force without friction), failed runs; cause(dialect, model, kind) -> the documented cause of one, or ''."""
    out = []
    frame = frame.reset_index(drop=True)          # invariant breaks point at rows by label
    frame = frame.assign(kt_ratio=tangential_energy_ratio(frame))
    for kind, column, what in (("energy gain", "ke_ratio", "kinetic energy"),
                               ("tangential energy gain", "kt_ratio", "tangential + rotational kinetic energy")):
        gain = frame[(frame[column] > 1.0 + ENERGY_TOLERANCE) & (frame.status == "ok")]
        for (engine, dialect), group in gain.groupby(["engine", "dialect"], sort=False):
            worst = group.loc[group[column].idxmax()]
            out.append({"engine": engine, "dialect": dialect, "kind": kind,
                        "detail": f"{counted(len(group), 'impact')} {verb(len(group), 'ends')} with more {what} than "
                                  f"at the start; worst ratio "
                                  f"{worst[column]:.6f} at e_n = {worst.e_n_target:g}, angle {worst.theta_deg:g} deg "
                                  f"(v_t1 = {worst.v_t1:.4f} m/s from v_t0 = {worst.v_t0:.4f})"
                                  + _because(worst, "energy gain", cause)})
    breaks = invariant_breaks(frame, gravity)
    breaks = breaks[breaks.kind.isin(("non-finite result", "long contact", "e_n off target", "friction at mu = 0",
                                      "Coulomb bound"))
                    & (frame.loc[breaks.row, "status"].to_numpy() == "ok")]
    for (engine, dialect, _, kind), group in breaks.groupby(["engine", "dialect", "model", "kind"], sort=False):
        rows = frame.loc[group.row]
        out.append({"engine": engine, "dialect": dialect, "kind": kind,
                    "detail": _break_detail(kind, group, rows) + _because(rows.iloc[0], kind, cause)})
    out += under_friction(frame, gravity, cause)
    failed = frame[frame.status != "ok"]
    for (engine, dialect, status), group in failed.groupby(["engine", "dialect", "status"], sort=False):
        out.append({"engine": engine, "dialect": dialect, "kind": status,
                    "detail": f"{counted(len(group), 'impact')}: {group.message.iloc[0]}"
                              + _because(group.iloc[0], status, cause)})
    return pd.DataFrame(out, columns=["engine", "dialect", "kind", "detail"])


def under_friction(frame, gravity=0.0, cause=no_cause):
    """The Coulomb bound from below: impacts the paper law slides throughout (|J_t| = mu J_n) where an engine or
    its formulas transmit less tangential impulse than mu J_n (by more than 0.1%), one finding per engine and
    dialect."""
    ok = frame[frame.status == "ok"].assign(coulomb=lambda f: coulomb_ratio(f, gravity))
    is_paper = (ok.engine == "reference") & (ok.dialect == "paper")
    sliding = ok[is_paper & ((ok.coulomb - 1.0).abs() <= SLIDING_TOLERANCE)]
    if sliding.empty:
        return []
    others = ok[~is_paper].merge(sliding[SAME_IMPACT].drop_duplicates(), on=SAME_IMPACT)
    under = others[others.coulomb < 1.0 - SLIDING_TOLERANCE]
    out = []
    for (engine, dialect), group in under.groupby(["engine", "dialect"], sort=False):
        worst = group.loc[group.coulomb.idxmin()]
        out.append({"engine": engine, "dialect": dialect, "kind": "Coulomb bound from below",
                    "detail": f"{counted(len(group), 'impact')} the paper law slides throughout "
                              f"{verb(len(group), 'transmits')} less than mu J_n; "
                              f"worst |J_t| {worst.coulomb:.3f} mu J_n at e_n {worst.e_n_target:g}, "
                              f"{worst.theta_deg:g} deg" + _because(worst, "Coulomb bound from below", cause)})
    return out


def _break_detail(kind, group, rows):
    """One line for a group of invariant breaks of one kind."""
    if kind == "e_n off target":
        miss = (group.value - group.limit).abs() / group.limit
        worst = group.loc[miss.idxmax()]
        normal = bool((rows.v_t0 == 0).all())
        return (f"{counted(len(group), ('normal ' if normal else '') + 'impact')} {verb(len(group), 'ends')} with e_n "
                f"more than 1% from "
                f"{'the target' if normal else 'the paper law at the same impact'}; worst {worst.value:.4g} for "
                f"{worst.limit:.4g} at e_n {worst.e_n_target:g}, {worst.theta_deg:g} deg")
    if kind == "long contact":
        worst = group.loc[(group.value / group.limit).idxmax()]
        return (f"{counted(len(group), 'impact')} {verb(len(group), 'stays')} in contact longer than the bound; worst "
                f"{worst.value:.3g} s against "
                f"{worst.limit:.3g} s at e_n = {worst.e_n_target:g}, angle {worst.theta_deg:g} deg")
    if kind == "Coulomb bound":
        excess = group.value / group.limit - 1.0
        worst = rows.loc[group.loc[excess.idxmax()].row]
        return (f"{counted(len(group), 'impact')} with |J_t| > mu J_n, worst by {100 * excess.max():.3g}% at e_n "
                f"{worst.e_n_target:g}, {worst.theta_deg:g} deg (v_t1 {worst.v_t1:.4g} m/s from {worst.v_t0:.4g}, "
                f"omega0 {worst.omega0:g} rad/s)")
    if kind == "friction at mu = 0":
        worst = rows.loc[group.loc[group.value.idxmax()].row]
        return (f"{counted(len(group), 'impact')} with mu = 0 {verb(len(group), 'changes')} the tangential velocity "
                f"or spin; worst v_t1 = "
                f"{worst.v_t1:.6g} m/s from {worst.v_t0:.6g}, omega1 = {worst.omega1:.4g} rad/s at angle "
                f"{worst.theta_deg:g} deg")
    worst = rows.iloc[0]
    return (f"{counted(len(group), 'impact')} {verb(len(group), 'ends')} with non-finite values, first at e_n = "
            f"{worst.e_n_target:g}, angle "
            f"{worst.theta_deg:g} deg")
