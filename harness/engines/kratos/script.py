"""Kratos' input and output: one Python script per run, every impact its own sphere (or pair) far from the others
against one rigid face, run by the Kratos venv's python in its batch's directory, and the velocities it reads from
the model part back (docs/kratos-dialect.md)."""
import json
import os
from pathlib import Path

import numpy as np

from ...infra.render import render
from ...infra.version import __version__
from ...infra.wording import counted
from ..dumps import pair_rebound, rebound
from ..runner import EngineFailure, read_tail, run_engine
from ..start import approach_drift, stepping, states_array
from .dialect import COUNTERPARTS

TEMPLATES = Path(__file__).resolve().parent / "templates"
RIGID_SCALE = 1e20              # a rigid wall: its E this many times the sphere's (Kratos' own tests use 1e20)
INPUT = "harness_kratos.py"
RESULT, OBSERVED, STATES = "result.json", "observe.json", "states.json"
# every sphere starts CLEARANCE of the contact's size clear of its target: Kratos counts contact from overlap > 0, and
# at a gap of exactly 0 the round-off of the distance to the face (it grows with x) would decide whether a sphere
# touches at step 0. The same gap in every batch (batched = alone), above that round-off for batches some metres wide,
# and its effect on the rebound (gap over peak overlap) ~2e-8 of v_n1 at grazing incidence
CLEARANCE = 1e-12


def typed(lines):
    """[(name, value)] of a script's contact lines: each material's numbers ("ball YOUNG_MODULUS") and the relation's
    (COEFFICIENT_OF_RESTITUTION, the frictions, the constitutive law), as Kratos names them."""
    import re
    out, material = [], ""
    for line in lines:
        opened = re.match(r'\s*"(\w+)": \{', line)
        if opened:
            material = opened.group(1) + " "
        elif line.startswith("RELATION"):
            material = ""
        out += [(material + name, value.strip('"')) for name, value in
                re.findall(r'"([A-Z_]+)": ("[^"]*"|[^,}\s]+)', line)]
    return out


def clearance(scene, size):
    """How far above touching a sphere starts: Scene.gap, else CLEARANCE of the contact's size."""
    return scene.gap if scene.gap > 0.0 else CLEARANCE * size


def wall_spheres(scene, spec):
    """Every impact's sphere touching the plane z = 0 (CLEARANCE) or Scene.gap above it, 4R apart, each over its own
    square of the wall (3R wide), both widened by the approach's drift; the materials of the sphere and the wall."""
    radius = scene.radius
    gap, drift = clearance(scene, radius), approach_drift(scene, spec.v_n0, spec.v_t0)
    spheres = [{"x": i * 4.0 * radius + 2.0 * i * drift, "z": radius + gap, "radius": radius, "vx": float(vt),
                "vz": -float(vn), "omegay": float(w), "material": "ball", "fixed": False}
               for i, (vn, vt, w) in enumerate(zip(spec.v_n0, spec.v_t0, spec.omega0))]
    wall = {"same": (scene.E, scene.nu), "rigid": (scene.E * RIGID_SCALE, scene.nu),
            "other": (scene.wall_E, scene.wall_nu)}[scene.wall]
    materials = [{"name": "ball", "E": scene.E, "nu": scene.nu, "rho": scene.rho},
                 {"name": "wall", "E": wall[0], "nu": wall[1], "rho": scene.rho}]
    return spheres, materials, 1.5 * radius + drift


def pair_spheres(scene, spec):
    """Every impact a projectile touching its target below it (CLEARANCE) or Scene.gap above touching (the target at
    rest, its own spin, fixed or free), their relative velocity the impact's; omega0 is the equivalent spin, so the
    projectile's own is (R* omega0 - R2 omega2)/R1."""
    projectile, target = scene.spheres
    r1, r2, r_star = projectile.radius, target.radius, scene.contact.radius
    spheres, gap = [], clearance(scene, r1 + r2)
    drift = approach_drift(scene, spec.v_n0, spec.v_t0)
    for i, (vn, vt, w) in enumerate(zip(spec.v_n0, spec.v_t0, spec.omega0)):
        x = i * 3.0 * (r1 + r2) + i * drift
        spheres.append({"x": x, "z": r1 + r2 + gap, "radius": r1, "vx": float(vt), "vz": -float(vn),
                        "omegay": (r_star * float(w) - r2 * target.omega) / r1, "material": "ball", "fixed": False})
        spheres.append({"x": x, "z": 0.0, "radius": r2, "vx": 0.0, "vz": 0.0, "omegay": target.omega,
                        "material": "target", "fixed": target.fixed})
    materials = [{"name": "ball", "E": projectile.E, "nu": projectile.nu, "rho": projectile.rho},
                 {"name": "target", "E": target.E, "nu": target.nu, "rho": target.rho}]
    return spheres, materials, None


def script(law, scene, spec, observe=False, own=None):
    """The script text of a run's spec (RunSpec; validated numbers and fixed words only, see
    harness.infra.render); `own`, a user's own input (its law, E, nu, e and mu), for every material and the relation."""
    target = "sphere" if scene.spheres else "wall"
    place = pair_spheres if scene.spheres else wall_spheres
    spheres, materials, wall = place(scene, spec)
    counterpart, e_n, mu = COUNTERPARTS[law.name], spec.e_n, scene.mu
    if own:
        materials = [dict(m, E=own["E"], nu=own["nu"]) for m in materials]
        counterpart, e_n, mu = own["counterpart"], own["e_n"], own["mu"]
    return render(TEMPLATES, "batch.py.j2", harness_version=__version__, law=law.name,
                  counterpart=counterpart, e_n=e_n, mu=mu, impacts=spec.impacts, target=target,
                  **stepping(scene, spec), observe=bool(observe), spheres=spheres,
                  materials=materials, wall=wall)


def run_inputs(python, count, timeout_s, workdir):
    """Each script batch<k>/harness_kratos.py in its own process of the Kratos python, one after the other, in its
    own directory: each batch's wall seconds, or the EngineFailure that ended it (with its log's tail)."""
    walls = []
    for k in range(count):
        directory = os.path.join(workdir, f"batch{k}")
        try:
            walls.append(run_engine([python, INPUT], directory, timeout_s).wall_s)
        except EngineFailure as exc:
            if exc.timed_out:
                raise
            walls.append(exc)
    return walls


def read_json(path, what):
    try:
        with open(path) as handle:
            data = json.load(handle)
    except OSError:
        raise EngineFailure(f"Kratos wrote no {what}") from None
    except ValueError:
        raise EngineFailure(f"Kratos {what} is malformed") from None
    if not isinstance(data, dict) or data.get("complete") is not True:
        raise EngineFailure(f"Kratos {what} is truncated")
    return data


def read_batch(scene, spec, directory, observe=False):
    """Rebound velocities and separation of one run's spec from result.json (per sphere x, z, vx, vz, omega_y), and
    what observe mode saw; a failure carries the tail of the batch's own log."""
    try:
        return read_outputs(scene, spec, directory, observe)
    except EngineFailure as exc:
        raise EngineFailure(str(exc), exc.log_tail or read_tail(os.path.join(directory, "engine.log"))) from None


def read_outputs(scene, spec, directory, observe):
    data = read_json(os.path.join(directory, RESULT), "result file")
    per_impact = 2 if scene.spheres else 1
    try:
        rows = np.array(data["rows"], dtype=float)
    except (KeyError, TypeError, ValueError):
        raise EngineFailure("Kratos result file is malformed") from None
    if rows.shape != (per_impact * spec.impacts, 5):
        raise EngineFailure(f"Kratos result file holds {counted(len(rows), 'sphere')} for {per_impact * spec.impacts}")
    final = pair_rebound(rows, scene) if scene.spheres else rebound(rows[:, 1:], scene.radius)
    if observe:
        final.update(read_observation(os.path.join(directory, OBSERVED), spec))
    if scene.at_times:
        final["states"] = read_states(os.path.join(directory, STATES), scene, spec)
    return final


def read_states(path, scene, spec):
    """The states at Scene.at_times (engines/start.py's array): overlap from the positions, the sphere's total force
    (TOTAL_FORCES: its one contact's, Kratos keeps no per-contact force) along the normal and tangent, and the
    velocities and spin as the results table gives them (the symplectic Euler's velocity the step ends with)."""
    data = read_json(path, "states file")
    width = 15 if scene.spheres else 10
    try:
        rows = np.array(data["rows"], dtype=float).reshape(-1, width)
    except (KeyError, TypeError, ValueError):
        raise EngineFailure("Kratos states file is malformed") from None
    bodies = rows[:, 5:]                    # x, z, vx, vz, omega_y of the sphere (and of its target)
    moved = pair_rebound(bodies.reshape(-1, 5), scene) if scene.spheres else rebound(bodies[:, 1:], scene.radius)
    values = np.column_stack([rows[:, :5], moved["v_n1"], moved["v_t1"], moved["omega1"]])
    return states_array(values, spec.impacts, scene, spec.dt, "Kratos")


def read_observation(path, spec):
    """Per impact: contact time in whole steps (first to last step with overlap > 0, dt each), peak normal force and
    peak overlap over the first contact."""
    data = read_json(path, "observe file")
    try:
        first, last, force, overlap = (np.array(data[key], dtype=float) for key in ("first", "last", "force",
                                                                                   "overlap"))
    except (KeyError, TypeError, ValueError):
        raise EngineFailure("Kratos observe file is malformed") from None
    if any(len(a) != spec.impacts for a in (first, last, force, overlap)) or np.any(first < 0):
        raise EngineFailure("Kratos observed no contact for some impacts")
    return {"t_contact": (last - first + 1) * spec.dt, "f_n_max": force, "overlap_max": overlap}


def render_batch(paper_law, scene, spec, options=None, observe=False):
    """The script text of one run's spec, as Engine.run_batch would run it (with a user's own input, the option
    `input` (harness.engines.user_inputs), its variables as given)."""
    from ..user_inputs import INPUT_OPTION, parse
    text = dict(options or {}).get(INPUT_OPTION)
    own = parse("kratos", text).deck_values() if text is not None else None
    return script(paper_law, scene, spec, observe, own)
