"""Invariants every impact must keep (issue 6): finite results, no kinetic-energy gain, separation within a bounded
time, the normal-impact e_n of its calibration, and outcomes continuous in the inputs. `invariant_breaks` and
`discontinuities` list the rows of a results table that break one, whatever engine produced them."""
import math

import numpy as np
import pandas as pd

# Tolerances, each with its physical justification:
ENERGY_TOLERANCE = 1e-6       # O((omega dt)^2) energy error of a second-order scheme over one elastic contact: <= 4e-9
                              # measured at 1000 and 2e-9 at 100 steps/contact; every physical gain found is >= 1e-4
E_N_TOLERANCE = 1e-2          # relative: experimental e_n is rarely known better than 1%; 3x the App. B fit's error
                              # below e_n 0.95 and the (omega dt)^2/8 = 3e-3 of a K2 = 1e4 K1 unloading at 1000 steps
FRICTIONLESS_TOLERANCE = 1e-6 # per V: with mu = 0 Coulomb allows no tangential force (|F_t| <= mu F_n), so v_t and
                              # R omega keep their values, but for the normal of YADE's stand-in sphere (radius 3e5 R),
                              # which tilts by slide/3e5 R ~ 2e-8 rad during a contact (measured 8e-9 of V)
CONTACT_TIME_FACTOR = 2.0     # the plan's contact-time estimate at the impact's normal speed (Hertz V_n^-1/5) is
                              # within 10% of every paper law's contact (measured on the catalogue): 2x is generous
SMOOTH_JUMP_RATIO = 0.7       # halving a grid spacing halves the largest neighbour jump of a smooth outcome (-> 0.5,
                              # more where the slope changes within a spacing); a discontinuity keeps it (ratio ~1)
COULOMB_TOLERANCE = 1e-6      # relative to mu J_n: |F_t| <= mu F_n at every instant gives |J_t| <= mu J_n exactly;
                              # the paper laws keep it to 1e-12 (measured on every law, 135 impacts each, with spin);
                              # plus FRICTIONLESS_TOLERANCE V: at mu ~ 1e-12 the round-off of v_t's steps dominates
MOTION = ("v_n1", "v_t1", "omega1", "ke_ratio")
REFERENCE_ONLY = ("t_contact", "f_n_max", "overlap_max")   # engines report no force history
CONTINUITY_METRICS = ("v_n1", "v_t1", "omega1")      # per impact speed: bounded, unlike e_t ~ 1/theta
PARAMETER_METRICS = ("e_n", "e_t", "omega_star")
SWEEP_IDENTITY = ("engine", "dialect", "model", "e_n_target", "mu", "theta_deg", "omega0", "radius", "E", "nu", "rho",
                  "case")       # "case": a hard-case label (harness.studies.hard_cases), where the table has one
COLUMNS = ["engine", "dialect", "model", "e_n_target", "theta_deg", "kind", "value", "limit", "row"]


def contact_time_bound(frame):
    """Longest plausible contact: factor x t_est (V/V_n)^1/5 sqrt(1 + ln^2 e/pi^2), t_est = dt x steps per contact
    (the plan's estimate at the scene speed V ~ |v0|; a dashpot ending at alpha = 0 lengthens the contact by
    1/sqrt(1 - g^2), docs/laws.md); engine dialects, which keep the contact at zero force until the gap opens (a latched
    dent, a clipped dashpot), also get the time to cross the largest overlap at the rebound speed."""
    t_est = frame.dt * frame.steps_per_contact
    slow = np.maximum(np.hypot(frame.v_n0, frame.v_t0) / frame.v_n0, 1.0) ** 0.2
    damped = np.sqrt(1.0 + (np.log(frame.e_n_target) / math.pi) ** 2)
    with np.errstate(divide="ignore", invalid="ignore"):
        exit_time = np.where(frame.v_n1 > 0, frame.overlap_max / frame.v_n1, np.inf)
    exit_time = np.where(frame.dialect == "paper", 0.0, exit_time)
    return CONTACT_TIME_FACTOR * t_est * slow * damped + exit_time


def _rows(frame, mask, kind, value=None, limit=None):
    mask = np.asarray(mask, dtype=bool)
    nan = np.full(len(frame), np.nan)
    part = frame.loc[mask]
    return pd.DataFrame({"engine": part.engine, "dialect": part.dialect, "model": part.model,
                         "e_n_target": part.e_n_target, "theta_deg": part.theta_deg, "kind": kind,
                         "value": np.asarray(nan if value is None else value, dtype=float)[mask],
                         "limit": np.asarray(nan if limit is None else limit, dtype=float)[mask], "row": part.index})


def _joined(parts):
    parts = [p for p in parts if not p.empty]
    return pd.concat(parts, ignore_index=True).loc[:, COLUMNS] if parts else pd.DataFrame(columns=COLUMNS)


def invariant_breaks(frame, gravity=0.0):
    """Rows breaking an invariant, one line per (row, kind): 'non-finite result', 'energy gain' (ke_ratio > 1 + tol),
    'no separation', 'long contact' (t_contact > contact_time_bound), 'e_n off target' (|e_n - target| > 1% of
    target: at normal incidence against the calibration target, since every law calibrates e_n for the normal impact
    at the scene speed; at every angle against the paper law's e_n at the same impact where the table holds it),
    'friction at
    mu = 0' (v_t or R omega changed with mu = 0) and 'Coulomb bound' (|J_t| > mu J_n: the tangential impulse
    m |v_t1 - v_t0| beyond mu times the normal impulse m (v_n0 + v_n1) + m g t_c). Failed runs are not judged: they
    have no results."""
    ok = (frame.status == "ok").to_numpy()
    is_reference = (frame.engine == "reference").to_numpy()
    finite = np.isfinite(frame[list(MOTION)].to_numpy(dtype=float)).all(axis=1)
    finite &= ~is_reference | np.isfinite(frame[list(REFERENCE_ONLY)].to_numpy(dtype=float)).all(axis=1)
    ke = frame.ke_ratio.to_numpy(dtype=float)
    t_c = frame.t_contact.to_numpy(dtype=float)
    target = frame.e_n_target.to_numpy(dtype=float)
    e_n = frame.e_n.to_numpy(dtype=float)
    with np.errstate(invalid="ignore"):
        bound = np.asarray(contact_time_bound(frame), dtype=float)
        long_contact = ok & is_reference & (t_c > bound)
        target, matched = e_n_targets(frame)
        off = ok & ((frame.v_t0 == 0).to_numpy() | matched) & (np.abs(e_n - target) > E_N_TOLERANCE * target)
        gain = ok & (ke > 1.0 + ENERGY_TOLERANCE)
        speed = np.hypot(frame.v_n0, frame.v_t0).to_numpy(dtype=float)
        change = (np.abs(frame.v_t1 - frame.v_t0) + frame.radius * np.abs(frame.omega1 - frame.omega0)).to_numpy(
            dtype=float) / speed
        friction = ok & (frame.mu == 0).to_numpy() & (change > FRICTIONLESS_TOLERANCE)
        j_t, mu_j_n = coulomb_impulses(frame, gravity)
        coulomb = ok & (frame.mu > 0).to_numpy() & (j_t > mu_j_n * (1.0 + COULOMB_TOLERANCE)
                                                     + FRICTIONLESS_TOLERANCE * speed)
    return _joined([
        _rows(frame, (ok & ~finite) | (frame.status == "non-finite").to_numpy(), "non-finite result"),
        _rows(frame, gain, "energy gain", ke, np.full(len(frame), 1.0 + ENERGY_TOLERANCE)),
        _rows(frame, (frame.status == "no-separation").to_numpy(), "no separation"),
        _rows(frame, long_contact, "long contact", t_c, bound),
        _rows(frame, off, "e_n off target", e_n, target),
        _rows(frame, friction, "friction at mu = 0", change, np.full(len(frame), FRICTIONLESS_TOLERANCE)),
        _rows(frame, coulomb, "Coulomb bound", j_t, mu_j_n),
    ])


PAPER_IMPACT = ["model", "e_n_target", "theta_deg", "v_n0", "v_t0", "omega0", "mu", "radius", "E", "nu", "rho"]


def e_n_targets(frame):
    """(target e_n per row, whether it comes from the paper law): an engine's or a dialect's row whose impact the
    paper law also ran (same table) has the paper law's e_n at that impact as its target, at every angle; every other
    row the calibration target e_n_target (checked at normal incidence, where every law is calibrated)."""
    target = frame.e_n_target.to_numpy(dtype=float).copy()
    matched = np.zeros(len(frame), dtype=bool)
    columns = [c for c in PAPER_IMPACT if c in frame.columns]
    paper = frame[(frame.dialect == "paper") & (frame.engine == "reference") & (frame.status == "ok")]
    if paper.empty or len(columns) < len(PAPER_IMPACT):
        return target, matched
    others = frame[frame.dialect != "paper"].reset_index().merge(
        paper[columns + ["e_n"]].drop_duplicates(columns), on=columns, suffixes=("", "_paper"))
    position = frame.index.get_indexer(others["index"])
    target[position] = others.e_n_paper.to_numpy(dtype=float)
    matched[position] = True
    return target, matched


def coulomb_impulses(frame, gravity=0.0):
    """Per unit mass: the tangential impulse |v_t1 - v_t0| and mu times the normal one, v_n0 + v_n1 + g t_c (the
    wall's push also carries the weight during contact; NaN where that needs a contact time the row lacks)."""
    j_n = (frame.v_n0 + frame.v_n1).to_numpy(dtype=float)
    if gravity:
        j_n = j_n + gravity * frame.t_contact.to_numpy(dtype=float)
    return np.abs(frame.v_t1 - frame.v_t0).to_numpy(dtype=float), frame.mu.to_numpy(dtype=float) * j_n


def coulomb_ratio(frame, gravity=0.0):
    """|J_t| / (mu J_n) per impact (NaN where mu J_n is 0): at most 1 when |F_t| <= mu F_n holds throughout."""
    j_t, mu_j_n = coulomb_impulses(frame, gravity)
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(mu_j_n > 0, j_t / mu_j_n, np.nan)


def max_jump(values):
    """Largest |f_i+1 - f_i| / max(1, |f_i|, |f_i+1|) along a sweep (relative where f is large)."""
    values = np.asarray(values, dtype=float)
    scale = np.maximum(1.0, np.maximum(np.abs(values[1:]), np.abs(values[:-1])))
    jumps = np.abs(np.diff(values)) / scale
    return float(np.nanmax(jumps)) if np.isfinite(jumps).any() else np.nan


def jump_floor(steps_per_contact):
    """pi/N: the most one time step of contact force changes a rebound velocity (a half-sine pulse of N steps peaks at
    (pi/2)(1 + e) m V/t_c); jumps below it are the step-granular contact end every engine has."""
    return math.pi / steps_per_contact


def normalised(frame, metric):
    """Rebound velocities per impact speed |v0| (omega1 as R omega1/|v0|); other metrics as they are."""
    speed = np.hypot(frame.v_n0, frame.v_t0).to_numpy(dtype=float)
    values = frame[metric].to_numpy(dtype=float)
    if metric in ("v_n1", "v_t1"):
        return values / speed
    return values * frame.radius.to_numpy(dtype=float) / speed if metric == "omega1" else values


def discontinuities(frame, parameter="theta_deg", metrics=CONTINUITY_METRICS, floor=None):
    """Sweeps over `parameter` (uniform, odd number of points >= 5, everything else equal) whose largest neighbour
    jump does not halve from the every-other-point grid to the full grid (ratio > SMOOTH_JUMP_RATIO) and exceeds
    `floor` (default jump_floor): one line per (sweep, metric), kind 'discontinuity in <metric>', value the ratio.
    Velocities are compared per impact speed (normalised), other metrics relative where they exceed 1."""
    keys = [k for k in SWEEP_IDENTITY if k != parameter and k in frame.columns]
    parts = []
    ok = frame[frame.status == "ok"]
    for _, sweep in ok.groupby(keys, sort=False, dropna=False):
        sweep = sweep.sort_values(parameter)
        x = sweep[parameter].to_numpy(dtype=float)
        if len(x) < 5 or len(x) % 2 == 0 or not np.allclose(np.diff(x), x[1] - x[0], rtol=1e-6, atol=0):
            continue
        least = jump_floor(float(sweep.steps_per_contact.min())) if floor is None else floor
        for metric in metrics:
            values = normalised(sweep, metric)
            fine, coarse = max_jump(values), max_jump(values[::2])
            if not (fine > least and fine > SMOOTH_JUMP_RATIO * coarse):
                continue
            scale = np.maximum(1.0, np.maximum(np.abs(values[1:]), np.abs(values[:-1])))
            worst = int(np.nanargmax(np.abs(np.diff(values)) / scale))
            mask = sweep.index == sweep.index[worst]
            parts.append(_rows(sweep, mask, f"discontinuity in {metric}", np.full(len(sweep), fine / coarse),
                               np.full(len(sweep), SMOOTH_JUMP_RATIO)))
    return _joined(parts)

