"""LIGGGHTS 3.8.0 adapter: one batched deck per (law, e_n), every impact its own sphere against a wall/gran plane."""
import math
import os
import re
import shutil
import subprocess
from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from .. import __version__
from ..render import render
from ..errors import UserError
from .runner import EngineFailure, run_engine

NAME = "liggghts"
INPUT_SUFFIX = ".in"
BINARY_VARIABLE = "HARNESS_LIGGGHTS"     # path of another liggghts binary (a custom build, or a test's fake)
MODELS = {                      # harness law -> LIGGGHTS normal model (MODELS 5)
    "linear-spring-dashpot": "hooke",
    "hertz-mindlin": "hertz",
    "walton-braun": "hooke/hysteresis",
    "thornton": "thornton_ning",
}
MIN_RESTITUTION = 0.05          # LIGGGHTS refuses coefficientRestitution <= 0.05 and poissonsRatio < 0; youngsModulus
                                # < 5e6 or > 1e9 only with soft_particles/hard_particles yes (sanity checks only)
OBSERVE_DUMP = "observe.dump"   # observe mode: `id z fz` of every sphere in contact, every step
DUMP_HEADER_LINES = 9           # TIMESTEP, NUMBER OF ATOMS, BOX BOUNDS (3 lines) and ATOMS items


@dataclass(frozen=True)
class Deck:
    """A rendered deck with the per-impact layout needed to read its dump back."""
    text: str
    model: str
    n_atoms: int


COMMON = {"end": "tension", "integrator": "velocity-verlet", "lever": "0.5"}
DIALECTS = {                    # sub-models that make the paper law compute what LIGGGHTS computes (MODELS 5)
    "linear-spring-dashpot": {**COMMON, "damping": "linear:tension", "tangential": "linear:1",
                              "tangential-damping": "normal-coefficient"},
    "hertz-mindlin": {**COMMON, "damping": "tsuji:tension", "tangential": "mindlin:total",
                      "tangential-damping": "normal-ratio"},
    "walton-braun": {**COMMON, "end": "no-tension", "normal": "liggghts-hysteresis", "tangential": "linear:1",
                     "tangential-damping": "none"},
    "thornton": {**COMMON, "end": "no-tension", "normal": "liggghts-thornton-ning", "tangential": "mindlin:total",
                 "tangential-damping": "reversed-beta"},
}
OPTIONS = {                     # option -> allowed values, default first, and the models that honour it
    "limitForce": (("off", "on"), ("hooke", "hertz")),
    "tangential_damping": (("on", "off"), ("hooke", "hertz", "hooke/hysteresis")),
    "ktToKnUser": (("off", "on"), ("hooke",)),
    "tangential": (("history", "no_history"), ("hooke", "hertz")),
}
KT_TO_KN_USER = "0.285714286"   # the literal LIGGGHTS multiplies by, not exactly 2/7


def check_options(law_name, options):
    """Validate --liggghts-option values; one clear line for a bad one."""
    for key, value in options.items():
        if key not in OPTIONS:
            raise UserError(f"unknown LIGGGHTS option {key!r}; known: {', '.join(OPTIONS)}")
        values, models = OPTIONS[key]
        if value not in values:
            raise UserError(f"LIGGGHTS option {key} takes {' or '.join(values)}, got {value!r}")
        if key == "tangential" and value != "history" and MODELS.get(law_name) not in models:
            raise UserError(f"tangential no_history is offered with hooke and hertz only, not {MODELS.get(law_name)}")


def dialect(law_name, options=None):
    """The law as LIGGGHTS 3.8.0 computes it (MODELS 5): velocity Verlet with half-step velocities in the forces,
    lever R - d/2, setup force at first touch, total-displacement tangential spring with its dashpot added after the
    Coulomb test; options change what the model honours (limitForce clips; tangential_damping off removes c_t;
    ktToKnUser gives k_t = 0.285714286 k_n; no_history replaces the spring by capped viscous friction)."""
    from ..laws import compose
    from ..laws.law import replace_submodels
    options = dict(options or {})
    check_options(law_name, options)
    overrides = dict(DIALECTS[law_name])
    honoured = {key: value for key, value in options.items() if MODELS[law_name] in OPTIONS[key][1]}
    if honoured.get("limitForce") == "on":
        overrides["end"] = "no-tension"
    if honoured.get("tangential_damping") == "off":
        overrides["tangential-damping"] = "none"
    if honoured.get("ktToKnUser") == "on":
        overrides["tangential"] = f"linear:{KT_TO_KN_USER}"
    if honoured.get("tangential") == "no_history":
        overrides["tangential"] = "viscous:linear" if MODELS[law_name] == "hooke" else "viscous:mindlin"
    return replace_submodels(compose(law_name), overrides, "liggghts")


def binary():
    return os.environ.get(BINARY_VARIABLE, "liggghts")


def available():
    return shutil.which(binary()) is not None


def version():
    return _version(binary())


@lru_cache(maxsize=None)
def _version(path):
    """'3.8.0' from the banner the binary prints."""
    try:
        out = subprocess.run([path, "-h"], capture_output=True, text=True, timeout=30, stdin=subprocess.DEVNULL)
    except (OSError, subprocess.TimeoutExpired):
        return "unknown"
    match = re.search(r"LIGGGHTS-PUBLIC ([0-9.]+)", out.stdout + out.stderr)
    return match.group(1) if match else "unknown"


def supports(law_name):
    return law_name in MODELS and law_name in DIALECTS


def law_stiffness(scene):
    """k_n of LIGGGHTS hooke: 16/15 sqrt(R) E* (15 m V_c^2/(16 sqrt(R) E*))^1/5 with V_c = the scene speed."""
    from ..submodels.calibration import hertz_equivalent_stiffness
    c = scene.contact
    return hertz_equivalent_stiffness(c.E_star, c.radius, c.mass, scene.speed)


def characteristic_velocity(k_n, contact):
    """V_c at which LIGGGHTS hooke's k_n = 16/15 sqrt(R) E* (15 m V_c^2/(16 sqrt(R) E*))^1/5 equals the law's k_n."""
    base = 16.0 / 15.0 * math.sqrt(contact.radius) * contact.E_star
    return math.sqrt((k_n / base) ** 5 * 16.0 * math.sqrt(contact.radius) * contact.E_star / (15.0 * contact.mass))


def settings(law, scene, e_n, options=None):
    """Model, tangential model, options and extra global properties that express `law` at e_n in LIGGGHTS."""
    model = MODELS[law.name]
    options = dict(options or {})
    tangential = options.pop("tangential", "history")
    properties = []
    restitution = e_n
    if model == "hooke":
        k_n = law.normal.parameters(scene.contact, e_n, scene.speed).values[0]
        properties.append(("characteristicVelocity", "scalar", characteristic_velocity(k_n, scene.contact)))
    if model == "hooke/hysteresis":
        properties.append(("characteristicVelocity", "scalar", scene.speed))
    if model == "hooke/hysteresis":
        restitution = 1.0                               # no viscous part: all dissipation by hysteresis
        from ..submodels.normal.liggghts_hysteresis import LudingHysteresis
        k1 = law_stiffness(scene)
        k2max, d_lim = LudingHysteresis.stiffness_and_limit(k1, scene.contact, e_n, scene.speed)
        depth = d_lim * (k2max - k1) / (k2max * 2 * scene.radius)
        if depth == 0.0:        # e_n = 1: LIGGGHTS' d_lim = k2max/(k2max - k1) phi 2R would be 0/0 and its force NaN,
            depth = d_lim / (2 * scene.radius)      # which it drops (the sphere passes through the wall); any phi > 0
                                                    # makes d_lim infinite and k2 = k1, the elastic limit
        properties += [("coefficientMaxElasticStiffness", "peratomtypepair", k2max / k1),
                       ("coefficientAdhesionStiffness", "peratomtypepair", 0.0),
                       ("coefficientPlasticityDepth", "peratomtypepair", depth)]
    if model == "thornton_ning":
        p_y = law.normal.yield_pressure(scene.contact, e_n, scene.speed)
        properties += [("coefficientYieldRatio", "peratomtype", math.pi * p_y / (2.0 * scene.contact.E_star)),
                       ("surfaceEnergy", "peratomtypepair", 0.0)]
    return model, tangential, sorted(options.items()), properties, restitution


def deck(law, scene, e_n, dt, v_n0, v_t0, omega0, steps_per_contact, max_steps, options=None, observe=False):
    """Render the batched deck (validated numbers and fixed words only; see harness.render); `observe` adds the
    per-step contact dump (OBSERVE_DUMP)."""
    model, tangential, options, properties, restitution = settings(law, scene, e_n, options)
    if not MIN_RESTITUTION < restitution <= 1.0:
        raise EngineFailure(f"LIGGGHTS accepts coefficientRestitution in (0.05, 1] only; e_n = {e_n:g} was not run")
    if scene.nu < 0.0:
        raise EngineFailure(f"LIGGGHTS accepts poissonsRatio in [0, 0.5] only; nu = {scene.nu:g} was not run")
    radius = scene.radius
    spacing = 4.0 * radius
    atoms = [{"x": i * spacing, "vx": float(vt), "vz": -float(vn), "omegay": float(w)}
             for i, (vn, vt, w) in enumerate(zip(v_n0, v_t0, omega0))]
    chunk = max(10, int(steps_per_contact // 10))
    text = render("liggghts/batch.in.j2", harness_version=__version__, law=law.name, model=model, e_n=restitution,
                  atoms=atoms, x_lo=-2.0 * radius, x_hi=len(atoms) * spacing, box_half=2.0 * radius,
                  z_lo=-radius, z_hi=4.0 * radius, skin=0.5 * radius, E=scene.E, nu=scene.nu, mu=scene.mu,
                  properties=properties, tangential=tangential, options=options, dt=dt, radius=radius,
                  rho=scene.rho, chunk=chunk, max_chunks=max(1, max_steps // chunk + 1), observe=bool(observe))
    return Deck(text, model, len(atoms))


def read_dump(path, n_atoms):
    """Final (z, vx, vz, omegay) per atom id from the dump; EngineFailure when it is missing or truncated."""
    try:
        with open(path) as handle:
            lines = handle.read().splitlines()
    except OSError:
        raise EngineFailure("LIGGGHTS wrote no final dump") from None
    try:
        start = next(i for i, line in enumerate(lines) if line.startswith("ITEM: ATOMS")) + 1
        rows = np.array([[float(x) for x in line.split()] for line in lines[start:] if line.strip()])
    except (StopIteration, ValueError):
        raise EngineFailure("LIGGGHTS final dump is malformed") from None
    if rows.ndim != 2 or rows.shape != (n_atoms, 5):
        raise EngineFailure(f"LIGGGHTS final dump is truncated: {len(rows)} of {n_atoms} spheres")
    rows = rows[np.argsort(rows[:, 0])]
    if not np.array_equal(rows[:, 0], np.arange(1, n_atoms + 1)):
        raise EngineFailure("LIGGGHTS final dump lacks some sphere ids")
    return rows[:, 1:]


def dump_rows(path):
    """(step, atom index, z, fz) of every row of the observe dump, one array each; EngineFailure when missing or
    malformed."""
    try:
        with open(path) as handle:
            frames = handle.read().split("ITEM: TIMESTEP\n")
    except OSError:
        raise EngineFailure("LIGGGHTS wrote no observe dump") from None
    try:
        heads = [frame.split("\n", DUMP_HEADER_LINES - 1) for frame in frames[1:]]
        if frames[0] or any(not head[-2].startswith("ITEM: ATOMS") for head in heads):
            raise ValueError("not a dump of `id z fz` frames")
        counts = np.array([int(head[2]) for head in heads], dtype=int)
        step = np.repeat([int(head[0]) for head in heads], counts).astype(int)
        rows = np.array(" ".join(head[-1] for head in heads).split(), dtype=float).reshape(len(step), 3)
    except (IndexError, ValueError):
        raise EngineFailure("LIGGGHTS observe dump is malformed") from None
    return step, rows[:, 0].astype(int) - 1, rows[:, 1], rows[:, 2]


def first_contact(step, atom):
    """Mask of the rows in each atom's first run of consecutive steps (a repeated frame or a later contact is not)."""
    order = np.lexsort((step, atom))
    s, a = step[order], atom[order]
    new_atom = np.r_[True, a[1:] != a[:-1]]
    gap = np.diff(s, prepend=0)
    breaks = np.cumsum(~new_atom & (gap > 1))
    run = breaks - np.maximum.accumulate(np.where(new_atom, breaks, 0))      # contacts before this one, per atom
    mask = np.empty(len(step), dtype=bool)
    mask[order] = (run == 0) & (new_atom | (gap != 0))
    return mask


def read_observation(path, n_atoms, radius, dt):
    """Per atom: contact time in whole steps (first step in contact to the first step out, dt each), peak fz (the
    wall force: no gravity, no sphere-sphere contact) and peak overlap R - z, over its first contact."""
    step, atom, z, fz = dump_rows(path)
    if np.any((atom < 0) | (atom >= n_atoms)) or len(np.unique(atom)) != n_atoms:
        raise EngineFailure("LIGGGHTS observe dump lacks some sphere ids")
    keep = first_contact(step, atom)
    step, atom, z, fz = step[keep], atom[keep], z[keep], fz[keep]
    first, last = np.full(n_atoms, np.iinfo(int).max), np.full(n_atoms, -1)
    force, overlap = np.full(n_atoms, -np.inf), np.full(n_atoms, -np.inf)
    np.minimum.at(first, atom, step)
    np.maximum.at(last, atom, step)
    np.maximum.at(force, atom, fz)
    np.maximum.at(overlap, atom, radius - z)
    return {"t_contact": (last - first + 1) * dt, "f_n_max": force, "overlap_max": overlap}


def run_deck(text, n_atoms, timeout_s, workdir):
    """Run one deck in workdir; returns (final state per atom, wall seconds, log tail)."""
    with open(os.path.join(workdir, "in.harness"), "w") as handle:
        handle.write(text)
    done = run_engine([binary(), "-in", "in.harness", "-log", "none", "-echo", "none"], workdir, timeout_s,
                      env={**os.environ, "OMP_NUM_THREADS": "1"})
    return read_dump(os.path.join(workdir, "final.dump"), n_atoms), done.wall_s, done.log_tail


def run_batch(paper_law, scene, batch, max_steps, timeout_s, workdir, options=None, observe=False):
    """One batch (one e_n) in LIGGGHTS: final v_n1, v_t1, omega1 per impact and whether each sphere separated;
    with `observe` also t_contact (a whole number of steps), f_n_max and overlap_max (see read_observation)."""
    text = render_batch(paper_law, scene, batch, max_steps, options, observe)
    state, wall, log_tail = run_deck(text, len(batch.v_n0), timeout_s, workdir)
    z, vx, vz, omegay = state.T
    if not np.all(np.isfinite(state)):
        raise EngineFailure("LIGGGHTS returned non-finite velocities", log_tail)
    final = {"v_n1": vz, "v_t1": vx, "omega1": omegay, "separated": z > scene.radius}
    if observe:
        final.update(read_observation(os.path.join(workdir, OBSERVE_DUMP), len(batch.v_n0), scene.radius, batch.dt))
    return final, wall, log_tail


def render_batch(paper_law, scene, batch, max_steps, options=None, observe=False):
    """The deck text for one batch, as run_batch would run it (for `harness render`)."""
    return deck(paper_law, scene, batch.e_n, batch.dt, batch.v_n0, batch.v_t0, batch.omega0,
                batch.steps_per_contact, max_steps, options, observe).text
