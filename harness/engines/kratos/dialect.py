"""What Kratos DEMApplication 10.4.4 computes for each law, as a composition of harness' existing sub-models
(docs/kratos-dialect.md): a first mapping, the nearest sub-models to Kratos' own formulas; where they differ is
written beside each entry and measured in the doc. Everything dialect-related of the Kratos engine is here."""
import math

from ...errors import UserError

COUNTERPARTS = {                # harness law -> Kratos' constitutive law of the ball-wall and ball-ball relations
    "hertz-mindlin": "DEM_D_Hertz_viscous_Coulomb",
    "linear-spring-dashpot": "DEM_D_Linear_viscous_Coulomb",
}
# Symplectic Euler (v from the forces at x_n, then x from the new v) is harness' leapfrog with v read at half steps;
# the Coulomb cap bounds spring plus dashpot ('total'; Kratos' own four-case split of the capped force is not a
# sub-model yet); the lever arm against a wall is R - d (spheric_particle.cpp, ComputeMoments).
COMMON = {"end": "no-tension", "integrator": "leapfrog", "coulomb": "total", "lever": "1"}
DIALECTS = {
    # damping from the paper's Appendix B fit (sphere_strategy.py, GammaForHertzThornton); the elastic tangential
    # force scaled by sqrt(d/d_old) = a/a_old on unloading, then the 8 G* a increment: the paper's eq. 18b
    "hertz-mindlin": {**COMMON, "damping": "tsuji:appendix-b", "tangential": "mindlin:rescale",
                      "tangential-damping": "normal-ratio"},
    # gamma from Schwager & Poeschel's no-tension e(gamma) by a 1e-4 bisection (the reference inverts it exactly);
    # k_t = 4 G*/E* k_n = kappa k_n, k_n fixed by E (the inputs give Kratos the E that makes it the law's k_n)
    "linear-spring-dashpot": {**COMMON, "damping": "linear:exact", "tangential-damping": "normal-ratio"},
}
# between two spheres: the pair's relative motion with the shear turned with the normal (the leapfrog pair stepper,
# whose Coulomb rule is 'spring'), torque from each R_i - d/2 (equal moduli)
PAIR = {"integrator": "leapfrog", "geometry": "pair-vector", "lever": "0.5", "torque": "contact-point",
        "end": "no-tension"}
PAIR_DIALECTS = {
    "hertz-mindlin": {**PAIR, "damping": "tsuji:appendix-b", "tangential": "mindlin:rescale",
                      "tangential-damping": "normal-ratio"},
    "linear-spring-dashpot": {**PAIR, "damping": "linear:exact", "tangential-damping": "normal-ratio"},
}
# Kratos' linear stiffness is k_n = beta E* pi r, r = 0.31225 R* (DEM_D_Linear_viscous_Coulomb_CL.cpp): beta = 1
# against a wall, 1.432 between two spheres
LINEAR_RADIUS = 0.31225
LINEAR_BETA = {"wall": 1.0, "sphere": 1.432}
RIGID_SCALE = 1e20              # a rigid wall: Kratos' E_wall this many times the sphere's (its own tests use 1e20)


def walls(law_name, options=None):
    """Any wall: a rigid face carries its own YOUNG_MODULUS and POISSON_RATIO, mixed with the sphere's as harness
    mixes them (InitializeContactWithFEM); rigid is a face this many times stiffer."""
    return ("same", "other", "rigid")


def moduli_scale(law, scene, e_n, target):
    """The factor on every Young's modulus that makes Kratos' own stiffness the law's: 1 for Hertz (its k_n is
    harness'); for the linear law, k_n/(beta E* pi 0.31225 R*), which leaves 4 G*/E* = k_t/k_n as it is."""
    if law.name != "linear-spring-dashpot":
        return 1.0
    contact = scene.contact
    k_n = law.normal.parameters(contact, e_n, scene.speed).values[0]
    return k_n / (LINEAR_BETA[target] * contact.E_star * math.pi * LINEAR_RADIUS * contact.radius)
