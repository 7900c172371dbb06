"""Catalogue of hard cases: named Scene overrides on a base scene, each with the laws it applies to,
and runners that put a case through the reference or, batched, through an engine."""
from dataclasses import dataclass

import numpy as np
import pandas as pd

from ..infra.errors import UserError
from ..laws import LAWS, compose
from ..scenes.scene import Scene

ALL_LAWS = tuple(LAWS)
EN_RANGE = (0.01, 0.02, 0.05, 0.1, 0.3, 0.5, 0.7, 0.9, 0.99, 1.0)   # "e_n from 0.01 to 1"
EN_DEFAULT = (0.05, 0.5, 1.0)         # low, middle and elastic, for the cases that vary something else
ANGLES = (0.0, 45.0, 89.5)            # normal (e_n is checked there), oblique, grazing
RATIO_TANGENTIAL = ("linear", "walton-braun")      # tangential springs whose k_t/k_n is an option (`linear:R`)
KT_KN_RANGE = (1e-3, 10.0)            # those springs accept k_t/k_n in (0, 10] (harness/submodels/tangential/ratio.py)
NU_RANGE = (0.499, -0.99)             # Mindlin's k_t/k_n = kappa = 2(1-nu)/(2-nu): 0.6671 and 1.3311 at the ends of
                                      # the Poisson range (-1, 0.5) a Scene accepts


BASE_SCENE = dict(radius=5e-3, mu=0.3, speed=1.0, material="example-5mm")   # the catalogue's values were chosen
                                    # on this scene (at the paper's 5 m/s E = 1e6 Pa would overlap 0.75 R)


@dataclass(frozen=True)
class HardCase:
    """One hard case: overrides of BASE_SCENE (R 5 mm, E 70 GPa, nu 0.3, rho 2650, mu 0.3, V 1 m/s), the laws it
    applies to, and k_t/k_n for the tangential springs that take a ratio (None: the law's own)."""
    name: str
    scene: dict
    laws: tuple = ALL_LAWS
    kt_kn: float | None = None
    why: str = ""

    def make_scene(self, **extra):
        """The Scene of this case (default e_n and angles unless the case sets them); `extra` overrides further."""
        values = {**BASE_SCENE, "e_n": EN_DEFAULT, "angles_deg": ANGLES, **self.scene, **extra}
        return Scene(**values)

    def law(self, name):
        """The registry law `name` with this case's k_t/k_n where its tangential spring takes one (engine dialects keep
        their own: LIGGGHTS k_t = k_n, YADE 2/7 or nu; only Mindlin's kappa moves with nu in every engine)."""
        if name not in self.laws:
            raise UserError(f"hard case {self.name!r} does not apply to {name}")
        law = compose(name)
        if self.kt_kn is None or law.tangential.name not in RATIO_TANGENTIAL:
            return law
        return compose(name, {"tangential": f"{law.tangential.name}:{self.kt_kn!r}"})


CATALOGUE = (
    HardCase("e_n 0.01 to 1", {"e_n": EN_RANGE, "angles_deg": (0.0, 45.0)},
             why="calibrations at both ends: overdamped-looking dashpots at 0.01, no dissipation at 1"),
    HardCase("exactly normal", {"angles_deg": (0.0,)}, why="no tangential motion: the plan switches friction off"),
    HardCase("grazing 89.5 deg", {"angles_deg": (89.5,)},
             why="V_n = 0.0087 V: long, shallow contact; plastic laws stay elastic below V_y"),
    HardCase("mu = 0", {"mu": 0.0}, why="no tangential force at all: rotation stays zero"),
    HardCase("mu = 2", {"mu": 2.0},
             why="rigid-body sliding only above 82 deg (tan theta = 3.5 mu (1 + e)): sticking, rolling, reversal"),
    HardCase("k_t/k_n low", {"nu": NU_RANGE[0]}, kt_kn=KT_KN_RANGE[0],
             why="tangential spring nearly absent (ratio 1e-3), Mindlin kappa 0.667 (nu 0.499)"),
    HardCase("k_t/k_n high", {"nu": NU_RANGE[1]}, kt_kn=KT_KN_RANGE[1],
             why="tangential spring 10x the normal one; Mindlin kappa 1.331 (nu -0.99)"),
    HardCase("E = 1e12 Pa", {"E": 1e12}, why="very stiff: contact 12 us, peak overlap 8e-4 R"),
    HardCase("E = 1e6 Pa", {"E": 1e6},
             why="very soft: contact 3 ms, peak overlap 0.14-1.9 R (the engines' levers R - alpha/2, R - alpha "
                 "shorten); beyond 0.1 R a row is 'invalid', outside the small-strain range"),
    HardCase("R = 10 um", {"radius": 1e-5}, why="tiny mass (1.1e-11 kg), contact 69 ns, V/R = 1e5 rad/s"),
    HardCase("R = 0.1 m", {"radius": 0.1}, why="large sphere: 11 kg, contact 0.69 ms"),
    HardCase("spin against the motion", {"omega0": -400.0, "angles_deg": (0.0, 20.0, 45.0, 89.5)},
             why="R omega0 = -2 V: the contact point slides at up to 3 V; friction slows the backspin"),
    HardCase("thornton e_n 0.05", {"e_n": (0.05,), "angles_deg": (0.0, 10.0, 30.0, 60.0, 89.5)},
             laws=("thornton",), why="deep plastic flow: V/V_y = 1/r = 3.2e5 at e_n = 0.05 (docs/laws.md)"),
    HardCase("K2 = 400 K1", {"e_n": (0.05,), "angles_deg": (0.0, 10.0, 30.0, 60.0, 89.5)},
             laws=("walton-braun", "partially-latching-spring"),
             why="Walton-Braun unloading 400x stiffer than loading (K2 = K1/e^2 at e_n = 0.05): 20x shorter period"),
)


def get_case(name):
    """The catalogue case called `name`; UserError listing the names otherwise."""
    for case in CATALOGUE:
        if case.name == name:
            return case
    raise UserError(f"unknown hard case {name!r}; known: {', '.join(c.name for c in CATALOGUE)}")


def material_key(scene):
    """What one engine run must share: everything but the impacts (angles, spin) and e_n."""
    return tuple((k, v) for k, v in sorted(vars(scene).items()) if k not in ("e_n", "angles_deg", "omega0", "extra"))


def run_reference(case, name, steps_per_contact=1000, **scene_overrides):
    """Results table of registry law `name` on `case` through the reference, with a 'case' column."""
    from ..solver.simulate import simulate
    frame = simulate(case.law(name), case.make_scene(**scene_overrides), steps_per_contact=steps_per_contact)[0]
    return frame.assign(case=case.name)


def run_engine(engine, name, cases, e_n, steps_per_contact=1000, options=None, **scene_overrides):
    """Every impact of `cases` (one material) at target e_n in ONE run of `engine`: (results table with a 'case'
    column, [FailedRun]); a refused or failed run gives status 'failed' rows and its one-line message."""
    from dataclasses import replace
    from ..runs.plan import engine_runs
    scenes = [case.make_scene(e_n=(e_n,), **scene_overrides) for case in cases]
    if len({material_key(s) for s in scenes}) != 1:
        raise ValueError("one engine run holds one material: these cases differ in more than angles, spin or e_n")
    run = replace(engine_runs(engine, compose(name), scenes[0], steps_per_contact, options)[0],
                  together=tuple(scenes[1:]))
    merged, failure = engine.run([run])[0]
    sizes = [len(s.impacts(e_n)[0]) for s in scenes]
    starts = np.cumsum([0] + sizes)
    frames = [merged.iloc[start:start + size].assign(case=case.name) for case, start, size in zip(cases, starts, sizes)]
    return pd.concat(frames, ignore_index=True), [failure] if failure is not None else []
