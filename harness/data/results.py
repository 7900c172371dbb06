"""The results table: one row per impact, stable column names (docs/results.md), written atomically."""
import os

import numpy as np
import pandas as pd

from ..infra.errors import UserError
from ..infra.files import write_text
from ..scenes.kinematics import rebound_quantities
from ..infra.reading import read_table

IDENTITY = ("model", "dialect", "engine", "engine_version", "engine_binary", "engine_sha256", "e_n_target", "mu",
            "theta_deg", "v_n0", "v_t0", "omega0", "radius", "E", "nu", "rho", "dt", "steps_per_contact")
BUILD = ("engine_binary", "engine_sha256")      # the executable that ran and its SHA-256 ('' for the reference)
OUTCOME = ("v_n1", "v_t1", "omega1", "e_n", "e_t", "beta", "psi1_maw", "psi2_maw", "psi1_star", "psi2_star",
           "omega_star", "theta_r_com_deg", "theta_r_cp_deg", "t_contact", "f_n_max", "overlap_max", "ke_ratio",
           "wall_s", "status", "message")
COLUMNS = IDENTITY + OUTCOME


def table(rows):
    """A DataFrame with exactly the result columns, in order."""
    frame = pd.DataFrame(rows)
    missing = [c for c in COLUMNS if c not in frame.columns]
    if missing:
        raise ValueError(f"result rows lack columns {missing}")
    return frame.loc[:, list(COLUMNS)]


def impact_frame(scene, batch, *, model, dialect, engine, engine_version, dt, steps_per_contact, v_n1, v_t1, omega1,
                 wall_s, status, message, t_contact=np.nan, f_n_max=np.nan, overlap_max=np.nan, engine_binary="",
                 engine_sha256=""):
    """Result rows of one batch (one e_n, every impact of the scene), outcome columns derived from the velocities."""
    rows = {
        "model": model, "dialect": dialect, "engine": engine, "engine_version": engine_version,
        "engine_binary": engine_binary, "engine_sha256": engine_sha256,
        "e_n_target": batch.e_n, "mu": scene.mu, "theta_deg": batch.theta_deg, "v_n0": batch.v_n0,
        "v_t0": batch.v_t0, "omega0": batch.omega0, "radius": scene.radius, "E": scene.E, "nu": scene.nu,
        "rho": scene.rho, "dt": dt, "steps_per_contact": steps_per_contact,
        "v_n1": v_n1, "v_t1": v_t1, "omega1": omega1, "t_contact": t_contact, "f_n_max": f_n_max,
        "overlap_max": overlap_max, "wall_s": wall_s, "status": status, "message": message,
    }
    rows.update(rebound_quantities(scene.contact, scene.mu, batch.v_n0, batch.v_t0, batch.omega0,
                                   np.asarray(v_n1, dtype=float), np.asarray(v_t1, dtype=float),
                                   np.asarray(omega1, dtype=float)))
    return mark_invalid(table(rows), pair=bool(scene.spheres))


SMALL_STRAIN = 0.1     # overlap / R: contact radius a = sqrt(R alpha) <= 0.3 R, the range Hertz's theory and every
                       # law built on it assume (a << R)


MOTION = ("v_n1", "v_t1", "omega1", "e_n", "theta_r_com_deg", "theta_r_cp_deg", "ke_ratio")   # finite in any ok row
MEASURED = ("t_contact", "f_n_max", "overlap_max")      # finite in the reference's ok rows (no engine run measures
                                                        # them: NaN there means not measured)
RATIOS = {   # NaN only where its denominator is 0 (undefined; +-inf where it is tiny is the limit): column -> which
    "e_t": ("v_t0",), "beta": ("slip0",), "psi1_maw": ("mu",), "psi2_maw": ("mu",), "psi1_star": ("mu",),
    "psi2_star": ("mu",), "omega_star": ("mu",)}


def undefined(frame):
    """{ratio column: rows where its denominator is 0} (V_t for e_t, the incident slip for beta, mu for the paper's
    and Maw's normalisations)."""
    zero = {"v_t0": frame.v_t0.to_numpy(float) == 0.0, "mu": frame.mu.to_numpy(float) == 0.0,
            "slip0": (frame.v_t0.to_numpy(float) - frame.radius.to_numpy(float) * frame.omega0.to_numpy(float)) == 0.0}
    return {column: np.logical_or.reduce([zero[d] for d in denominators]) for column, denominators in RATIOS.items()}


def non_finite(frame):
    """Per row, the outcome columns that are not finite where they must be ("" when none): the rebound, e_n, the
    angles and the energy ratio always; contact time, peak force and overlap in the reference's rows; a ratio NaN
    where its denominator is not 0."""
    reference = frame.engine.to_numpy() == "reference"
    allowed = undefined(frame)
    bad = {c: ~np.isfinite(frame[c].to_numpy(float)) for c in MOTION}
    bad.update({c: reference & ~np.isfinite(frame[c].to_numpy(float)) for c in MEASURED})
    bad.update({c: ~allowed[c] & np.isnan(frame[c].to_numpy(float)) for c in RATIOS})
    return [", ".join(c for c in bad if bad[c][i]) for i in range(len(frame))]


def mark_invalid(frame, pair=False):
    """Rows that ran but whose result is physically meaningless get status "invalid" and the reason: an overlap
    beyond the small-strain range, a negative e_n (for two spheres: along the line of centres at first touch, which
    an engine's turns as they pass each other), a value that is not finite where it is defined (docs/results.md)."""
    ok = frame.status.to_numpy() == "ok"
    overlap = frame.overlap_max.to_numpy(float) / frame.radius.to_numpy(float)
    missing = non_finite(frame)
    reasons = [(overlap > SMALL_STRAIN, lambda i: f"overlap {overlap[i]:.3g} R exceeds the small-strain range "
                                                  f"({SMALL_STRAIN:g} R) of the law"),
               (frame.e_n.to_numpy(float) < 0.0, lambda i: f"e_n {frame.e_n.iat[i]:.3g} < 0: " + (
                   "along the first line of centres, which turned as the spheres passed" if pair else
                   "the sphere did not rebound")),
               (~np.isfinite(frame.ke_ratio.to_numpy(float)), lambda i: "kinetic energy ratio not finite"),
               (np.array([bool(m) for m in missing], dtype=bool), lambda i: f"not finite: {missing[i]}")]
    for bad, why in reasons:
        for i in np.flatnonzero(ok & bad):
            frame.iat[i, frame.columns.get_loc("status")] = "invalid"
            frame.iat[i, frame.columns.get_loc("message")] = why(i)
            ok[i] = False
    return frame


def write_csv(frame, path):
    """Write the table whole or not at all (harness.infra.files), so an interrupted run never leaves half a table."""
    directory = os.path.dirname(os.path.abspath(os.fspath(path)))
    if not os.path.isdir(directory):
        raise UserError(f"output directory does not exist: {directory}")
    write_text(path, frame.to_csv(index=False, float_format="%.17g"))


TEXT = ("model", "dialect", "engine", "engine_version", "status", "message") + BUILD   # every other one a number


def read_csv(path):
    """Read a results table (a regular file holding every column, numbers where numbers belong); a missing, foreign
    or damaged file is a user error."""
    try:
        frame = read_table(path, [c for c in COLUMNS if c not in BUILD], [c for c in COLUMNS if c not in TEXT],
                           "results table", TEXT)
    except FileNotFoundError:
        raise UserError(f"cannot read results table {path}: no such file") from None
    if frame.empty and not len(frame.columns):
        raise UserError(f"cannot read results table {path}: the file is empty")
    cut = frame[["model", "engine", "dialect", "status"]].isna().any(axis=1).to_numpy()
    if cut.any():
        raise UserError(f"{path} is cut or damaged at data row {int(cut.argmax()) + 1} (a row without its "
                        "model, engine, dialect or status)")
    for column in BUILD:            # a table written before harness recorded the executable
        if column not in frame.columns:
            frame.insert(COLUMNS.index(column), column, "")
    frame[list(BUILD)] = frame[list(BUILD)].fillna("")
    return frame
