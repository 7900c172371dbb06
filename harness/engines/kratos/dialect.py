"""What Kratos DEMApplication 10.4.4 computes for each law against a rigid face (RigidFace3D4N) and between two
spheres, as a composition of sub-models (docs/kratos-dialect.md). Sources: the laws' C++
(custom_constitutive/DEM_D_<law>_CL.cpp), the element (custom_elements/spheric_particle.cpp), the scheme
(custom_strategies/schemes/symplectic_euler_scheme.cpp) and the installed Python (DEMApplication/sphere_strategy.py)."""

COUNTERPARTS = {"hertz-mindlin": "DEM_D_Hertz_viscous_Coulomb", "linear-spring-dashpot": "DEM_D_Linear_viscous_Coulomb"}
COMMON = {
    # symplectic_euler_scheme.cpp, UpdateTranslationalVariables and CalculateNewRotationalVariablesOfSpheres: forces
    # from x_n and v_n, then v += dt F/m, x += dt v (omega likewise): the leapfrog's algebra
    "integrator": "leapfrog",
    # the laws' CalculateForcesWithFEM / CalculateForces: elastic + damping clipped at 0 while the overlap lasts
    "end": "no-tension",
    # CalculateViscoDampingForce(WithFEM): c_t = 2 gamma sqrt(m* k_t), the normal dashpot's gamma
    "tangential-damping": "normal-ratio",
    # DEM_D_Hertz_viscous_Coulomb_CL.cpp, CalculateTangentialForceWithNeighbour (the linear law's the same): the
    # sum capped by four cases, the stored spring cut to mu F_n only where it carries the total
    "coulomb": "total-cases",
    # spheric_particle.cpp, ComputeMoments and the rigid-face relative velocity: arm R - delta on a wall
    "lever": "1",
    # spheric_particle.cpp: forces only where indentation > 0, so a sphere placed touching feels none
    "touch": "overlap",
}
DIALECTS = {                 # sub-models that make the paper law compute what Kratos computes against a rigid face
    # DAMPING_GAMMA from sphere_strategy.py, GammaForHertzThornton (the paper's App. B fit) on k_n = 2E*sqrt(R d);
    # DEM_D_Hertz_viscous_Coulomb_CL.cpp, CalculateTangentialForceWithNeighbour: F sqrt(d/d_old) on unloading only,
    # k_t = 4 G*/E* k_n = 8 G* a (InitializeContactWithFEM)
    "hertz-mindlin": {**COMMON, "damping": "tsuji:appendix-b", "tangential": "mindlin-unloading"},
    # DEM_D_Linear_viscous_Coulomb_CL.cpp, InitializeContactWithFEM: k_n = E* pi 0.31225 R, k_t = 4 G*/E* k_n;
    # sphere_strategy.py, RootByBisection on coeff_of_rest_diff (Schwager & Poeschel), bracket [0, 16], tol 1e-4
    "linear-spring-dashpot": {**COMMON, "normal": "linear-modulus:wall", "damping": "linear:bisection",
                              "tangential": "linear:kappa"},
}
# two spheres: their relative motion (scalar shear along the turning tangent: the stored force read in the old local
# frame is reused in the new one), arms R_i - delta E_j/(E_i + E_j) = R_i - delta/2 for equal moduli
PAIR = {"geometry": "pair", "lever": "0.5"}
PAIR_DIALECTS = {
    "hertz-mindlin": {**DIALECTS["hertz-mindlin"], **PAIR},
    # DEM_D_Linear_viscous_Coulomb_CL.cpp, InitializeContact: k_n = 1.432 E* pi 0.31225 R*
    "linear-spring-dashpot": {**DIALECTS["linear-spring-dashpot"], **PAIR, "normal": "linear-modulus:pair"},
}


def dialect(law_name, target="wall"):
    """The law as Kratos 10.4.4 computes it: symplectic Euler, App. B (Hertz) or 1e-4-bisected Schwager-Poeschel
    (linear, k_n = beta E* pi 0.31225 R*) damping on the current stiffness, no tension, Mindlin 8 G* a rescaled on
    unloading only (Hertz) or k_t = 4 G*/E* k_n (linear), the four-case cap on spring plus dashpot, no force at
    overlap 0, lever R - delta against a wall and R - delta/2 between equal spheres."""
    from ...laws import compose
    from ...laws.law import replace_submodels
    chosen = PAIR_DIALECTS if target == "sphere" else DIALECTS
    return replace_submodels(compose(law_name), chosen[law_name], "kratos")
