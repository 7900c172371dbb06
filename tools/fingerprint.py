"""Exact outputs of the reference solver on a fixed matrix, to prove a refactoring changes none of them.

Every law (and the spring-dashpot laws without their tangential dashpot, which the adaptive integrator covers) and
every engine dialect, at e_n 0.9/0.5/0.1 and 30 impact angles on the paper's scene: the plain kernel at 1000 steps
per contact and the converged mode (Dormand-Prince, SDIRK or the graded ladder, whichever each row takes); then
every engine dialect between two spheres (a smaller steel target spinning against the projectile's spin). Floats are
written in hexadecimal, so equal files mean bitwise equal results.

    python tools/fingerprint.py write before.csv     # before the change
    python tools/fingerprint.py compare before.csv   # after it: exit 1 and the differing rows if any (the rows of
                                                     # a law or dialect added since are named, not compared)
"""
import sys

import numpy as np
import pandas as pd

from harness.engines import ENGINES, EXTERNAL
from harness.laws import LAWS, compose
from harness.runs.request import scene_from
from harness.scenes.scene import Scene
from harness.solver.simulate import simulate

COLUMNS = ("v_n1", "v_t1", "omega1", "t_contact", "f_n_max", "overlap_max", "steps_per_contact", "dt")
SCENE = Scene(e_n=(0.9, 0.5, 0.1), angles_deg=tuple(float(a) for a in np.linspace(0.0, 87.0, 30)))
PAIR_SCENE = scene_from(en=(0.9, 0.5, 0.1), angles=[float(a) for a in np.linspace(0.0, 87.0, 30)], omega0=-20.0,
                        target="sphere", target_radius=0.01, target_material="E=2.1e11,nu=0.29,rho=7800",
                        target_omega=-30.0)


def laws():
    """(label, law) of every law, the dashpot-free spring-dashpot laws, and every engine dialect."""
    out = [(name, compose(name)) for name in LAWS]
    out += [(f"{name} without tangential dashpot", compose(name, {"tangential-damping": "none"}))
            for name in ("linear-spring-dashpot", "hertz-mindlin")]
    out += [(f"{engine} {name}", ENGINES[engine].dialect(name)) for engine in EXTERNAL
            for name in LAWS if ENGINES[engine].supports(name)]
    return out


def pair_laws():
    """(label, law) of every engine dialect between two spheres."""
    import importlib
    out = []
    for engine in EXTERNAL:
        pairs = importlib.import_module(f"harness.engines.{engine}.dialect").PAIR_DIALECTS
        out += [(f"{engine} {name} two spheres", ENGINES[engine].dialect(name, {}, "sphere")) for name in pairs]
    return out


def fingerprint():
    frames = []
    for label, law in laws():
        for mode, options in (("plain", {"steps_per_contact": 1000}), ("converged", {"converged": True})):
            if mode == "converged" and law.integrator != "paper":
                continue
            frame = simulate(law, SCENE, **options)[0]
            frames.append(frame.assign(law=label, mode=mode))
    for label, law in pair_laws():
        frames.append(simulate(law, PAIR_SCENE, steps_per_contact=1000)[0].assign(law=label, mode="plain"))
    table = pd.concat(frames, ignore_index=True)[["law", "mode", "e_n_target", "theta_deg", *COLUMNS, "message"]]
    for column in COLUMNS:
        table[column] = [float(x).hex() for x in table[column]]
    return table


def main(argv):
    if len(argv) != 3 or argv[1] not in ("write", "compare"):
        print(__doc__)
        return 2
    now = fingerprint()
    if argv[1] == "write":
        now.to_csv(argv[2], index=False)
        print(f"wrote {len(now)} rows to {argv[2]}")
        return 0
    before = pd.read_csv(argv[2], keep_default_na=False)
    now = now.astype(str).reset_index(drop=True)
    before = before.astype(str).reset_index(drop=True)
    added = ~now.law.isin(set(before.law))          # a law or dialect the earlier file did not have: new, not changed
    if added.any():
        print(f"{int(added.sum())} rows of laws {argv[2]} does not have, not compared: "
              f"{', '.join(sorted(set(now.law[added])))}")
        now = now[~added].reset_index(drop=True)
    if list(before.columns) != list(now.columns) or len(before) != len(now):
        print(f"different shape: {before.shape} before, {now.shape} now")
        return 1
    differ = (before != now).any(axis=1)
    print(f"{int(differ.sum())} of {len(now)} rows differ")
    if differ.any():
        print(pd.concat([before[differ].head(10), now[differ].head(10)], keys=["before", "now"]).to_string())
    return 1 if differ.any() else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
