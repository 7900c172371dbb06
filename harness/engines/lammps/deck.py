"""LAMMPS' input and output: one batched deck per (law, e_n), every impact its own sphere against a `fix wall/gran
granular` plane, run in its own directory, and its final dump read back (docs/lammps-dialect.md)."""
import math
import os
from pathlib import Path


from ...infra.render import render
from ...infra.version import __version__
from ..base import split_submodels
from ..dumps import read_final, read_observed, read_pair_batch, rebound
from ..runner import EngineFailure
from ..states_deck import gap_and_states, read_states, refuse_between_spheres
from .dialect import HISTORY_STYLES, dialect, numbers, walls, words

TEMPLATES = Path(__file__).resolve().parent / "templates"
INPUT = "in.harness"
OBSERVE_DUMP = "observe.dump"   # observe mode: `id z fz` of every sphere in contact, every step
BINARY_VARIABLE = "HARNESS_LAMMPS"      # path of another lmp binary (a custom build, or a test's fake)


def settings(law, scene, e_n, options=None, version=None):
    """The words and coefficients that make LAMMPS compute the dialect of `law` at e_n, as the template's values.
    granular: LAMMPS' damping coefficient is e itself for tsuji, c/m for mass_velocity and c/(m sqrt R) for
    viscoelastic; x_gamma_t = c_t/c_n, a constant for each counterpart (Mindlin's k_t and the Tsuji dashpot both grow
    as alpha^1/2 and alpha^1/4). history: k_n (4/3 E* for hertz/history), k_t (8 G*), gamma_n = c_n/m (c_n/(m sqrt R)
    for hertz/history), gamma_t = c_t/m, and dampflag 1 where there is a tangential dashpot. A sub-model among the
    options (a mapped `--with`) replaces that of the dialect, and the numbers follow it; the dialect is LAMMPS
    `version`'s (the older styles' numbers are the same in every release: dialect.numbers)."""
    options, submodels = split_submodels(options)
    style, normal, damping, tangential = words(law.name, options, version)
    own = numbers(law.name) if style in HISTORY_STYLES.values() else \
        dialect(law.name, options, "sphere" if scene.spheres else "wall", version)
    if submodels:
        from ...laws.law import replace_submodels
        own = replace_submodels(own, submodels)
    c = scene.contact
    stiffness = own.normal.parameters(c, e_n, scene.speed)
    dashpot = own.damping.dashpot(own.normal, c, e_n, scene.speed, own.end)
    k_t = own.tangential.parameter(c, stiffness.linear_stiffness)
    c_t = own.tangential_damping.prefactor(c, dashpot, stiffness.linear_stiffness,     # c_t = this sqrt(k_t)
                                           k_t if own.tangential.constant_stiffness else None, e_n)
    values = dict(style=style, normal=normal, damping=damping, tangential=tangential, normal_args=[],
                  history_args=[], dampflag=0, k_t=None, x_gamma_t=0.0)
    if style == "hooke/history":
        values.update(history_args=[stiffness.values[0], k_t, dashpot.c0 / c.mass, c_t * math.sqrt(k_t) / c.mass,
                                    scene.mu], dampflag=1 if c_t else 0)
    elif style == "hertz/history":
        values.update(history_args=[4.0 / 3.0 * stiffness.values[0], 8.0 * k_t,
                                    dashpot.c0 / (c.mass * math.sqrt(c.radius)), 0.0, scene.mu])
    elif normal == "hooke":
        values.update(normal_args=[stiffness.values[0], dashpot.c0 / c.mass], k_t=k_t,
                      x_gamma_t=c_t * math.sqrt(k_t) / dashpot.c0 if dashpot.c0 else 0.0)
    else:
        coefficient = {"tsuji": e_n, "coeff_restitution": e_n,
                       "viscoelastic": dashpot.c0 / (c.mass * math.sqrt(c.radius))}[damping]
        values.update(normal_args=[scene.E, coefficient, scene.nu],
                      x_gamma_t=c_t * math.sqrt(8.0 * k_t * math.sqrt(c.radius)) / dashpot.c0 if c_t else 0.0)
    return values


NORMAL_ARGUMENTS = {"hertz/material": ("E", "eta_n0", "nu"), "hooke": ("k_n", "eta_n0")}
HISTORY_ARGUMENTS = ("Kn", "Kt", "gamma_n", "gamma_t", "xmu", "dampflag")
RESTITUTION_DAMPING = ("tsuji", "coeff_restitution")       # whose eta_n0 slot takes the restitution coefficient e


def typed(lines):
    """[(name, value)] of the `fix wall/gran` line among a deck's contact lines, named as LAMMPS' manual names them:
    granular NORMAL E eta_n0 nu (e for damping tsuji and coeff_restitution) damping D tangential FORM k_t x_gamma_t
    mu, or STYLE Kn Kt gamma_n gamma_t xmu dampflag."""
    words = next((line.split() for line in lines if line.startswith("fix wall ")), [])
    if "wall/gran" not in words:
        return []
    words = words[words.index("wall/gran") + 1:]
    if words[0] != "granular":
        return [("style", words[0])] + list(zip(HISTORY_ARGUMENTS, words[1:]))
    normal, count = words[1], len(NORMAL_ARGUMENTS.get(words[1], ()))
    rest = words[2 + count:]
    damping = rest[rest.index("damping") + 1]
    names = [("e" if name == "eta_n0" and damping in RESTITUTION_DAMPING else name)
             for name in NORMAL_ARGUMENTS.get(normal, ())]
    tangential = rest.index("tangential")
    return ([("normal", normal)] + list(zip(names, words[2:2 + count])) + [("damping", damping)]
            + [("tangential", rest[tangential + 1])] + list(zip(("k_t", "x_gamma_t", "mu"), rest[tangential + 2:])))


def pair_material(contact):
    """(E, nu) whose own mixing, E/(2(1 - nu^2)) and E/(4 (2 - nu)(1 + nu)), gives the pair's E* and G*: with
    r = E*/G* = 2 (2 - nu)/(1 - nu), nu = (4 - r)/(2 - r) and E = 2 (1 - nu^2) E* (pair_coeff 1 2 mixes one
    material with itself; its mixing of 1 1 and 2 2 is unusable in this version: docs/lammps-dialect.md)."""
    r = contact.E_star / contact.G_star
    nu = (4.0 - r) / (2.0 - r)
    return {"E": 2.0 * (1.0 - nu * nu) * contact.E_star, "nu": nu}


def pair_deck(law, scene, spec, options=None, observe=False, version=None, own=None):
    """The batched deck of two-sphere impacts: pair k is atoms 2k-1 (the projectile, above) and 2k (its target, at
    rest, frozen when fixed), touching, their relative velocity the impact's; omega0 is the equivalent spin, so the
    projectile's own is (R* omega0 - R2 omega2)/R1. hertz/material gets each type's E and nu and the pair's mixing
    (pair_material); hooke takes the pair's k_n, damping and k_t as numbers."""
    refuse_between_spheres(scene, "LAMMPS")
    projectile, target = scene.spheres
    r1, r2, r_star = projectile.radius, target.radius, scene.contact.radius
    spacing = 3.0 * (r1 + r2)
    pairs = [{"x": i * spacing, "vx": float(vt), "vz": -float(vn),
              "omega1": (r_star * float(w) - r2 * target.omega) / r1}
             for i, (vn, vt, w) in enumerate(zip(spec.v_n0, spec.v_t0, spec.omega0))]
    values = dict(INPUT_SETTINGS, normal_args=[0.0, 0.0]) if own else settings(law, scene, spec.e_n, options, version)
    normal_args = values.pop("normal_args")          # hooke: k_n, c_n/m; hertz/material: E, coefficient, nu
    k_n, coefficient = normal_args[0], normal_args[1]
    materials = [(1, 1, {"E": projectile.E, "nu": projectile.nu}), (2, 2, {"E": target.E, "nu": target.nu}),
                 (1, 2, pair_material(scene.contact))]
    big = max(r1, r2)
    return render(TEMPLATES, "pair.in.j2", harness_version=__version__, law=law.name, mu=scene.mu, e_n=spec.e_n,
                  pairs=pairs, coefficients=materials, coefficient=coefficient, x_lo=-2.0 * big,
                  x_hi=len(pairs) * spacing, box_half=2.0 * big, z_lo=-2.0 * r2, z_hi=2.0 * (r1 + r2) + 2.0 * r1,
                  skin=0.5 * min(r1, r2), dt=spec.dt, centres=r1 + r2, r1=r1, r2=r2, rho1=projectile.rho,
                  rho2=target.rho, omega2=target.omega, fixed=target.fixed, chunk=spec.chunk, max_chunks=spec.chunks,
                  normal=values["normal"], damping=values["damping"], tangential=values["tangential"],
                  x_gamma_t=values["x_gamma_t"], k_n=k_n, k_t=values["k_t"], observe=bool(observe),
                  **{"input_style": (), "input_coeff": (), **(own or {})})


def input_words(options, version):
    """{pair_style, pair_coeff, wall} words of a user's own input (option `input`: engines/user_inputs.py), or {}."""
    from ..user_inputs import INPUT_OPTION, parse
    text = dict(options or {}).get(INPUT_OPTION)
    if text is None:
        return {}
    style, coefficients, wall = parse("lammps", text, version).deck_style()
    return {"input_style": style, "input_coeff": coefficients, "input_wall": wall}


def deck(law, scene, spec, options=None, observe=False, version=None):
    """Render the batched deck of a run's spec (RunSpec; validated numbers and fixed words only, see
    infra/render.py) for LAMMPS `version`; `observe` adds the per-step contact dump (OBSERVE_DUMP). A user's own input
    (the option `input`) gives its contact words verbatim to pair_style, pair_coeff * * and fix wall/gran."""
    own = input_words(options, version)
    if scene.spheres:
        return pair_deck(law, scene, spec, options, observe, version, own)
    if not own and scene.wall not in walls(law.name, split_submodels(options)[0]):
        raise EngineFailure(f"LAMMPS' {law.name} decks use a wall of the sphere's own material")
    radius = scene.radius
    spacing = 4.0 * radius
    atoms = [{"x": i * spacing, "vx": float(vt), "vz": -float(vn), "omegay": float(w)}
             for i, (vn, vt, w) in enumerate(zip(spec.v_n0, spec.v_t0, spec.omega0))]
    return render(TEMPLATES, "batch.in.j2", harness_version=__version__, law=law.name, mu=scene.mu, e_n=spec.e_n,
                  atoms=atoms, x_lo=-2.0 * radius, x_hi=len(atoms) * spacing, box_half=2.0 * radius, z_lo=-radius,
                  z_hi=4.0 * radius + scene.gap, skin=0.5 * radius, dt=spec.dt, radius=radius, rho=scene.rho,
                  chunk=spec.chunk, max_chunks=spec.chunks, observe=bool(observe), start_z=radius + scene.gap,
                  **gap_and_states(scene, spec),
                  **({**INPUT_SETTINGS, **own} if own else {**NO_INPUT, **settings(law, scene, spec.e_n, options,
                                                                                  version)}))


INPUT_SETTINGS = dict(style="input", normal="input", damping="input", tangential="input", normal_args=[],
                      history_args=[], dampflag=0, k_t=None, x_gamma_t=0.0)    # what a template reads of an input
NO_INPUT = dict(input_style=(), input_coeff=(), input_wall=())


def run_inputs(lmp, count, timeout_s, workdir):
    """The decks batch<k>/in.harness in one process of the LAMMPS executable `lmp` (batches.in_one_process)."""
    from ..batches import in_one_process    # loaded by harness.runs.before_threads; here, not when engines are listed
    return in_one_process([lmp, "-log", "none", "-echo", "none", "-nocite"], INPUT, count, timeout_s, workdir)


def read_batch(scene, spec, directory, observe=False):
    """Rebound velocities and separation of one run's spec (RunSpec) run in `directory` (and what
    observe mode saw)."""
    if scene.spheres:
        return read_pair_batch(directory, scene, spec, observe, "LAMMPS", OBSERVE_DUMP)
    final = read_outputs(directory, spec, scene.radius, observe)
    if scene.at_times:
        final["states"] = read_states(directory, scene, spec, scene.radius, "LAMMPS")
    return final


def read_outputs(directory, spec, radius, observe):
    """Rebound velocities and separation from the final dump in `directory`; with `observe` also t_contact, f_n_max
    and overlap_max from the observe dump."""
    final = rebound(read_final(os.path.join(directory, "final.dump"), spec.impacts, "LAMMPS"), radius)
    if observe:
        final.update(read_observed(os.path.join(directory, OBSERVE_DUMP), spec.impacts, radius, spec.dt, "LAMMPS"))
    return final


def render_batch(paper_law, scene, spec, options=None, observe=False, version=None):
    """The deck text of one run's spec (RunSpec; for `harness render` and the runs) for LAMMPS
    `version`."""
    return deck(paper_law, scene, spec, options, observe, version)
