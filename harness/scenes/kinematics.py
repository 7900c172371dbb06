"""Rebound kinematics and the paper's normalised quantities, from incident and rebound velocities
(docs/laws.md#normalisation).

Convention (printed in every report): wall below, V_n > 0 the approach speed and v_n1 > 0 the rebound speed;
V_t along +x; omega is the spin about +y, positive when the sphere rolls in +x; contact-point slip V_s = V_t - R omega.
"""
import numpy as np

CONVENTIONS = (
    "V_n > 0 is the approach speed, v_n1 > 0 the rebound speed; V_t > 0 along the wall; "
    "omega > 0 is the spin of a sphere rolling in +V_t; contact-point slip V_s = V_t - R omega. "
    "e_n = v_n1/V_n; e_t = v_t1/V_t (centre); beta = -V_sr/V_si (contact point). "
    "The paper's normalisation (Thornton, Cummins & Cleary 2013), e the achieved e_n: "
    "Psi1* = 2 V_si/(mu (1 + e) V_n), Psi2* = 2 V_sr/(mu (1 + e) V_n), Omega* = -2 R omega1/(mu (1 + e) V_n); "
    "a rigid sphere sliding throughout has Omega* = -5 and Psi2* = Psi1* - 7, and without initial spin "
    "e_t = 5/7 + 2 Psi2*/(7 Psi1*). Maw, Barber & Fawcett's form is kept apart as psi1_maw = kappa V_si/(mu V_n) "
    "and psi2_maw = kappa V_sr/(mu V_n), kappa = 4G*/E*. Rebound angles atan(v_t1/v_n1) (centre) and "
    "atan(V_sr/v_n1) (contact point), degrees from the normal."
)


def _ratio(num, den):
    num, den = np.broadcast_arrays(np.asarray(num, dtype=float), np.asarray(den, dtype=float))
    out = np.full(num.shape, np.nan)
    with np.errstate(over="ignore", invalid="ignore"):   # a denormal mu gives an infinite Psi, which is the limit
        np.divide(num, den, out=out, where=den != 0)
    return out


def paper_scale(mu, e_n, v_n0):
    """mu (1 + e) V_n / 2: the paper's unit of tangential speed (Psi* = V_s / this, Omega* = -R omega / this)."""
    return 0.5 * mu * (1.0 + np.asarray(e_n, dtype=float)) * v_n0


def rebound_quantities(contact, mu, v_n0, v_t0, omega0, v_n1, v_t1, omega1):
    """All outcome columns that follow from velocities alone (docs/laws.md#normalisation), as a dict of arrays."""
    radius, kappa = contact.radius, contact.kappa
    e_n = _ratio(v_n1, v_n0)
    slip0 = v_t0 - radius * omega0
    slip1 = v_t1 - radius * omega1
    unit = paper_scale(mu, e_n, v_n0)
    ke0 = contact.mass * (v_n0 ** 2 + v_t0 ** 2) + contact.inertia * omega0 ** 2
    ke1 = contact.mass * (v_n1 ** 2 + v_t1 ** 2) + contact.inertia * omega1 ** 2
    return {
        "e_n": e_n,
        "e_t": _ratio(v_t1, v_t0),
        "beta": -_ratio(slip1, slip0),
        "psi1_maw": kappa * _ratio(slip0, mu * v_n0),
        "psi2_maw": kappa * _ratio(slip1, mu * v_n0),
        "psi1_star": _ratio(slip0, unit),
        "psi2_star": _ratio(slip1, unit),
        "omega_star": -_ratio(radius * omega1, unit),
        "theta_r_com_deg": np.degrees(np.arctan2(v_t1, v_n1)),
        "theta_r_cp_deg": np.degrees(np.arctan2(slip1, v_n1)),
        "ke_ratio": ke1 / ke0,
    }
