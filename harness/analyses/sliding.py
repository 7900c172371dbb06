"""Where an impact slides throughout: the smallest Psi1* found from simulation (harness.studies.sliding_search runs the
search) beside the conditions derived for it (docs/laws.md#sliding-throughout).

Sliding throughout means |F_t| = mu F_n during the whole contact: no step of the reference kernel ends with the
tangential force strictly inside the Coulomb cone (the kernel counts those steps; stick-slip transitions of the
spring are located inside their steps). Then the tangential impulse is mu times the normal one, |v_t1 - v_t0| =
mu (v_n1 + v_n0) without gravity whatever the lever arm (`impulse_deficit`, a check that needs only velocities).
"""
import math
from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class Threshold:
    """The smallest Psi1* found sliding throughout (NaN when none up to the search's PSI_MAX), the bracket width, how it
    was
    found, and the derived condition with its formula where one applies."""
    e_n: float
    simulated: float
    resolution: float
    method: str
    derived: float
    formula: str

    @property
    def difference(self):
        return self.simulated - self.derived


def impulse_deficit(frame):
    """1 - |v_t1 - v_t0| / (mu (v_n1 + v_n0)): 0 when the contact slides throughout (rows without gravity)."""
    tangential = (frame.v_t1 - frame.v_t0).abs().to_numpy(dtype=float)
    normal = (frame.mu * (frame.v_n1 + frame.v_n0)).to_numpy(dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        return 1.0 - tangential / normal


def derived_threshold(law, contact, e_n, speed=5.0):
    """(Psi1*_c, formula) derived for rigid-sphere kinematics with lever R, or (NaN, '') where no condition is
    derived. A viscous law with a tangential dashpot and no tension: Coulomb's test on spring plus dashpot ('total')
    slides throughout exactly when the rigid body does, Psi1* >= 7 (V_s falls to 0 at the release there; once it
    reaches 0 the clipped spring-plus-dashpot force leaves the cone); the spring's test first ('spring-first') keeps
    a spring on a shrinking cone sliding while k_t |V_s| <= mu |F_n'|, which for the linear spring-dashpot binds at
    the release (F_n' = -k_n e V_n there): Psi1* >= 7 - 2e/(q (1 + e)), q = k_t/k_n >= 2/7, where the dashpot holds
    the force on the cone from first touch (Psi1* >= 2 c_n/(c_t (1 + e)) below that). Mindlin's 8G*a on Hertzian
    unloading (elastic Hertz, Thornton, Stronge) slides throughout for Psi1* >= 7 - 2 lam e/(kappa (1 + e)),
    lam = 1 incremental, 2/3 with the eq. 18b rescale; a linear spring k_t = q K1 on the latching spring
    K2 = K1/e^2 (and on the elastic linear spring, e = 1) for Psi1* >= max(2 max(3.5, 1/q)/(1 + e),
    7 - 2/(q e (1 + e)))."""
    if law.lever != 0.0 or law.integrator != "paper":
        return math.nan, ""
    if law.tangential_damping.rule != "none" and law.damping.name != "none" and law.end == "no-tension":
        if law.tangential_damping.cone == "total":
            return 7.0, "7 (rigid body: a dashpot-held contact sticks only once V_s reaches 0)"
        return spring_first_threshold(law, contact, e_n, speed)
    if law.tangential_damping.rule != "none" or law.damping.name != "none":
        return math.nan, ""
    kappa, normal, tangential = contact.kappa, law.normal.name, law.tangential
    hertzian = normal in ("hertz", "thornton", "stronge")
    if hertzian and tangential.name == "mindlin" and tangential.form in ("rescale", "incremental"):
        lam = 2.0 / 3.0 if tangential.form == "rescale" else 1.0
        formula = ("7 - 4e/(3 kappa (1 + e))" if tangential.form == "rescale" else "7 - 2e/(kappa (1 + e))")
        return 7.0 - 2.0 * lam * e_n / (kappa * (1.0 + e_n)), formula
    latching = normal in ("walton-braun", "partially-latching-spring") or (normal == "linear" and e_n == 1.0)
    if latching and tangential.name == "linear":
        q = {"kappa": kappa, "nu": contact.nu}.get(tangential.kt_kn, tangential.kt_kn)
        loading = 2.0 * max(3.5, 1.0 / q) / (1.0 + e_n)
        return max(loading, 7.0 - 2.0 / (q * e_n * (1.0 + e_n))), "max(2 max(3.5, 1/q)/(1 + e), 7 - 2/(q e (1 + e)))"
    return math.nan, ""


def spring_first_threshold(law, contact, e_n, speed):
    """The linear spring-dashpot's 7 - 2e/(q (1 + e)) under the spring-first dashpot, where it holds (q >= 2/7, and
    the dashpot holds the force on the cone at first touch below it: 2 c_n/(c_t (1 + e))); else (NaN, '')."""
    if law.normal.name != "linear" or law.tangential.name != "linear":
        return math.nan, ""
    normal = law.normal.parameters(contact, e_n, speed)
    q = law.tangential.parameter(contact, normal.linear_stiffness) / normal.linear_stiffness
    if q < 2.0 / 7.0:
        return math.nan, ""
    dashpot = law.damping.dashpot(law.normal, contact, e_n, speed, law.end)
    k_t = q * normal.linear_stiffness
    c_t = law.tangential_damping.prefactor(contact, dashpot, normal.linear_stiffness, k_t, e_n) * math.sqrt(k_t)
    release = 7.0 - 2.0 * e_n / (q * (1.0 + e_n))
    if not c_t > 0.0 or 2.0 * dashpot.c0 / (c_t * (1.0 + e_n)) >= release:
        return math.nan, ""
    return release, "7 - 2e/(q (1 + e)) (the spring leaves the shrinking cone at the release)"


def threshold_table(law_name, thresholds):
    """The thresholds as a table: model, e_n_target, simulated, resolution, derived, difference, formula, method."""
    import pandas as pd
    return pd.DataFrame([{"model": law_name, "e_n_target": t.e_n, "simulated": t.simulated,
                          "resolution": t.resolution, "derived": t.derived, "difference": t.difference,
                          "formula": t.formula, "method": t.method} for t in thresholds])
