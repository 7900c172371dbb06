"""What Kratos DEMApplication 10.4.4 computes for each law, as a composition of harness' existing sub-models
(docs/kratos-dialect.md): a first mapping, the nearest sub-models to Kratos' own formulas; where they differ is
written beside each entry and measured in the doc. Everything dialect-related of the Kratos engine is here (the
engine reads COUNTERPARTS, DIALECTS and PAIR_DIALECTS)."""
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
