"""Each physics check's miss, impact by impact: how far a law's rows are from the paper law's same impacts, in the
check's own measure, and the bound beyond which the impact fails the check (its tolerance, plus a round-off allowance
for the Coulomb check). The verdict (physics.py), the shares of the causes (causes.py) and the attribution's search
for pairs read the same numbers."""
import numpy as np

from .findings import tangential_energy_ratio
from .invariants import FRICTIONLESS_TOLERANCE, coulomb_impulses

CHECKS = ("velocity", "e_n", "coulomb", "energy")
IMPACT = ["model", "e_n_target", "theta_deg", "v_n0", "v_t0", "omega0", "mu", "radius", "E", "nu", "rho"]
VELOCITIES = (("v_n1", "m/s", "V"), ("v_t1", "m/s", "V"), ("omega1", "rad/s", "V/R"))


def with_paper(rows, paper):
    """`rows` (ok) beside the paper law's ok rows of the same impacts (suffix _paper), in the order of `rows`."""
    paper = paper[paper.status == "ok"][IMPACT + ["v_n1", "v_t1", "omega1", "e_n"]]
    return rows[rows.status == "ok"].merge(paper, on=IMPACT, suffixes=("", "_paper")).reset_index(drop=True)


def velocity_miss(pairs):
    """(max over v_n1, v_t1 and R omega1 of |x - paper| / V, the quantity that is the max, {quantity: signed
    difference / V})."""
    speed = np.hypot(pairs.v_n0, pairs.v_t0).to_numpy(dtype=float)
    radius = pairs.radius.to_numpy(dtype=float)
    relative = {metric: (pairs[metric] - pairs[metric + "_paper"]).to_numpy(dtype=float)
                * (radius if metric == "omega1" else 1.0) / speed for metric, _, _ in VELOCITIES}
    stacked = np.abs(np.vstack(list(relative.values())))
    metric_of = [VELOCITIES[j][0] for j in np.argmax(np.nan_to_num(stacked, nan=-1.0), axis=0)]
    return np.fmax.reduce(stacked, axis=0), metric_of, relative


def e_n_miss(pairs):
    """|e_n - the paper law's e_n at the same impact|."""
    return np.abs(pairs.e_n - pairs.e_n_paper).to_numpy(dtype=float)


def coulomb_miss(pairs, tolerance, gravity=0.0):
    """(miss, ratio, allowance, slides): |J_t| / (mu J_n) - 1 where mu > 0, and |that| where the paper law slides
    throughout (its |J_t| = mu J_n within the tolerance, without gravity); the round-off allowance at tiny mu
    (1e-6 V)."""
    j_t, mu_j_n = coulomb_impulses(pairs, gravity)
    speed = np.hypot(pairs.v_n0, pairs.v_t0).to_numpy(dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        ratio = np.where(mu_j_n > 0, j_t / mu_j_n, np.nan)
        paper = (np.abs(pairs.v_t1_paper - pairs.v_t0) / (pairs.mu * (pairs.v_n0 + pairs.v_n1_paper))).to_numpy()
        slides = (np.abs(paper - 1.0) <= tolerance) & (gravity == 0.0)
        miss = np.where(slides, np.abs(ratio - 1.0), ratio - 1.0)
        allowance = np.where(mu_j_n > 0, FRICTIONLESS_TOLERANCE * speed / mu_j_n, 0.0)
    return miss, ratio, allowance, slides


def energy_miss(pairs):
    """(max(KE1/KE0, (KE_t1 + KE_r1)/(KE_t0 + KE_r0)) - 1, the total ratio, the tangential one)."""
    total = pairs.ke_ratio.to_numpy(dtype=float)
    tangential = tangential_energy_ratio(pairs).to_numpy(dtype=float)
    return np.fmax(total, tangential) - 1.0, total, tangential


def misses(pairs, tolerances, gravity=0.0):
    """{check: (per-impact miss, per-impact bound)}: an impact fails a check where its miss exceeds the bound; NaN
    where the check does not apply."""
    ones = np.ones(len(pairs))
    coulomb, _, allowance, _ = coulomb_miss(pairs, tolerances.coulomb, gravity)
    return {"velocity": (velocity_miss(pairs)[0], tolerances.velocity * ones),
            "e_n": (e_n_miss(pairs), tolerances.e_n * ones),
            "coulomb": (coulomb, tolerances.coulomb + allowance),
            "energy": (energy_miss(pairs)[0], tolerances.energy * ones)}


def misses_at(rows, paper, impacts, tolerances, gravity=0.0):
    """misses() of `rows` at the impacts of `impacts` (a frame with the IMPACT columns), in its order: NaN where
    `rows` has no ok row of that impact."""
    return misses(impacts[IMPACT].merge(with_paper(rows, paper), on=IMPACT, how="left"), tolerances, gravity)


def closed_share(before, after):
    """The share of the summed miss `before` that `after` closes (both clipped at 0: a miss below 0 is none), over
    the impacts where both are measured; NaN where there is no miss to close."""
    before, after = np.fmax(before, 0.0), np.fmax(after, 0.0)
    measured = np.isfinite(before) & np.isfinite(after)
    total = before[measured].sum()
    return float((before[measured] - after[measured]).sum() / total) if total > 0 else float("nan")
