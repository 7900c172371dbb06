"""What a run at one time step says about stability, read from its results: every state finite, no energy gained
beyond a stated bound, a resting contact's overlap not drifting beyond a stated bound; and the verdict of a case's
bracket (studies/stability.py runs the bisection). Reads tables and arrays, runs nothing."""
import math
from dataclasses import dataclass

import numpy as np

IMPACT_GAIN = 1e-9      # an impact's rebound kinetic + rotational energy may exceed the incident one by this fraction
                        # (round-off of the energies of a run of up to 1e6 steps: ~1e-16 per step)
SCENE_GAIN = 1e-9       # a scene's largest energy gain (the system integrator's M_GAIN) as a fraction of its initial
                        # mechanical energy (kinetic and m g z of every body)
DRIFT = 1e-2            # a resting contact's overlap may move by this fraction of the static overlap while held:
                        # a jitter or a creep, not what the settling leaves of a heavily damped Hertz contact
LOST = ("non-finite",)  # the impact status that says a state was not finite (a row still in contact at its step cap,
                        # 'no-separation', is judged by its energy: an engine's reading may say so of a finite rebound)


@dataclass(frozen=True)
class Probe:
    """One run at time step `dt`: whether it passed (is stable, or accurate), why not (or what it measured), its
    energy gain (a fraction of the energy the gain is counted against) and, for a resting contact, the overlap's
    drift (a fraction of the static overlap; NaN where it does not apply)."""
    dt: float
    passed: bool
    why: str
    gain: float = math.nan
    drift: float = math.nan
    log_tail: str = ""      # a failed engine run's log tail


def impact_probe(frame, dt, failure="", log_tail=""):
    """The Probe of an impact run's results table: unstable where the run failed (`failure`, its message, and its
    `log_tail`), a row is
    non-finite (LOST) or its rebound not finite, or the largest ke_ratio - 1 over the impacts is above IMPACT_GAIN
    (every law here has e <= 1: none may return more energy than it was given)."""
    if failure:
        return Probe(dt, False, f"run failed: {failure}", log_tail=log_tail)
    status = frame.status.to_numpy()
    lost = np.isin(status, LOST)
    if lost.any():
        return Probe(dt, False, f"{status[lost][0]} at {frame.theta_deg.to_numpy()[lost][0]:g} deg")
    ratio = frame.ke_ratio.to_numpy(dtype=float)
    if not np.isfinite(ratio).all():
        return Probe(dt, False, "rebound not finite")
    gain = float(np.max(ratio - 1.0))
    worst = float(frame.theta_deg.to_numpy()[int(np.argmax(ratio))])
    if gain > IMPACT_GAIN:
        return Probe(dt, False, f"energy gain {gain:.3g} at {worst:g} deg", gain)
    return Probe(dt, True, f"rebound energy at most 1 + {max(gain, 0.0):.2g} of the incident", gain)


def scene_probe(dt, finite, gain, energy, drift=math.nan):
    """The Probe of a scene run: unstable where a state is not finite, the largest energy gain `gain` [J] is above
    SCENE_GAIN of `energy` [J], or the resting overlap's relative drift is above DRIFT."""
    if not finite:
        return Probe(dt, False, "state not finite")
    relative = gain / energy
    if relative > SCENE_GAIN:
        return Probe(dt, False, f"energy gain {relative:.3g} of the initial energy", relative, drift)
    if drift > DRIFT:
        return Probe(dt, False, f"overlap drift {drift:.3g} of the static overlap", relative, drift)
    held = "" if math.isnan(drift) else f", overlap drift {drift:.2g}"
    return Probe(dt, True, f"energy gain {relative:.2g}{held}", relative, drift)


def overlap_drift(z, static_overlap):
    """max |z - z_0| over the held recorded heights `z` of a sphere resting on the wall, over its static overlap."""
    z = np.asarray(z, dtype=float)
    return float(np.max(np.abs(z - z[0])) / static_overlap) if len(z) else 0.0


def verdict(inside, rayleigh):
    """('pass' or 'fail', why): fail where a probe inside the stable bracket (`inside`, Probes at dt <= dt_stable) or
    the probe at 20% of the Rayleigh time (`rayleigh`) is not stable: any energy gain beyond the round-off bound is
    a failure."""
    bad = [p for p in inside if not p.passed]
    if bad:
        return "fail", f"inside the stable bracket, dt {bad[0].dt:.4g} s: {bad[0].why}"
    if rayleigh is not None and not rayleigh.passed:
        return "fail", f"at 20% of the Rayleigh time, dt {rayleigh.dt:.4g} s: {rayleigh.why}"
    return "pass", "stable at every step probed inside the bracket" + (
        "" if rayleigh is None else " and at 20% of the Rayleigh time")
