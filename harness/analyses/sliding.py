"""Where an impact slides throughout: the smallest Psi1* found from simulation, and the conditions derived for it
(docs/laws.md#sliding-throughout).

Sliding throughout means |F_t| = mu F_n during the whole contact: no step of the reference kernel ends with the
tangential force strictly inside the Coulomb cone (the kernel counts those steps; stick-slip transitions of the
spring are located inside their steps). Then the tangential impulse is mu times the normal one, |v_t1 - v_t0| =
mu (v_n1 + v_n0) without gravity whatever the lever arm (`impulse_deficit`, a check that needs only velocities).
"""
import math
from dataclasses import dataclass, replace

import numpy as np

from ..errors import UserError
from ..solver import codes as C
from ..solver.plan import plan_batch
from ..solver.reference import adaptive_batch, run_adaptive, run_kernel

PSI_MAX = 40.0          # Psi1* searched up to this (the rigid-body threshold is 7; viscous laws without a
                        # tangential dashpot approach the sliding line only as 1/Psi1* and never reach it)
SLIDING_STEPS = 10000   # steps per contact of the kernel's runs that search for it (a stick shorter than a step
                        # hides: the threshold found is low by ~1e-3 x Psi1* where the adaptive integrator cannot run)
ADAPTIVE_TOLERANCE = 1e-9
GRID, ROUNDS = 24, 5    # points per round, rounds: the bracket shrinks ~(GRID - 1)^(ROUNDS - 1) times


@dataclass(frozen=True)
class Threshold:
    """The smallest Psi1* found sliding throughout (NaN when none up to PSI_MAX), the bracket width, how it was
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


def _probe(law, scene, e_n, psi):
    """The kernel rows of the normal impact at the scene speed with these Psi1* values, and whether the adaptive
    integrator covers them."""
    probe = replace(scene, e_n=(e_n,), angles_deg=None, v_t=None, psi1_star=tuple(float(p) for p in psi),
                    omega0=0.0, gravity=0.0)
    batch, covered = adaptive_batch(law, probe, e_n)
    return probe, covered.all()


def method(law, scene, e_n):
    """How the threshold is found for this law: located stick events, or kernel steps."""
    if _probe(law, scene, e_n, (1.0,))[1]:
        return f"adaptive integrator, located stick events (tol {ADAPTIVE_TOLERANCE:.0e})"
    return f"kernel, no step ending inside the cone at {SLIDING_STEPS} steps/contact"


def _sliding(law, scene, e_n, psi):
    """Per Psi1* value (the request, with the target e_n): does the impact slide throughout (False where the run
    did not end ok), and its achieved e_n. The adaptive integrator where it covers the law (its stick phases are
    located events, also at the singular release of Hertzian unloading), else the kernel at SLIDING_STEPS (no step
    may end sticking)."""
    probe, covered = _probe(law, scene, e_n, psi)
    if covered:
        batch = adaptive_batch(law, probe, e_n)[0]
        out = run_adaptive(batch, np.arange(len(psi)), ADAPTIVE_TOLERANCE)[0]
    else:
        out = run_kernel(plan_batch(law, probe, e_n, SLIDING_STEPS))[0]
    slides = (out[:, C.O_STATUS] == C.STATUS_OK) & (out[:, C.O_STICKING] == 0)
    return slides, out[:, C.O_VZ] / scene.speed


def simulated_threshold(law, scene, e_n):
    """(smallest Psi1* that slides throughout, bracket width), in the paper's Psi1* with the achieved e_n (the
    results table's psi1_star): a grid over (0, PSI_MAX], then grids inside the bracket of the last change from
    sticking to sliding; (NaN, NaN) when nothing slides throughout."""
    if scene.mu <= 0.0:
        raise UserError("sliding throughout needs friction: mu > 0")
    lo, hi, achieved = 0.0, PSI_MAX, e_n
    for _ in range(ROUNDS):
        psi = np.linspace(lo, hi, GRID)[1:] if lo == 0.0 else np.linspace(lo, hi, GRID)
        slides, e_achieved = _sliding(law, scene, e_n, psi)
        if not slides[-1]:
            return math.nan, math.nan
        sticks = np.flatnonzero(~slides)
        first = sticks[-1] + 1 if len(sticks) else 0
        achieved = e_achieved[first]
        if len(sticks) == 0:
            lo, hi = float(psi[0]) - (psi[1] - psi[0]), float(psi[0])
            break
        lo, hi = float(psi[sticks[-1]]), float(psi[first])
    to_paper = (1.0 + e_n) / (1.0 + achieved)          # Psi1* requested with the target e, reported with the achieved
    return hi * to_paper, (hi - lo) * to_paper


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


def sliding_thresholds(law, scene):
    """One Threshold per e_n of the scene, at the scene's speed held as the normal speed (the paper's figures)."""
    out = []
    for e_n in scene.e_n:
        found, width = simulated_threshold(law, scene, e_n)
        derived, formula = derived_threshold(law, scene.contact, e_n, scene.speed)
        out.append(Threshold(e_n, found, width, method(law, scene, e_n), derived, formula))
    return out


def threshold_table(law_name, thresholds):
    """The thresholds as a table: model, e_n_target, simulated, resolution, derived, difference, formula, method."""
    import pandas as pd
    return pd.DataFrame([{"model": law_name, "e_n_target": t.e_n, "simulated": t.simulated,
                          "resolution": t.resolution, "derived": t.derived, "difference": t.difference,
                          "formula": t.formula, "method": t.method} for t in thresholds])
