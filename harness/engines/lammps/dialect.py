"""What LAMMPS (29 Sep 2021) computes for each law through `fix wall/gran granular` and `fix nve/sphere`, as a
composition of sub-models (docs/lammps-dialect.md), and its options."""
from ..protocol import check_options as check_declared

COUNTERPARTS = {              # harness law -> LAMMPS granular (normal, damping, tangential) sub-models
    "linear-spring-dashpot": ("hooke", "mass_velocity", "linear_history"),
    "hertz-mindlin": ("hertz/material", "tsuji", "mindlin"),
    "hertz-kuwabara-kono": ("hertz/material", "viscoelastic", "mindlin"),
}
OPTIONS = {}                 # none yet: each law has one counterpart
COMMON = {"end": "tension", "integrator": "lammps", "lever": "0"}
HERTZ = {**COMMON, "normal": "lammps-wall-hertz", "tangential": "lammps-wall-mindlin:total"}
DIALECTS = {                 # sub-models that make the paper law compute what LAMMPS computes
    "linear-spring-dashpot": {**COMMON},
    "hertz-mindlin": {**HERTZ, "damping": "tsuji:lammps"},
    "hertz-kuwabara-kono": {**HERTZ},
}


def check_options(law_name, options):
    """The LAMMPS options given, validated; one clear line for a bad one."""
    return check_declared("lammps", OPTIONS, options)


def dialect(law_name, options=None):
    """The law as LAMMPS computes it through fix wall/gran granular and fix nve/sphere: LIGGGHTS' velocity Verlet
    steps (forces from the half-step velocities, contact from gap 0, no clipping of the normal force), the wall's own
    moduli E_w = E/(2(1 - nu)) and K = E/4 (2 - nu)(1 + nu), the spring on the total displacement, and the Coulomb
    cap on spring plus dashpot with lever R."""
    from ...laws import compose
    from ...laws.law import replace_submodels
    check_options(law_name, options)
    return replace_submodels(compose(law_name), DIALECTS[law_name], "lammps")
