"""YADE's input and output: one batched script per (law, e_n), every impact its own sphere against one wall, run
as a Python module in its own directory, and its result files read back (docs/yade-dialect.md)."""
import os
from pathlib import Path

import numpy as np

from ...infra.version import __version__
from ...infra.render import render
from ...infra.wording import counted
from ..dumps import pair_rebound, rebound
from ..runner import EngineFailure, ended_lines, remove_engine_tmpdir, run_engine
from ..start import approach_drift, stepping, states_array
from .dialect import COUNTERPARTS
from .flavours import environment, python

TEMPLATES = Path(__file__).resolve().parent / "templates"

OBSERVE_FILE = "observe.txt"    # observe mode: per sphere, first and last real step, peak normal force and overlap
STATES_FILE = "states.txt"      # Scene.at_times: per sphere and named time, its state after the named step
RIGID_E = 1e100     # a rigid wall's young: (1 - nu^2)/E vanishes beside the sphere's, and YADE's E_a E_b stays finite
PAIR_COLUMNS = 11   # a pair's result row: index, then x, z, vx, vz, omega_y of the projectile and of its target


def viscel_contact_time(law, scene, e_n):
    """tc for ViscElMat such that its k_n = (m/2)(pi^2 + ln^2 e)/tc^2 (reduced mass m/2 against a wall) equals the
    harness linear spring's k_n: tc = sqrt((pi^2 + ln^2 e) (m/2) / k_n)."""
    import math
    k = law.normal.parameters(scene.contact, e_n, scene.speed).values[0]
    return math.sqrt((math.pi ** 2 + math.log(e_n) ** 2) * 0.5 * scene.contact.mass / k)


def script(law, scene, spec, linear="viscel", observe=False):
    """Render the batched script of a run's spec (RunSpec; validated numbers and fixed words only, see
    harness.infra.render); `observe` adds the per-step PyRunner that writes OBSERVE_FILE."""
    import math
    e_n, v_n0, v_t0, omega0 = spec.e_n, spec.v_n0, spec.v_t0, spec.omega0
    radius = scene.radius
    spheres = [{"x": i * 4.0 * radius, "vx": float(vt), "vz": -float(vn), "omegay": float(w)}
               for i, (vn, vt, w) in enumerate(zip(v_n0, v_t0, omega0))]
    common = dict(harness_version=__version__, law=law.name, law2=COUNTERPARTS[law.name], e_n=e_n, rho=scene.rho,
                  friction_angle=math.atan(scene.mu), radius=radius, height=radius + scene.gap, spheres=spheres,
                  ig2="Ig2_Wall_Sphere_ScGeom", hertzian=True, **stepping(scene, spec), observe=bool(observe),
                  other=None, target=None)
    if scene.spheres:
        return pair_script(scene, e_n, v_n0, v_t0, omega0, common)
    if scene.wall != "same":
        if law.name != "hertz-mindlin":
            raise EngineFailure(f"YADE runs {law.name} against a wall of the sphere's own material only")
        common["other"] = ({"young": RIGID_E, "poisson": 0.0, "rho": scene.rho} if scene.wall == "rigid" else
                           {"young": scene.wall_E, "poisson": scene.wall_nu, "rho": scene.rho})
    if law.name == "walton-braun":
        from ...submodels.normal.luding_incremental import LudingIncremental
        luding = LudingIncremental()
        k1, kp, d_p_max, _ = luding.parameters(scene.contact, e_n, scene.speed).values
        if not kp > k1:             # YADE throws 'k1 have to be less as kp!' and the interpreter aborts (signal 6)
            raise EngineFailure(f"YADE's Luding law needs kp > k1, i.e. e_n < 1; e_n = {e_n:g} was not run")
        big = LudingIncremental.HUGE * radius
        spacing = 2.0 * math.sqrt(2.0 * big * radius) + approach_drift(scene, v_n0, v_t0)  # a neighbour's: 4R below
        for i, s in enumerate(spheres):
            s["x"] = i * spacing
        return render(TEMPLATES, "batch.py.j2", **{**common, "ig2": "Ig2_Sphere_Sphere_ScGeom", "hertzian": False},
                      material="LudingMat", k1=k1, kp=kp, ks=2.0 / 7.0 * k1,
                      phi_f=luding.plasticity_depth(k1, kp, d_p_max, scene.contact), huge_radius=big,
                      ip2="Ip2_LudingMat_LudingMat_LudingPhys", ip2_args=[])
    if law.name == "linear-spring-dashpot" and linear == "cundall-strack":
        return render(TEMPLATES, "batch.py.j2", **{**common, "law2": "Law2_ScGeom_FrictPhys_CundallStrack",
                                             "hertzian": False}, material="FrictMat", young=scene.E, poisson=scene.nu,
                      ip2="Ip2_FrictMat_FrictMat_FrictPhys", ip2_args=[])
    if law.name == "linear-spring-dashpot":
        return render(TEMPLATES, "batch.py.j2", **common, material="ViscElMat", tc=viscel_contact_time(law, scene, e_n),
                      en=e_n, et=e_n, ip2="Ip2_ViscElMat_ViscElMat_ViscElPhys", ip2_args=[])
    return render(TEMPLATES, "batch.py.j2", **common, material="FrictMat", young=scene.E, poisson=scene.nu,
                  ip2="Ip2_FrictMat_FrictMat_MindlinPhys", ip2_args=[("en", e_n), ("es", e_n)])


def typed(lines):
    """[(name, value)] of a script's contact lines: the material's class and each number it or the physics functor
    takes (as YADE names them), and the functors."""
    import re
    out = []
    for line in lines:
        out += [("material", m) for m in re.findall(r"= (\w+Mat)\(", line)]
        out += [(name, value) for name, value in re.findall(r"(\w+)=Real\(\"([^\"]+)\"\)", line)]
        out += [(name.split("_")[0], name) for name in re.findall(r"\b((?:Ip2|Law2)_\w+)\(", line)]
    return out


def pair_script(scene, e_n, v_n0, v_t0, omega0, common):
    """The batched script of two-sphere impacts (Mindlin): every projectile touching its own target below it (at
    rest, fixed or free, its own material and spin), their relative velocity the impact's; omega0 is the equivalent
    spin, so the projectile's own is (R* omega0 - R2 omega2)/R1."""
    projectile, target = scene.spheres
    r1, r2, r_star = projectile.radius, target.radius, scene.contact.radius
    drift = approach_drift(scene, v_n0, v_t0)
    spheres = [{"x": i * 3.0 * (r1 + r2) + i * drift, "vx": float(vt), "vz": -float(vn),
                "omegay": (r_star * float(w) - r2 * target.omega) / r1}
               for i, (vn, vt, w) in enumerate(zip(v_n0, v_t0, omega0))]
    return render(TEMPLATES, "batch.py.j2", **{
        **common, "radius": r1, "height": r1 + r2 + scene.gap, "spheres": spheres, "rho": projectile.rho,
        "ig2": "Ig2_Sphere_Sphere_ScGeom", "hertzian": False,
        "other": {"young": target.E, "poisson": target.nu, "rho": target.rho},
        "target": {"radius": r2, "fixed": target.fixed, "omega": target.omega}},
        material="FrictMat", young=projectile.E, poisson=projectile.nu, ip2="Ip2_FrictMat_FrictMat_MindlinPhys",
        ip2_args=[("en", e_n), ("es", e_n)])


def read_result(path, n_spheres, what="result file", columns=5):
    """(left, vx, vz, wy) per sphere (or the four columns of the observe file, or a pair's ten: see PAIR_COLUMNS);
    EngineFailure when missing or truncated."""
    lines = ended_lines(path, "YADE", what)
    try:
        rows = np.array([[float(x) for x in line.split()] for line in lines])
    except ValueError:
        raise EngineFailure(f"YADE {what} is malformed") from None
    if len(rows) > n_spheres:
        raise EngineFailure(f"YADE {what} holds {counted(len(rows), 'row')} for {counted(n_spheres, 'sphere')}")
    if rows.shape != (n_spheres, columns) or not np.array_equal(rows[:, 0], np.arange(n_spheres)):
        raise EngineFailure(f"YADE {what} is truncated: {len(rows)} of {n_spheres} spheres")
    return rows[:, 1:]


def run_script(text, n_spheres, timeout_s, workdir, precision="double"):
    """Run one script in workdir under Debian's python3.11 with the flavour's module path; (rows, wall, log)."""
    with open(os.path.join(workdir, "harness_yade.py"), "w") as handle:
        handle.write(text)
    try:
        done = run_engine([python(), "harness_yade.py"], workdir, timeout_s, env=environment(precision),
                          private_tmp=True)            # YADE's /tmp/yade-XXXXXX made inside workdir
    finally:
        remove_engine_tmpdir(workdir)
    try:
        return read_result(os.path.join(workdir, "result.txt"), n_spheres), done.wall_s, done.log_tail
    except EngineFailure as exc:
        raise EngineFailure(str(exc), exc.log_tail or done.log_tail) from None


def run_inputs(precision, count, timeout_s, workdir):
    """The scripts batch<k>/harness_yade.py in one interpreter, one start-up for all (O.reset() between them): each
    batch's wall seconds with the start-up shared equally, or the EngineFailure that ended it."""
    with open(os.path.join(workdir, "harness_driver.py"), "w") as handle:
        handle.write(render(TEMPLATES, "driver.py.j2", harness_version=__version__, count=count))
    try:
        done = run_engine([python(), "harness_driver.py"], workdir, timeout_s, env=environment(precision),
                          private_tmp=True)            # YADE's /tmp/yade-XXXXXX made inside workdir
    finally:
        remove_engine_tmpdir(workdir)
    walls = []
    for k in range(count):
        try:
            with open(os.path.join(workdir, f"batch{k}", "time.txt")) as handle:
                seconds, status = handle.read().split()
            walls.append(float(seconds) if status == "ok" else
                         EngineFailure(f"YADE stopped in batch {k + 1} of {count} with an error", done.log_tail))
        except (OSError, ValueError):
            walls.append(EngineFailure(f"YADE did not finish batch {k + 1} of {count}", done.log_tail))
    startup = max(0.0, done.wall_s - sum(w for w in walls if not isinstance(w, EngineFailure))) / count
    return [w if isinstance(w, EngineFailure) else w + startup for w in walls]


def read_batch(scene, spec, directory, observe=False):
    """The final state of one run's spec (RunSpec) run in `directory` (and what observe mode saw)."""
    n = spec.impacts
    if scene.spheres:
        rows = read_result(os.path.join(directory, "result.txt"), n, columns=PAIR_COLUMNS)
        final = pair_rebound(rows.reshape(2 * n, 5), scene)
    else:
        final = final_of(read_result(os.path.join(directory, "result.txt"), n))
    if observe:
        final.update(read_observation(os.path.join(directory, OBSERVE_FILE), n, spec.dt))
    if scene.at_times:
        final["states"] = read_states(os.path.join(directory, STATES_FILE), scene, spec)
    return final


def read_states(path, scene, spec):
    """The states at Scene.at_times (engines/start.py's array): overlap, forces along the normal and tangent, and
    the velocities and spin as the results table gives them (the half-step velocity the step ends with, a pair's
    relative one); EngineFailure when missing, truncated or short of a state."""
    lines = ended_lines(path, "YADE", "states file")
    widths = (15,) if scene.spheres else (10, 15)  # a target's (or a stand-in sphere's) x, z, vx, vz, omega_y follow
    try:
        rows = np.array([[float(x) for x in line.split()] for line in lines], dtype=float)
    except ValueError:
        raise EngineFailure("YADE states file is malformed") from None
    if rows.ndim != 2 or rows.shape[1] not in widths:
        raise EngineFailure("YADE states file is malformed")
    bodies = rows[:, 5:]                    # x, z, vx, vz, omega_y of the sphere (and of its target)
    moved = pair_rebound(bodies.reshape(-1, 5), scene) if scene.spheres else rebound(bodies[:, 1:5], scene.radius)
    values = np.column_stack([rows[:, :5], moved["v_n1"], moved["v_t1"], moved["omega1"]])
    return states_array(values, spec.impacts, scene, spec.dt, "YADE")


def final_of(rows, log_tail=""):
    """The velocities and separation of the result rows."""
    left, vx, vz, wy = rows.T
    if not np.all(np.isfinite(rows)):
        raise EngineFailure("YADE returned non-finite velocities", log_tail)
    return {"v_n1": vz, "v_t1": vx, "omega1": wy, "separated": left > 0}


def read_observation(path, n_spheres, dt):
    """Per sphere: contact time in whole steps (first real step to the first step with the interaction gone, dt
    each), peak normal force and peak overlap over the first contact; EngineFailure when missing or truncated."""
    rows = read_result(path, n_spheres, "observe file")
    first, last, force, overlap = rows.T
    if np.any(first < 0) or not np.all(np.isfinite(rows)):
        raise EngineFailure("YADE observed no contact for some spheres")
    return {"t_contact": (last - first + 1) * dt, "f_n_max": force, "overlap_max": overlap}


def render_batch(paper_law, scene, spec, options=None, observe=False):
    """The script text of one run's spec (solver/resolution.py's RunSpec), as Engine.run_batch would run it (with a
    user's own input, the option `input` (engines/user_inputs.py), its material and functors verbatim)."""
    from ..user_inputs import INPUT_OPTION, parse
    options = dict(options or {})
    text = options.pop(INPUT_OPTION, None)
    if text is not None:
        return input_script(scene, spec, parse("yade", text).deck_values(), observe)
    return script(paper_law, scene, spec, options.get("linear", "viscel"), observe)


def input_script(scene, spec, own, observe=False):
    """The batched script of a user's own input (`own`: its material, functors and their values), the sphere and its
    wall or target sphere of that one material."""
    e_n, v_n0, v_t0, omega0 = spec.e_n, spec.v_n0, spec.v_t0, spec.omega0
    radius = scene.radius
    spheres = [{"x": i * 4.0 * radius, "vx": float(vt), "vz": -float(vn), "omegay": float(w)}
               for i, (vn, vt, w) in enumerate(zip(v_n0, v_t0, omega0))]
    common = dict(harness_version=__version__, law="input", e_n=e_n, rho=scene.rho, radius=radius,
                  height=radius + scene.gap, spheres=spheres, ig2="Ig2_Wall_Sphere_ScGeom", hertzian=True,
                  **stepping(scene, spec), observe=bool(observe), other=None, target=None, **own)
    if scene.spheres:
        projectile, target = scene.spheres
        r1, r2, r_star = projectile.radius, target.radius, scene.contact.radius
        drift = approach_drift(scene, v_n0, v_t0)
        common.update(radius=r1, height=r1 + r2 + scene.gap, rho=projectile.rho, ig2="Ig2_Sphere_Sphere_ScGeom",
                      hertzian=False,
                      target={"radius": r2, "fixed": target.fixed, "omega": target.omega},
                      spheres=[{"x": i * 3.0 * (r1 + r2) + i * drift, "vx": float(vt), "vz": -float(vn),
                                "omegay": (r_star * float(w) - r2 * target.omega) / r1}
                               for i, (vn, vt, w) in enumerate(zip(v_n0, v_t0, omega0))])
    return render(TEMPLATES, "batch.py.j2", **common)
