"""The search for where an impact slides throughout (analyses/sliding.py): the reference solver runs grids of normal
impacts over Psi1*, each round inside the bracket of the last change from sticking to sliding; the adaptive
integrator where it covers the law (its stick phases are located events), else the kernel, whose count of steps
ending inside the Coulomb cone says whether a run stuck."""
import math
from dataclasses import replace

import numpy as np

from ..analyses.sliding import Threshold, derived_threshold
from ..infra.errors import UserError
from ..solver import codes as C
from ..solver.simulate import adaptive_batch, batch_at, run_adaptive, run_kernel

PSI_MAX = 40.0          # Psi1* searched up to this (the rigid-body threshold is 7; viscous laws without a
                        # tangential dashpot approach the sliding line only as 1/Psi1* and never reach it)
SLIDING_STEPS = 10000   # steps per contact of the kernel's runs that search for it (a stick shorter than a step
                        # hides: the threshold found is low by ~1e-3 x Psi1* where the adaptive integrator cannot run)
ADAPTIVE_TOLERANCE = 1e-9
GRID, ROUNDS = 24, 5    # points per round, rounds: the bracket shrinks ~(GRID - 1)^(ROUNDS - 1) times


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
        out = run_kernel(batch_at(law, probe, e_n, SLIDING_STEPS))[0]
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


def sliding_thresholds(law, scene):
    """One Threshold per e_n of the scene, at the scene's speed held as the normal speed (the paper's figures)."""
    out = []
    for e_n in scene.e_n:
        found, width = simulated_threshold(law, scene, e_n)
        derived, formula = derived_threshold(law, scene.contact, e_n, scene.speed)
        out.append(Threshold(e_n, found, width, method(law, scene, e_n), derived, formula))
    return out
