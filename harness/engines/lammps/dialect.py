"""What LAMMPS (29 Sep 2021) computes for each law through `fix wall/gran` and `fix nve/sphere`, as a composition of
sub-models (docs/lammps-dialect.md), and its options."""
from ...errors import UserError
from ..protocol import Option, check_options as check_declared

GRANULAR = {                  # harness law -> LAMMPS granular (normal, damping, tangential) sub-models
    "linear-spring-dashpot": ("hooke", "mass_velocity", "linear_history"),
    "hertz-mindlin": ("hertz/material", "tsuji", "mindlin"),
    "hertz-kuwabara-kono": ("hertz/material", "viscoelastic", "mindlin"),
}
COUNTERPARTS = {law: " + ".join(words) for law, words in GRANULAR.items()}     # as `harness models` prints them
HISTORY_STYLES = {"linear-spring-dashpot": "hooke/history", "hertz-kuwabara-kono": "hertz/history"}
MINDLIN_FORMS = {"mindlin": "total", "mindlin_rescale": "total-rescale", "mindlin/force": "force",
                 "mindlin_rescale/force": "force-rescale"}
OPTIONS = {                  # declared options, default first (`--engine-option lammps:KEY=VALUE`)
    "style": Option(("granular", "history"),
                    "wall/gran granular, or the older hooke/history (linear-spring-dashpot), hertz/history "
                    "(hertz-kuwabara-kono)"),
    "tangential": Option(tuple(MINDLIN_FORMS), "the Mindlin spring of the granular style's hertz/material laws"),
}
COMMON = {"end": "tension", "integrator": "velocity-verlet", "coulomb": "total", "lever": "0"}
PAIR = {**COMMON, "geometry": "pair"}     # two spheres: their relative motion, the normal turning
HERTZ = {**COMMON, "normal": "hertz-wall-modulus"}
DIALECTS = {                 # sub-models that make the paper law compute what LAMMPS computes
    "linear-spring-dashpot": {**COMMON},
    "hertz-mindlin": {**HERTZ, "damping": "tsuji:polynomial"},
    "hertz-kuwabara-kono": {**HERTZ},
}
PAIR_DIALECTS = {            # pair granular between two spheres: the pair's own mixing of E* and G* (the paper's), the
    "hertz-mindlin": {**PAIR, "damping": "tsuji:polynomial", "tangential": "mindlin:total", "torque": "contact-point"},
    "hertz-kuwabara-kono": {**PAIR, "tangential": "mindlin:total", "torque": "contact-point"},
    "linear-spring-dashpot": {**PAIR, "torque": "contact-point"},
}                            # slip from the full radii, the torque from each R_i - d/2
HISTORY_DIALECTS = {         # the older styles take harness' own k_n, E* and G* (no mixing of their own)
    "linear-spring-dashpot": {**COMMON},
    "hertz-kuwabara-kono": {**COMMON, "tangential": "mindlin:total", "tangential-damping": "none"},
}


def check_options(law_name, options):
    """The LAMMPS options given, validated; one clear line for a bad one (each option where its law has it)."""
    options = check_declared("lammps", OPTIONS, options)
    if options.get("style", "granular") == "history" and law_name not in HISTORY_STYLES:
        raise UserError(f"LAMMPS has no older wall style for {law_name}; style history is for "
                        f"{', '.join(HISTORY_STYLES)}")
    if "tangential" in options and (GRANULAR.get(law_name, ("",))[0] != "hertz/material"
                                    or options.get("style", "granular") != "granular"):
        raise UserError(f"the Mindlin springs are for the granular style's hertz/material laws, not {law_name}")
    return options


def words(law_name, options):
    """(style, normal, damping, tangential) words of the deck for `law_name` with the options given."""
    options = check_options(law_name, options)
    if options.get("style", "granular") == "history":
        return HISTORY_STYLES[law_name], None, None, None
    normal, damping, tangential = GRANULAR[law_name]
    return "granular", normal, damping, options.get("tangential", tangential)


def walls(law_name, options=None):
    """Any wall where the deck gives the wall's stiffnesses as numbers (granular hooke, the older hooke/history and
    hertz/history styles): harness computes them from the contact's E* and G*. hertz/material takes one E and nu and
    mixes them with themselves, so its wall is of the sphere's own material."""
    if law_name not in DIALECTS:
        return ("same",)
    style, normal, _, _ = words(law_name, options)
    return ("same", "other", "rigid") if style in HISTORY_STYLES.values() or normal == "hooke" else ("same",)


def dialect(law_name, options=None, target="wall"):
    """The law as LAMMPS computes it through fix wall/gran and fix nve/sphere: LIGGGHTS' velocity Verlet steps
    (forces from the half-step velocities, contact from gap 0, no clipping of the normal force), lever R, the Coulomb
    cap on spring plus dashpot (Coulomb rule `total`); the granular style's own wall moduli E_w = E/(2(1 - nu)) and
    K = E/4 (2 - nu)(1 + nu) and its Mindlin forms; the older styles with the numbers harness gives them. Against a
    sphere (target 'sphere', pair granular): E* and G* mixed as the paper does, `mindlin` on the total displacement,
    slip from the full radii and torque from R_i - d/2, contact from overlap > 0."""
    from ...laws import compose
    from ...laws.law import replace_submodels
    options = check_options(law_name, options)
    if target == "sphere":
        if options:
            raise UserError(f"LAMMPS' pair inputs take no option, got {', '.join(options)}")
        return replace_submodels(compose(law_name), PAIR_DIALECTS[law_name], "lammps")
    if options.get("style", "granular") == "history":
        return replace_submodels(compose(law_name), HISTORY_DIALECTS[law_name], "lammps")
    overrides = dict(DIALECTS[law_name])
    if GRANULAR[law_name][0] == "hertz/material":
        form = MINDLIN_FORMS[options.get("tangential", "mindlin")]
        overrides["tangential"] = f"mindlin-wall-coefficient:{form}"
    return replace_submodels(compose(law_name), overrides, "lammps")
