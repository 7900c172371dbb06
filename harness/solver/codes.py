"""The kernel rows' layout: parameter and integer slots, end rules, outputs and statuses (the sub-models' kernel
codes are the registry's: solver/dispatch.py; the stepping codes submodels/stepping.py's)."""
from ..submodels.stepping import (COULOMB_SPRING, COULOMB_SPRING_FIRST, COULOMB_TOTAL,  # noqa: F401
                                  COULOMB_TOTAL_CASES,
                                  GEOMETRY_PAIR, GEOMETRY_PAIR_VECTOR, GEOMETRY_STAND_IN_SPHERE, GEOMETRY_WALL, INTEGRATOR_LEAPFROG, INTEGRATOR_PAPER,
                                  INTEGRATOR_VELOCITY_VERLET, TOUCH_GAP, TOUCH_OVERLAP)

# end-of-contact rule
END_ALPHA = 0              # tension allowed, contact ends when alpha returns to 0
END_FORCE = 1              # no tension: F clipped at 0, contact ends when F returns to 0

# per-impact parameter slots (columns of the float parameter matrix)
P_MASS, P_INERTIA, P_RADIUS, P_DT, P_GRAVITY, P_MU = 0, 1, 2, 3, 4, 5
P_N1, P_N2, P_N3, P_N4 = 6, 7, 8, 9          # the normal kernel's four slots (each kernel module names them)
P_DAMP_C0, P_DAMP_POWER = 10, 11             # c(alpha) = c0 alpha^power
P_T1, P_T2 = 12, 13                          # tangential-model parameters
P_TDAMP = 14                                 # tangential dashpot: c_t = P_TDAMP sqrt(k_t), 0 = none
P_LEVER = 15                                 # lever arm R - P_LEVER alpha (paper 0)
P_VZ0, P_VX0, P_W0 = 16, 17, 18              # initial velocities (vz < 0 approaching), spin omega_y
P_MAXSTEPS = 19
P_SLIP_R1 = 20                               # slip form: 0 -> V_t - lever omega; r1 > 0 -> the noRatch form
                                             # (r1 + R)/(r1 + R - d) V_t - R omega
P_BIG_R = 21                                 # geometry stand-in-sphere: the radius of the fixed sphere playing the
                                             # wall; pair geometries: R1 + R2 - R*, the centres' distance at touch
                                             # less R*
P_GRADE_T, P_GRADE_N = 22, 23                # > 0: graded steps, N of them over [0, T] (paper scheme, converged mode)
P_TORQUE_LEVER = 24                          # torque lever R - P_TORQUE_LEVER alpha in the Verlet schemes (= P_LEVER
                                             # unless torque 'contact-point': torque from each R_i - d/2)
P_R1, P_R2, P_INV_I1, P_INV_I2, P_W2 = 25, 26, 27, 28, 29   # two spheres: radii, 1/inertias (0: fixed), target's spin
P_TCONE = 30                                 # the paper scheme's Coulomb test with a tangential dashpot: 0 the
                                             # spring's first, 1 spring plus dashpot (tangential_damping.CONES)
P_TSHARE = 31                                # tangential dashpot, Verlet schemes: c_t += P_TSHARE c_n(alpha), a share
                                             # of the normal dashpot (0 = none)
N_PARAMS = 32

# per-impact integer slots
I_NORMAL, I_END, I_TANGENTIAL, I_INTEGRATOR, I_COULOMB, I_GEOMETRY, I_TOUCH = 0, 1, 2, 3, 4, 5, 6
N_INTS = 7

# outputs
O_VZ, O_VX, O_W, O_TC, O_FMAX, O_AMAX, O_STEPS, O_STATUS = 0, 1, 2, 3, 4, 5, 6, 7
O_ACCEPTED = 8              # adaptive integrator: accepted steps (O_STEPS counts its force evaluations)
O_STICKING = 9              # kernel: steps ending with |F_t| strictly inside the Coulomb cone (F_n > 0) or on its
                            # other side from the step before (a dashpot can carry it across); adaptive:
                            # stick phases begun, first touch included (an implicit spring: one more, never on it)
N_OUT = 10

STATUS_OK = 0
STATUS_NO_SEPARATION = 1
STATUS_NONFINITE = 2
