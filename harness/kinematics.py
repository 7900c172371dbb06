"""Rebound kinematics and normalised quantities of MODELS 4, from incident and rebound velocities.

Convention (printed in every report): wall below, V_n > 0 the approach speed and v_n1 > 0 the rebound speed;
V_t along +x; omega is the spin about +y, positive when the sphere rolls in +x; contact-point slip V_s = V_t - R omega.
"""
import numpy as np

CONVENTIONS = (
    "V_n > 0 is the approach speed, v_n1 > 0 the rebound speed; V_t > 0 along the wall; "
    "omega > 0 is the spin of a sphere rolling in +V_t; contact-point slip V_s = V_t - R omega. "
    "e_n = v_n1/V_n; e_t = v_t1/V_t (centre); beta = -V_sr/V_si (contact point); "
    "Psi1 = kappa V_si/(mu V_n), Psi2 = kappa V_sr/(mu V_n), Psi* = Psi/(1 + e_n); "
    "Omega* = R omega1/[mu (1 + e_n) V_n]; rebound angles atan(v_t1/v_n1) (centre) and atan(V_sr/v_n1) "
    "(contact point), degrees from the normal; kappa = 4G*/E*."
)


def _ratio(num, den):
    num, den = np.broadcast_arrays(np.asarray(num, dtype=float), np.asarray(den, dtype=float))
    out = np.full(num.shape, np.nan)
    with np.errstate(over="ignore"):                 # a denormal mu gives an infinite Psi, which is the limit
        np.divide(num, den, out=out, where=den != 0)
    return out


def rebound_quantities(contact, mu, v_n0, v_t0, omega0, v_n1, v_t1, omega1):
    """All outcome columns that follow from velocities alone (MODELS 4), as a dict of arrays."""
    radius, kappa = contact.radius, contact.kappa
    e_n = _ratio(v_n1, v_n0)
    slip0 = v_t0 - radius * omega0
    slip1 = v_t1 - radius * omega1
    psi1 = kappa * _ratio(slip0, mu * v_n0)
    psi2 = kappa * _ratio(slip1, mu * v_n0)
    ke0 = contact.mass * (v_n0 ** 2 + v_t0 ** 2) + contact.inertia * omega0 ** 2
    ke1 = contact.mass * (v_n1 ** 2 + v_t1 ** 2) + contact.inertia * omega1 ** 2
    return {
        "e_n": e_n,
        "e_t": _ratio(v_t1, v_t0),
        "beta": -_ratio(slip1, slip0),
        "psi1": psi1,
        "psi2": psi2,
        "psi1_star": psi1 / (1.0 + e_n),
        "psi2_star": psi2 / (1.0 + e_n),
        "omega_star": _ratio(radius * omega1, mu * (1.0 + e_n) * v_n0),
        "theta_r_com_deg": np.degrees(np.arctan2(v_t1, v_n1)),
        "theta_r_cp_deg": np.degrees(np.arctan2(slip1, v_n1)),
        "ke_ratio": ke1 / ke0,
    }
