"""LIGGGHTS' input and output: one batched deck per (law, e_n), every impact its own sphere against a wall/gran plane,
run in its own directory, and its dumps read back (docs/liggghts-dialect.md)."""
import math
import os
from dataclasses import dataclass
from pathlib import Path

from ...infra.version import __version__
from ...infra.render import render
from ..dumps import read_final, read_observed, read_pair_batch, rebound
from ..executable import chosen
from ..runner import EngineFailure, run_engine
from ..states_deck import gap_and_states, read_states, refuse_between_spheres
from .dialect import COUNTERPARTS

BINARY_VARIABLE = "HARNESS_LIGGGHTS"     # path of another liggghts binary (a custom build, or a test's fake)

TEMPLATES = Path(__file__).resolve().parent / "templates"
MIN_RESTITUTION = 0.05          # LIGGGHTS refuses coefficientRestitution <= 0.05 and poissonsRatio < 0; youngsModulus
                                # < 5e6 or > 1e9 only with soft_particles/hard_particles yes (sanity checks only)
OBSERVE_DUMP = "observe.dump"   # observe mode: `id z fz` of every sphere in contact, every step


def binary():
    return chosen(BINARY_VARIABLE, "liggghts")


@dataclass(frozen=True)
class Deck:
    """A rendered deck with the per-impact layout needed to read its dump back."""
    text: str
    model: str
    n_atoms: int


def law_stiffness(scene):
    """k_n of LIGGGHTS hooke: 16/15 sqrt(R) E* (15 m V_c^2/(16 sqrt(R) E*))^1/5 with V_c = the scene speed."""
    from ...submodels.calibration import hertz_equivalent_stiffness
    c = scene.contact
    return hertz_equivalent_stiffness(c.E_star, c.radius, c.mass, scene.speed)


def characteristic_velocity(k_n, contact):
    """V_c at which LIGGGHTS hooke's k_n = 16/15 sqrt(R) E* (15 m V_c^2/(16 sqrt(R) E*))^1/5 equals the law's k_n."""
    base = 16.0 / 15.0 * math.sqrt(contact.radius) * contact.E_star
    return math.sqrt((k_n / base) ** 5 * 16.0 * math.sqrt(contact.radius) * contact.E_star / (15.0 * contact.mass))


def settings(law, scene, e_n, options=None):
    """Model, tangential model, options and extra global properties that express `law` at e_n in LIGGGHTS."""
    model = COUNTERPARTS[law.name]
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
        from ...submodels.normal.luding_peak import LudingPeak
        k1 = law_stiffness(scene)
        k2max, d_lim = LudingPeak.stiffness_and_limit(k1, scene.contact, e_n, scene.speed)
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


def typed(lines):
    """[(name, value)] of a deck's contact lines, named as LIGGGHTS' manual names them: each `fix property/global`
    (its values after the style, and after a peratomtypepair's type count) and the `pair_style gran` keywords."""
    out = []
    for line in lines:
        words = line.split()
        if "property/global" in words:
            at = words.index("property/global")
            name, style, values = words[at + 1], words[at + 2], words[at + 3:]
            shown = sorted(set(values[1:])) if style == "peratomtypepair" else values
            out.append((name, " ".join(shown)))
        elif words[:2] == ["pair_style", "gran"]:
            out += list(zip(words[2::2], words[3::2]))
    return out


RIGID_E = 1e300        # a rigid wall's youngsModulus: (1 - nu^2)/E vanishes beside the sphere's in double precision
OTHER_WALL_MODELS = ("hooke", "hertz", "hooke/hysteresis")   # per-type: E and nu (mixed as harness does), else per pair


def wall_material(scene, model):
    """[] for a wall of the sphere's own material (one atom type), else [(E, nu)] of the wall (atom type 2): LIGGGHTS
    mixes Y* = 1/((1 - nu1^2)/Y1 + (1 - nu2^2)/Y2) and G* = 1/(2(2 - nu1)(1 + nu1)/Y1 + 2(2 - nu2)(1 + nu2)/Y2), the
    scene's E* and G*; thornton_ning's per-type yield ratio is left to a later version."""
    if scene.wall == "same":
        return []
    if model not in OTHER_WALL_MODELS:
        raise EngineFailure(f"LIGGGHTS {model} runs against a wall of the sphere's own material only")
    return [(RIGID_E, 0.0)] if scene.wall == "rigid" else [(scene.wall_E, scene.wall_nu)]


def pair_deck(law, scene, spec, observe=False, own=None):
    """The batched deck of two-sphere impacts: pair k is atoms 2k-1 (the projectile, above) and 2k (its target, at
    rest, frozen when fixed), touching, their relative velocity the impact's, each of its own material; omega0 is the
    equivalent spin,
    so the projectile's own is (R* omega0 - R2 omega2)/R1."""
    refuse_between_spheres(scene, "LIGGGHTS")
    model, tangential, _, properties, restitution = settings(law, scene, spec.e_n, {}) if own is None else \
        (own["model"], own["tangential"], own["options"], own["properties"], own["e_n"])
    if own and own["options"]:
        raise EngineFailure("LIGGGHTS' pair decks take no setting of your input yet (limitForce, "
                            "tangential_damping, ktToKnUser)")
    if any(style not in ("scalar", "peratomtypepair") for _, style, _ in properties):
        raise EngineFailure(f"LIGGGHTS' pair decks take no per-type property of {model}")
    projectile, target = scene.spheres
    r1, r2, r_star = projectile.radius, target.radius, scene.contact.radius
    spacing = 3.0 * (r1 + r2)
    pairs = [{"x": i * spacing, "vx": float(vt), "vz": -float(vn),
              "omega1": (r_star * float(w) - r2 * target.omega) / r1}
             for i, (vn, vt, w) in enumerate(zip(spec.v_n0, spec.v_t0, spec.omega0))]
    big = max(r1, r2)
    text = render(TEMPLATES, "pair.in.j2", harness_version=__version__, law=law.name, model=model, e_n=restitution,
                  E1=own["E"][0] if own else projectile.E, E2=own["E"][0] if own else target.E,
                  nu1=own["nu"][0] if own else projectile.nu, nu2=own["nu"][0] if own else target.nu,
                  pairs=pairs, properties=properties,
                  x_lo=-2.0 * big, x_hi=len(pairs) * spacing, box_half=2.0 * big, z_lo=-2.0 * r2,
                  z_hi=2.0 * (r1 + r2) + 2.0 * r1, skin=0.5 * min(r1, r2), mu=own["mu"] if own else scene.mu,
                  tangential=tangential,
                  dt=spec.dt, centres=r1 + r2, r1=r1, r2=r2, rho1=projectile.rho, rho2=target.rho,
                  omega2=target.omega, fixed=target.fixed, chunk=spec.chunk, max_chunks=spec.chunks,
                  observe=bool(observe))
    return Deck(text, model, 2 * len(pairs))


def deck(law, scene, spec, options=None, observe=False):
    """Render the batched deck of a run's spec (RunSpec; validated numbers and fixed words only, see
    harness.infra.render); `observe` adds the per-step contact dump (OBSERVE_DUMP)."""
    from ..user_inputs import INPUT_OPTION, parse
    options = dict(options or {})
    text = options.pop(INPUT_OPTION, None)
    own = parse("liggghts", text).deck_values() if text is not None else None
    if scene.spheres:
        return pair_deck(law, scene, spec, observe, own)
    e_n = spec.e_n
    if own:
        return input_deck(law, scene, spec, observe, own)
    model, tangential, options, properties, restitution = settings(law, scene, e_n, options)
    if not MIN_RESTITUTION < restitution <= 1.0:
        raise EngineFailure(f"LIGGGHTS accepts coefficientRestitution in (0.05, 1] only; e_n = {e_n:g} was not run")
    if scene.nu < 0.0:
        raise EngineFailure(f"LIGGGHTS accepts poissonsRatio in [0, 0.5] only; nu = {scene.nu:g} was not run")
    walls = wall_material(scene, model)
    radius = scene.radius
    spacing = 4.0 * radius
    atoms = [{"x": i * spacing, "vx": float(vt), "vz": -float(vn), "omegay": float(w)}
             for i, (vn, vt, w) in enumerate(zip(spec.v_n0, spec.v_t0, spec.omega0))]
    text = render(TEMPLATES, "batch.in.j2", harness_version=__version__, law=law.name, model=model, e_n=restitution,
                  types=1 + len(walls), E=[scene.E] + [w[0] for w in walls], nu=[scene.nu] + [w[1] for w in walls],
                  atoms=atoms, x_lo=-2.0 * radius, x_hi=len(atoms) * spacing, box_half=2.0 * radius,
                  z_lo=-radius, z_hi=4.0 * radius + scene.gap, skin=0.5 * radius, mu=scene.mu,
                  properties=properties, tangential=tangential, options=options, dt=spec.dt, radius=radius,
                  rho=scene.rho, chunk=spec.chunk, max_chunks=spec.chunks, observe=bool(observe),
                  start_z=radius + scene.gap, **gap_and_states(scene, spec))
    return Deck(text, model, len(atoms))


def input_deck(law, scene, spec, observe, own):
    """The wall deck of a user's own input (`own`: its model, settings and property values, one atom type)."""
    radius = scene.radius
    spacing = 4.0 * radius
    atoms = [{"x": i * spacing, "vx": float(vt), "vz": -float(vn), "omegay": float(w)}
             for i, (vn, vt, w) in enumerate(zip(spec.v_n0, spec.v_t0, spec.omega0))]
    text = render(TEMPLATES, "batch.in.j2", harness_version=__version__, law=law.name, types=1, atoms=atoms,
                  x_lo=-2.0 * radius, x_hi=len(atoms) * spacing, box_half=2.0 * radius, z_lo=-radius,
                  z_hi=4.0 * radius + scene.gap, skin=0.5 * radius, dt=spec.dt, radius=radius, rho=scene.rho,
                  chunk=spec.chunk, max_chunks=spec.chunks, observe=bool(observe), start_z=radius + scene.gap,
                  **gap_and_states(scene, spec), **own)
    return Deck(text, own["model"], len(atoms))


def read_dump(path, n_atoms):
    """Final (z, vx, vz, omegay) per atom id from LIGGGHTS' final dump (see dumps.read_final)."""
    return read_final(path, n_atoms, "LIGGGHTS")


def read_observation(path, n_atoms, radius, dt):
    """Per atom: contact time, peak wall force and peak overlap over its first contact (see dumps.read_observed)."""
    return read_observed(path, n_atoms, radius, dt, "LIGGGHTS")


def run_deck(text, n_atoms, timeout_s, workdir):
    """Run one deck in workdir; returns (final state per atom, wall seconds, log tail)."""
    with open(os.path.join(workdir, "in.harness"), "w") as handle:
        handle.write(text)
    done = run_engine([binary(), "-in", "in.harness", "-log", "none", "-echo", "none"], workdir, timeout_s,
                      env={**os.environ, "OMP_NUM_THREADS": "1"})
    try:
        return read_dump(os.path.join(workdir, "final.dump"), n_atoms), done.wall_s, done.log_tail
    except EngineFailure as exc:
        raise EngineFailure(str(exc), exc.log_tail or done.log_tail) from None


def run_inputs(liggghts, count, timeout_s, workdir):
    """The decks batch<k>/in.harness in one process of the LIGGGHTS executable (batches.in_one_process)."""
    from ..batches import in_one_process    # loaded by harness.runs.before_threads; here, not when engines are listed
    return in_one_process([liggghts, "-log", "none", "-echo", "none"], "in.harness", count, timeout_s, workdir,
                          env={**os.environ, "OMP_NUM_THREADS": "1"})


def read_batch(scene, spec, directory, observe=False):
    """The final state of one run's spec (RunSpec) run in `directory` (and what observe mode saw)."""
    if scene.spheres:
        return read_pair_batch(directory, scene, spec, observe, "LIGGGHTS", OBSERVE_DUMP)
    final = rebound(read_dump(os.path.join(directory, "final.dump"), spec.impacts), scene.radius)
    if observe:
        final.update(read_observation(os.path.join(directory, OBSERVE_DUMP), spec.impacts, scene.radius, spec.dt))
    if scene.at_times:
        final["states"] = read_states(directory, scene, spec, scene.radius, "LIGGGHTS")
    return final


def render_batch(paper_law, scene, spec, options=None, observe=False):
    """The deck text of one run's spec (RunSpec), as Engine.run_batch would run it."""
    return deck(paper_law, scene, spec, options, observe).text
