"""YADE and Kratos against the reference's small-system integrator in the engine's dialect on one-sphere scenes, at
equal dt: the largest difference of the recorded states and of the bounce's touch and parting speeds, and the wall
seconds of each engine run (docs/yade-dialect.md#scenes, docs/kratos-dialect.md#scenes). hertz-mindlin on every
one-sphere scene, linear-spring-dashpot on the bounce and at rest; E 1e7, R 5 mm, e_n 0.5, mu 0.3, dt 1e-5.

    python tools/scene_agreement.py [ENGINE ...]      # yade kratos by default
"""
import math
import os
import sys
import tempfile

import numpy as np

from harness.engines import get_engine
from harness.laws import compose
from harness.solver.system import E_VN
from harness.solver.system_rows import contact_properties
from harness.solver.system_run import Sphere, Variant, simulate_system
from harness.studies.scenes import Case

R, E, NU, RHO, MU, G, DT, E_N = 0.005, 1e7, 0.3, 2500.0, 0.3, 9.81, 1e-5, 0.5
REST = (3.0 * 4.0 / 3.0 * math.pi * R ** 3 * RHO * G / (4.0 * E / (2.0 * (1.0 - NU ** 2)) * math.sqrt(R))) ** (2 / 3)
LAWS = {"hertz-mindlin": ("free-fall", "bounce", "rest", "slide-to-roll"), "linear-spring-dashpot": ("bounce", "rest")}
SCENES = {   # kind: (spheres, steps)
    "free-fall": ((Sphere(R, z=0.2, vz=0.5),), 15_000),
    "bounce": ((Sphere(R, z=R + 0.05),), 12_000),
    "rest": ((Sphere(R, z=R),), 20_000),
    "slide-to-roll": ((Sphere(R, z=R - REST, vx=1.0, w=40.0),), 12_000),
}


def grid(steps):
    every = -(-steps // 200)
    return DT * np.unique(np.append(np.arange(0, steps + 1, every), steps)).astype(float)


def engine_run(engine, kind, case, times):
    with tempfile.TemporaryDirectory() as workdir:
        directory = os.path.join(workdir, "batch0")
        os.makedirs(directory)
        with open(os.path.join(directory, engine.INPUT_NAME), "w") as handle:
            handle.write(engine.render_scene(kind, case, times))
        wall, = engine.run_inputs(engine.flavour({}), 1, 600, workdir)
        if isinstance(wall, Exception):
            raise wall
        return engine.read_scene(kind, case, times, directory), wall


def main(names):
    for name in names:
        engine = get_engine(name)
        for law_name, kinds in LAWS.items():
            law, dialect = compose(law_name), engine.dialect(law_name, {}, "wall")
            for kind in kinds:
                print(compared(engine, law, dialect, kind), flush=True)


def compared(engine, law, dialect, kind):
    """One line: the engine's run of `kind` against the reference's in the engine's dialect."""
    spheres, steps = SCENES[kind]
    fields = dict(E=E, nu=NU, rho=RHO, mu=MU, e_n=E_N, speed=1.0, dt=DT, steps=steps, gravity=G)
    case = Case(kind, Variant(spheres, law, **fields), contact_properties(R, None, E, NU, RHO), E_N)
    times = grid(steps)
    got, wall = engine_run(engine, kind, case, times)
    reference = simulate_system([Variant(spheres, dialect, **fields)], times)
    d = np.abs(got.trace[0] - reference.trace[0]).max(axis=(0, 1))
    line = (f"{engine.NAME} {law.name} {kind} ({steps} steps, {wall:.1f} s): max |dx| {d[0]:.2e} m, |dz| {d[1]:.2e} "
            f"m, |dvx| {d[2]:.2e} m/s, |dvz| {d[3]:.2e} m/s, |dw| {d[4]:.2e} rad/s")
    if kind == "bounce":
        n = min(got.n_events[0], reference.n_events[0])
        dv = np.abs(got.events[0, :n, E_VN] - reference.events[0, :n, E_VN]).max()
        line += f"; {n} touches and partings, max |dV_n| {dv:.2e} m/s, first rebound {got.events[0, 1, E_VN]:.9f} m/s"
    return line


if __name__ == "__main__":
    main(sys.argv[1:] or ["yade", "kratos"])
