"""Distance of the reference's curves from the paper's published points (harness/data/digitised.py): per law, e_n and
quantity, the RMS and worst |reference - published|, the reference interpolated linearly in Psi1* at each published
Psi1*; e_t's distances counted x10 (its range is a tenth of the others')."""
import numpy as np
import pandas as pd

from ..data.digitised import points_of, published_points

SCALE = {"psi2_star": 1.0, "omega_star": 1.0, "e_t": 10.0}
GOAL = {"worst": 0.2, "rms": 0.1}         # issue 27: every law, e_n and quantity within these (e_t x10)
COLUMNS = ["model", "e_n_target", "quantity", "scale", "points", "rms", "worst", "psi1_star_at_worst",
           "published_at_worst", "reference_at_worst"]


def curve_distance(psi1, values, points, scale=1.0):
    """(points compared, RMS, worst, index of the worst) of the curve (psi1, values) from the published points
    inside its Psi1* range, scale times |interpolated - published|."""
    order = np.argsort(psi1)
    psi1, values = np.asarray(psi1, dtype=float)[order], np.asarray(values, dtype=float)[order]
    keep = np.isfinite(psi1) & np.isfinite(values)
    psi1, values = psi1[keep], values[keep]
    inside = (points.psi1_star >= psi1[0]) & (points.psi1_star <= psi1[-1]) if len(psi1) else points.psi1_star < 0
    points = points[inside]
    if points.empty:
        return points, np.array([]), np.nan, np.nan, -1
    reference = np.interp(points.psi1_star, psi1, values)
    distance = scale * np.abs(reference - points.value.to_numpy())
    worst = int(np.argmax(distance))
    return points, reference, float(np.sqrt(np.mean(distance ** 2))), float(distance[worst]), worst


def published_distances(curves):
    """One row per (law, e_n, quantity) the published points cover, from the curves' rows (model, e_n_target,
    psi1_star, psi2_star, omega_star, e_t; status 'ok' where the column exists) of the laws they cover."""
    rows = []
    if "status" in curves:
        curves = curves[curves.status == "ok"]
    covered = set(published_points().model)
    for (model, e_n), group in curves[curves.model.isin(covered)].groupby(["model", "e_n_target"], sort=True):
        for quantity, scale in SCALE.items():
            points = points_of(model, quantity, e_n)
            if points.empty:
                continue
            used, reference, rms, worst, at = curve_distance(group.psi1_star, group[quantity], points, scale)
            row = {"model": model, "e_n_target": float(e_n), "quantity": quantity, "scale": scale,
                   "points": len(used), "rms": rms, "worst": worst}
            if at >= 0:
                row.update(psi1_star_at_worst=float(used.psi1_star.iloc[at]),
                           published_at_worst=float(used.value.iloc[at]), reference_at_worst=float(reference[at]))
            rows.append(row)
    return pd.DataFrame(rows, columns=COLUMNS)


def meets_goal(distances):
    """Rows within GOAL (worst and RMS, e_t x10)."""
    return (distances.worst <= GOAL["worst"]) & (distances.rms <= GOAL["rms"])
