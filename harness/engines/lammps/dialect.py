"""What LAMMPS computes for each law through `fix wall/gran` and `fix nve/sphere`, as a composition of sub-models
keyed on the release (docs/lammps-dialect.md#versions), and its options."""
from ...infra.errors import UserError
from ..protocol import Option, check_options as check_declared
from .versions import NEWEST, checked, holds, nearest, spelled

GRANULAR = {                  # harness law -> LAMMPS granular (normal, damping, tangential) sub-models
    "linear-spring-dashpot": ("hooke", "mass_velocity", "linear_history"),
    "hertz-mindlin": ("hertz/material", "tsuji", "mindlin"),
    "hertz-kuwabara-kono": ("hertz/material", "viscoelastic", "mindlin"),
}
COUNTERPARTS = {law: " + ".join(words) for law, words in GRANULAR.items()}     # as `harness models` prints them
HISTORY_STYLES = {"linear-spring-dashpot": "hooke/history", "hertz-kuwabara-kono": "hertz/history"}
MINDLIN_FORMS = {"mindlin": "total", "mindlin_rescale": "total-rescale", "mindlin/force": "force",
                 "mindlin_rescale/force": "force-rescale"}
INGREDIENTS = {              # ingredient -> ((first, last checked release it holds for, choice), ...), read from each
    # hertz/material against a wall: the wall's own E/(2(1 - nu)) and E/4 (2 - nu)(1 + nu) (fix_wall_gran.cpp,
    # FixWallGran::granular), then the pair's E* and G* (gran_sub_mod.cpp, mix_stiffnessE_wall/mix_stiffnessG_wall)
    "wall-moduli": (((2021, 9, 29, 2), (2022, 6, 23, 4), "wall"), ((2023, 8, 2, 3), NEWEST, "pair")),
    # `damping coeff_restitution` (gran_sub_mod_damping.cpp, GranSubModDampingCoeffRestitution): absent, then there
    "coeff_restitution": (((2021, 9, 29, 2), (2023, 8, 2, 3), False), ((2024, 8, 29, 3), NEWEST, True)),
    # a sphere at gap 0 against a wall: in contact (fix_wall_gran.cpp, contact while rsq <= R^2), then not
    # (gran_sub_mod_normal.cpp, GranSubModNormal::touch, rsq < radsum^2)
    "touch": (((2021, 9, 29, 2), (2022, 6, 23, 4), "gap"), ((2023, 8, 2, 3), NEWEST, "overlap")),
    # the hooke/history and hertz/history styles' tangential spring: kt xi (hertz: kt a xi) reset to the capped
    # force's (fix_wall_gran.cpp, hooke_history/hertz_history), then kt a xi for both, reset to xi = -F/kt
    # (granular_model.cpp, define_classic_model; gran_sub_mod_tangential.cpp, linear_history_classic and
    # mindlin_classic)
    "classic-spring": (((2021, 9, 29, 2), (2022, 6, 23, 4), "own"), ((2023, 8, 2, 3), NEWEST, "contact-radius")),
}
OPTIONS = {                  # declared options, default first (`--engine-option lammps:KEY=VALUE`)
    "style": Option(("granular", "history"),
                    "wall/gran granular, or the older hooke/history (linear-spring-dashpot), hertz/history "
                    "(hertz-kuwabara-kono)"),
    "tangential": Option(tuple(MINDLIN_FORMS), "the Mindlin spring of the granular style's hertz/material laws"),
    "damping": Option(("tsuji", "coeff_restitution"),
                      "hertz-mindlin's normal dashpot: Tsuji's polynomial, or coeff_restitution (in LAMMPS "
                      f"{checked(*INGREDIENTS['coeff_restitution'][-1][:2])})"),
}
DAMPING_LAWS = ("hertz-mindlin",)     # laws whose granular deck takes the `damping` option
DAMPING = {"tsuji": "tsuji:polynomial", "coeff_restitution": "tsuji:tension"}   # A(e) polynomial; sqrt5 beta
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
CONTACT_RADIUS_SPRINGS = {   # the same numbers through the classic styles' spring (classic-spring contact-radius):
    "linear-spring-dashpot": "contact-radius-spring:kappa",       # k a xi, k the deck's kt
    "hertz-kuwabara-kono": "contact-radius-spring:mindlin",
}


def check_options(law_name, options, version=None):
    """The LAMMPS options given, validated; one clear line for a bad one (each option where its law and release have
    it)."""
    options = check_declared("lammps", OPTIONS, options)
    if "damping" in options and (law_name not in DAMPING_LAWS or options.get("style", "granular") != "granular"):
        raise UserError(f"the damping option is for the granular style's {', '.join(DAMPING_LAWS)}, not {law_name}")
    if options.get("damping") == "coeff_restitution" and version and not holds(INGREDIENTS["coeff_restitution"],
                                                                                 version):
        near = spelled(nearest(version))
        which = f"LAMMPS {version}" if near == version else \
            f"LAMMPS {version} was never checked; the release nearest it that was, {near},"
        raise UserError(f"{which} has no damping coeff_restitution (of the releases harness checked, "
                        f"{releases_of('coeff_restitution', True)} have it)")
    if options.get("style", "granular") == "history" and law_name not in HISTORY_STYLES:
        raise UserError(f"LAMMPS has no older wall style for {law_name}; style history is for "
                        f"{', '.join(HISTORY_STYLES)}")
    if "tangential" in options and (GRANULAR.get(law_name, ("",))[0] != "hertz/material"
                                    or options.get("style", "granular") != "granular"):
        raise UserError(f"the Mindlin springs are for the granular style's hertz/material laws, not {law_name}")
    return options


def words(law_name, options, version=None):
    """(style, normal, damping, tangential) words of the deck for `law_name` with the options given."""
    options = check_options(law_name, options, version)
    if options.get("style", "granular") == "history":
        return HISTORY_STYLES[law_name], None, None, None
    normal, damping, tangential = GRANULAR[law_name]
    return "granular", normal, options.get("damping", damping), options.get("tangential", tangential)


def walls(law_name, options=None):
    """Any wall where the deck gives the wall's stiffnesses as numbers (granular hooke, the older hooke/history and
    hertz/history styles): harness computes them from the contact's E* and G*. hertz/material takes one E and nu and
    mixes them with themselves, so its wall is of the sphere's own material."""
    from ..user_inputs import INPUT_OPTION
    if INPUT_OPTION in (options or {}):
        return ("same", "other", "rigid")         # a user's input gives the contact's numbers whatever the wall
    if law_name not in DIALECTS:
        return ("same",)
    style, normal, _, _ = words(law_name, options)
    return ("same", "other", "rigid") if style in HISTORY_STYLES.values() or normal == "hooke" else ("same",)


def dialect(law_name, options=None, target="wall", version=None):
    """The law as LAMMPS `version` computes it through fix wall/gran and fix nve/sphere: LIGGGHTS' velocity Verlet
    steps (forces from the half-step velocities, no clipping of the normal force), lever R, the Coulomb cap on spring
    plus dashpot (Coulomb rule `total`), contact from gap 0 or from overlap > 0 (`touch`, by release); the granular
    style's wall moduli and Mindlin forms (by release); the older styles with the numbers harness gives them and
    their spring by release. Against a sphere (target 'sphere', pair granular): E* and G* mixed as the paper does,
    `mindlin` on the total displacement, slip from the full radii and torque from R_i - d/2, contact from overlap >
    0."""
    from ...laws import compose
    from ...laws.law import replace_submodels
    options = check_options(law_name, options, version)
    if target == "sphere":
        if options:
            raise UserError(f"LAMMPS' pair inputs take no option, got {', '.join(options)}")
        return replace_submodels(compose(law_name), PAIR_DIALECTS[law_name], "lammps")
    touch = {"touch": holds(INGREDIENTS["touch"], version)}
    if options.get("style", "granular") == "history":
        spring = {} if holds(INGREDIENTS["classic-spring"], version) == "own" else \
            {"tangential": CONTACT_RADIUS_SPRINGS[law_name]}
        return replace_submodels(compose(law_name), {**HISTORY_DIALECTS[law_name], **spring, **touch}, "lammps")
    overrides = {**DIALECTS[law_name], **touch}
    if GRANULAR[law_name][0] == "hertz/material":
        form = MINDLIN_FORMS[options.get("tangential", "mindlin")]
        if holds(INGREDIENTS["wall-moduli"], version) == "wall":
            overrides["tangential"] = f"mindlin-wall-coefficient:{form}"
        else:
            overrides.update(normal="hertz", tangential=f"mindlin-pair-coefficient:{form}")
    if "damping" in options:
        overrides["damping"] = DAMPING[options["damping"]]
    return replace_submodels(compose(law_name), overrides, "lammps")


def numbers(law_name):
    """The composition whose numbers a wall deck gives the older hooke/history and hertz/history styles (k_n, k_t,
    gamma_n, gamma_t): the same in every release checked, which differ in what they compute with them."""
    from ...laws import compose
    from ...laws.law import replace_submodels
    return replace_submodels(compose(law_name), HISTORY_DIALECTS[law_name], "lammps")


def ingredients(version):
    """{ingredient: choice} of the release nearest to `version` that was checked (versions.py)."""
    return {name: holds(ranges, version) for name, ranges in INGREDIENTS.items()}


def releases_of(name, choice):
    """'2024.8.29.3 to 2025.7.22.4': the checked releases in which ingredient `name` is `choice`."""
    return "; ".join(checked(first, last) for first, last, chosen in INGREDIENTS[name] if chosen == choice)
