"""The cost study's converged reference of each dialect: its finest uniform run, every impact that still changes
from half the steps run again at twice the steps until it settles; the paper scheme's from the adaptive integrator
where that is more certain. Its levels are rungs of the dialect's curve beyond the ladder."""
from dataclasses import dataclass, replace

import numpy as np
import pandas as pd

from ..analyses.cost import METRICS, SCALED, impact_errors, uncertainty_of
from ..runs.execute import execute
from ..runs.plan import reference_runs
from ..solver.simulate import adaptive_batch, simulate_adaptive

TRUTH_STEPS = {"paper": 2 ** 16, "engine": 2 ** 18}   # the engines' schemes are first order: a finer truth
TRUTH_SHARPEN = 1e-7             # a paper truth less certain than this is taken from the adaptive integrator ...
TRUTH_TOLERANCE = 1e-11          # ... at this tolerance
TRUTH_TARGET = 1e-4              # an impact whose truth changes by more than this from half its steps is run again
TRUTH_MAX_STEPS = 2 ** 21        # at twice the steps, up to this many


@dataclass
class Truth:
    """A dialect's converged reference: `frame` one row per impact in the scene's order; `uncertainty` per e_n the
    largest last change of its impacts per metric (err_<metric>, err_max) and what the truth is (truth); `levels`
    [(steps per contact, the rows run there, their frame)], coarsest first, the first two every impact."""
    frame: pd.DataFrame
    uncertainty: dict
    levels: list


def truth_of(law, scene, cache=None):
    """The Truth of one dialect: 2^18 uniform steps per contact for an engine's scheme (first order), 2^16 for the
    paper's, each impact's uncertainty its change from half the steps (an upper bound for first- and second-order
    schemes alike); an impact that changes by more than TRUTH_TARGET is run at twice the steps until it does not or
    TRUTH_MAX_STEPS. Where 2^16 steps leave the paper scheme uncertain beyond TRUTH_SHARPEN (Walton-Braun's spring at
    grazing incidence: ~1e-5, order 1.5) and the adaptive integrator covers the law, its run at TRUTH_TOLERANCE
    instead (uncertainty: the change from 10x that tolerance; tests/test_adaptive_walton_braun.py checks it against
    the deep graded ladder). With a cache (a campaign store), the uniform runs are taken from it when it holds them,
    and added to it when not."""
    steps = TRUTH_STEPS["paper" if law.integrator == "paper" else "engine"]
    fine, half = (reference(law, scene, n, cache) for n in (steps, steps // 2))
    every = np.arange(len(fine))
    levels = [(steps // 2, every, half), (steps, every, fine)]
    changes = changes_of(half, fine)
    worst = float(np.nanmax(changes.to_numpy())) if len(changes) else 0.0
    if law.integrator == "paper" and worst > TRUTH_SHARPEN and covered(law, scene):
        truth = simulate_adaptive(law, scene, TRUTH_TOLERANCE).reset_index(drop=True)
        coarse = simulate_adaptive(law, scene, 10 * TRUTH_TOLERANCE).reset_index(drop=True)
        said = f"adaptive at tol {TRUTH_TOLERANCE:.0e} ({steps} steps/contact: {worst:.1e})"
        return Truth(truth, per_e_n(changes_of(coarse, truth), truth, said), levels)
    truth, changes, finer = refined(law, scene, fine, changes, steps, cache)
    said = f"{steps} steps/contact"
    if finer:
        count = len(finer[0][1])
        said += (f"; {count} impact{'s' if count > 1 else ''} changing by more than {TRUTH_TARGET:.0e} refined, up "
                 f"to {finer[-1][0]}")
    return Truth(truth, per_e_n(changes, truth, said), levels + finer)


def reference(law, scene, resolution, cache=None):
    """The reference solver's results of `law` at `resolution`, through the plan (and the cache, if given)."""
    return execute(reference_runs(law, scene, resolution, law), cache=cache)[0].reset_index(drop=True)


def covered(law, scene):
    """The adaptive integrator covers every impact of the scene."""
    return all(adaptive_batch(law, scene, e_n)[1].all() for e_n in scene.e_n)


def changes_of(coarse, fine, scales=None):
    """Per impact and metric the change from `coarse` to `fine` (analyses.cost.impact_errors, e_n by e_n, contact
    time and peak force against their largest value at that e_n, or `scales` {e_n: {metric: scale}})."""
    parts = [impact_errors(coarse.loc[group.index], group, (scales or {}).get(e_n))
             for e_n, group in fine.groupby("e_n_target", sort=False)]
    return pd.concat(parts).loc[fine.index] if parts else pd.DataFrame(columns=list(METRICS))


def refined(law, scene, fine, changes, steps, cache=None):
    """(truth, changes, levels beyond `steps`): the impacts whose change exceeds TRUTH_TARGET run again at twice the
    steps, while any does and up to TRUTH_MAX_STEPS; each level (steps, rows, their frame)."""
    truth, changes, levels = fine.copy(), changes.copy(), []
    scales = {e_n: {m: float(np.nanmax(np.abs(g[m]))) for m in SCALED} for e_n, g in fine.groupby("e_n_target")}
    pending = (changes.max(axis=1) > TRUTH_TARGET).to_numpy()
    n = steps
    while pending.any() and 2 * n <= TRUTH_MAX_STEPS:
        n *= 2
        rows = np.flatnonzero(pending)
        finer = impacts_at(law, scene, truth, rows, n, cache)
        changed = changes_of(truth.iloc[rows].set_axis(finer.index), finer, scales)
        for column in finer.columns:
            truth.loc[truth.index[rows], column] = finer[column].to_numpy()
        changes.iloc[rows] = changed.to_numpy()
        levels.append((n, rows, finer))
        pending = np.zeros(len(truth), dtype=bool)
        pending[rows] = (changed.max(axis=1) > TRUTH_TARGET).to_numpy()
    return truth, changes, levels


def impacts_at(law, scene, frame, rows, resolution, cache=None):
    """The reference's results of `law` at `resolution` for the impacts at `rows` of `frame` (a results table in the
    scene's order), in that order."""
    position = frame.groupby("e_n_target", sort=False).cumcount().to_numpy()
    parts = []
    for e_n in dict.fromkeys(frame.e_n_target.iloc[rows]):
        mine = [r for r in rows if frame.e_n_target.iloc[r] == e_n]
        parts.append(reference(law, part(scene, e_n, position[mine]), resolution, cache))
    return pd.concat(parts, ignore_index=True)


def part(scene, e_n, positions):
    """The scene at one e_n with only its impacts at `positions` (of the field that lists them)."""
    field = next(f for f in ("angles_deg", "psi1_star", "v_t") if getattr(scene, f) is not None)
    values = getattr(scene, field)
    return replace(scene, e_n=(e_n,), **{field: tuple(values[i] for i in positions)})


def per_e_n(changes, truth, said):
    """{e_n: uncertainty} (analyses.cost.uncertainty_of) of the impacts' last changes."""
    return {e_n: uncertainty_of(changes.loc[group.index], said)
            for e_n, group in truth.groupby("e_n_target", sort=False)}
