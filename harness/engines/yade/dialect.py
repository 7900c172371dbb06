"""What YADE 2023.02a computes for each law, as a composition of sub-models (docs/yade-dialect.md), and its options."""
from ...infra.errors import UserError
from ..protocol import Option, check_options as check_declared

COUNTERPARTS = {"hertz-mindlin": "Law2_ScGeom_MindlinPhys_Mindlin",
                "linear-spring-dashpot": "Law2_ScGeom_ViscElPhys_Basic",
                "walton-braun": "Law2_ScGeom_LudingPhys_Basic"}
DIALECTS = {                    # sub-models that make the paper law compute what YADE computes
    "hertz-mindlin": {"damping": "tsuji:appendix-b", "end": "no-tension", "tangential": "mindlin:incremental",
                      "tangential-damping": "normal-ratio", "integrator": "leapfrog", "coulomb": "spring",
                      "lever": "1", "slip": "noratch"},
    "linear-spring-dashpot": {"damping": "linear:half-mass", "end": "no-tension", "tangential": "linear:2/7",
                              "tangential-damping": "proportional", "integrator": "leapfrog", "coulomb": "spring",
                              "lever": "1"},
    "walton-braun": {"normal": "luding-incremental", "end": "no-tension", "tangential": "linear:2/7",
                     "tangential-damping": "none", "integrator": "leapfrog", "coulomb": "spring",
                     "geometry": "stand-in-sphere", "lever": "0.5"},
}
PAIR_DIALECTS = {              # Ig2_Sphere_Sphere_ScGeom between two spheres: slip from the full radii with noRatch
    "hertz-mindlin": {**DIALECTS["hertz-mindlin"], "geometry": "pair-vector", "lever": "0", "slip": "noratch-pair",
                      "torque": "contact-point"},       # (R1 + R2)/(R1 + R2 - d), torque from each R_i - d/2
}
OPTIONS = {                     # declared options, default first (`--engine-option yade:KEY=VALUE`)
    "precision": Option(("double", "long-double", "float128", "mpfr150"),
                        "the YADE flavour (arithmetic) that runs; inputs go in as exact decimal strings"),
    "linear": Option(("viscel", "cundall-strack"),
                     "YADE's law for linear-spring-dashpot: ViscEl, or the elastic CundallStrack"),
}
CUNDALL_STRACK = {             # K_n = E R, K_s = nu K_n, no damping (e = 1 whatever e_n), noRatch slip with the
    "normal": "cundall-strack", "damping": "none", "end": "tension",  # default wall geometry (r1 = R),
    "tangential": "linear:nu", "tangential-damping": "none",                 # torque lever R - d/2
    "integrator": "leapfrog", "coulomb": "spring", "lever": "0.5", "slip": "noratch-sphere"}


def dialect(law_name, options=None, target="wall"):
    """The law as YADE 2023.02a computes it: leapfrog with forces from the half-step velocities, contact from
    overlap >= 0 until the first negative overlap, App. B damping with the normal force clipped at 0, incremental
    8G*a shear spring (not reduced as a falls), dashpot after the Coulomb test, torque lever R - d, noRatch slip."""
    from ...laws import compose
    from ...laws.law import replace_submodels
    options = check_options(options)
    if target == "sphere":
        if law_name not in PAIR_DIALECTS:
            raise UserError(f"YADE's sphere-target inputs run hertz-mindlin only, not {law_name}")
        if "linear" in options:
            raise UserError("YADE's sphere-target inputs take the precision option only")
        return replace_submodels(compose(law_name), PAIR_DIALECTS[law_name], "yade")
    if law_name == "linear-spring-dashpot" and options.get("linear") == "cundall-strack":
        return replace_submodels(compose(law_name), CUNDALL_STRACK, "yade")
    return replace_submodels(compose(law_name), DIALECTS[law_name], "yade")


def check_options(options):
    """The YADE options given, validated; one clear line for a bad one."""
    return check_declared("yade", OPTIONS, options)
