"""What LIGGGHTS 3.8.0 computes for each law, as a composition of sub-models (docs/liggghts-dialect.md), and what
its contact options change."""
from ...infra.errors import UserError
from ..protocol import Option, check_options as check_declared

COUNTERPARTS = {                      # harness law -> LIGGGHTS normal model
    "linear-spring-dashpot": "hooke",
    "hertz-mindlin": "hertz",
    "walton-braun": "hooke/hysteresis",
    "thornton": "thornton_ning",
}
OPTIONS = {                     # declared options, default first (`--engine-option liggghts:KEY=VALUE`)
    "limitForce": Option(("off", "on"), "clip the normal force at 0 (hooke, hertz)"),
    "tangential_damping": Option(("on", "off"), "the tangential dashpot (hooke, hertz, hooke/hysteresis)"),
    "ktToKnUser": Option(("off", "on"), "k_t = 0.285714286 k_n instead of k_n (hooke)"),
    "tangential": Option(("history", "no_history"), "spring-less viscous friction with no_history (hooke, hertz)"),
}
HONOURED_BY = {                 # the LIGGGHTS models that read each option (the others accept it and ignore it)
    "limitForce": ("hooke", "hertz"),
    "tangential_damping": ("hooke", "hertz", "hooke/hysteresis"),
    "ktToKnUser": ("hooke",),
    "tangential": ("hooke", "hertz"),
}
COMMON = {"end": "tension", "integrator": "velocity-verlet", "coulomb": "spring", "lever": "0.5"}
DIALECTS = {                    # sub-models that make the paper law compute what LIGGGHTS computes
    "linear-spring-dashpot": {**COMMON, "damping": "linear:tension", "tangential": "linear:1",
                              "tangential-damping": "normal-coefficient"},
    "hertz-mindlin": {**COMMON, "damping": "tsuji:tension", "tangential": "mindlin:total",
                      "tangential-damping": "normal-ratio"},
    "walton-braun": {**COMMON, "end": "no-tension", "normal": "luding-peak", "tangential": "linear:1",
                     "tangential-damping": "none"},
    "thornton": {**COMMON, "end": "no-tension", "normal": "thornton-ning", "tangential": "mindlin:total",
                 "tangential-damping": "reversed-beta"},
}
PAIR_DIALECTS = {              # pair gran between two spheres: slip and torque from each sphere's own R_i - d/2
    "hertz-mindlin": {**DIALECTS["hertz-mindlin"], "geometry": "pair", "torque": "contact-point"},
    "linear-spring-dashpot": {**DIALECTS["linear-spring-dashpot"], "geometry": "pair", "torque": "contact-point"},
    "walton-braun": {**DIALECTS["walton-braun"], "geometry": "pair", "torque": "contact-point"},
}
KT_TO_KN_USER = "0.285714286"   # the literal LIGGGHTS multiplies by, not exactly 2/7


def check_options(law_name, options):
    """The LIGGGHTS options given, validated; one clear line for a bad one (no_history exists for hooke and hertz
    only)."""
    options = check_declared("liggghts", OPTIONS, options)
    honoured = COUNTERPARTS.get(law_name) in HONOURED_BY["tangential"]
    if options.get("tangential", "history") != "history" and not honoured:
        raise UserError(f"tangential no_history is offered with hooke and hertz only, not {COUNTERPARTS.get(law_name)}")
    return options


def dialect(law_name, options=None, target="wall"):
    """The law as LIGGGHTS 3.8.0 computes it: velocity Verlet with half-step velocities in the forces,
    lever R - d/2, setup force at first touch, total-displacement tangential spring with its dashpot added after the
    Coulomb test; options change what the model honours (limitForce clips; tangential_damping off removes c_t;
    ktToKnUser gives k_t = 0.285714286 k_n; no_history replaces the spring by capped viscous friction)."""
    from ...laws import compose
    from ...laws.law import replace_submodels
    options = check_options(law_name, options)
    if target == "sphere":
        if options:
            raise UserError(f"LIGGGHTS' pair inputs take no option, got {', '.join(options)}")
        return replace_submodels(compose(law_name), PAIR_DIALECTS[law_name], "liggghts")
    overrides = dict(DIALECTS[law_name])
    honoured = {key: value for key, value in options.items() if COUNTERPARTS[law_name] in HONOURED_BY[key]}
    if honoured.get("limitForce") == "on":
        overrides["end"] = "no-tension"
    if honoured.get("tangential_damping") == "off":
        overrides["tangential-damping"] = "none"
    if honoured.get("ktToKnUser") == "on":
        overrides["tangential"] = f"linear:{KT_TO_KN_USER}"
    if honoured.get("tangential") == "no_history":
        overrides["tangential"] = "viscous:linear" if COUNTERPARTS[law_name] == "hooke" else "viscous:mindlin"
    return replace_submodels(compose(law_name), overrides, "liggghts")


