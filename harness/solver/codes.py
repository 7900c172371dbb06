"""The kernel rows' layout: parameter and integer slots, end rules, integrators, outputs and statuses (the
sub-models' kernel codes are the registry's: solver/dispatch.py)."""

# end-of-contact rule
END_ALPHA = 0              # tension allowed, contact ends when alpha returns to 0
END_FORCE = 1              # no tension: F clipped at 0, contact ends when F returns to 0

# integrator
INTEGRATOR_PAPER = 0            # second-order splitting on u = m alpha_dot + D(alpha), release located in-step
INTEGRATOR_VELOCITY_VERLET = 1  # LIGGGHTS nve/sphere: forces from half-step velocities, release at the step
INTEGRATOR_LEAPFROG = 2         # YADE NewtonIntegrator: forces at x(t) from v(t - h/2), then v, then x
INTEGRATOR_LAMMPS = 3           # LAMMPS nve/sphere: LIGGGHTS' steps; the Coulomb cap on spring plus dashpot
INTEGRATOR_LAMMPS_PAIR = 4      # LAMMPS nve/sphere on two spheres: their relative motion, its normal turning
INTEGRATOR_LIGGGHTS_PAIR = 5    # the same with LIGGGHTS' Coulomb rule (the spring capped, its dashpot added below it)
INTEGRATOR_YADE_PAIR = 6        # YADE NewtonIntegrator on two spheres: leapfrog on their relative motion, vector shear
INTEGRATORS = {"paper": INTEGRATOR_PAPER, "velocity-verlet": INTEGRATOR_VELOCITY_VERLET,
               "leapfrog": INTEGRATOR_LEAPFROG, "lammps": INTEGRATOR_LAMMPS, "lammps-pair": INTEGRATOR_LAMMPS_PAIR,
               "liggghts-pair": INTEGRATOR_LIGGGHTS_PAIR, "yade-pair": INTEGRATOR_YADE_PAIR}

# per-impact parameter slots (columns of the float parameter matrix)
P_MASS, P_INERTIA, P_RADIUS, P_DT, P_GRAVITY, P_MU = 0, 1, 2, 3, 4, 5
P_N1, P_N2, P_N3, P_N4 = 6, 7, 8, 9          # the normal kernel's four slots (each kernel module names them)
P_DAMP_C0, P_DAMP_POWER = 10, 11             # c(alpha) = c0 alpha^power
P_T1, P_T2 = 12, 13                          # tangential-model parameters
P_TDAMP = 14                                 # tangential dashpot: c_t = P_TDAMP sqrt(k_t), 0 = none
P_LEVER = 15                                 # lever arm R - P_LEVER alpha (paper 0)
P_VZ0, P_VX0, P_W0 = 16, 17, 18              # initial velocities (vz < 0 approaching), spin omega_y
P_MAXSTEPS = 19
P_SLIP_R1 = 20                               # slip form: 0 -> V_t - lever omega; r1 > 0 -> YADE noRatch
P_BIG_R = 21                                 # > 0: the wall is a fixed sphere of this radius (YADE Luding set-up);
                                             # *-pair: R1 + R2 - R*, the centres' distance at touch less R*
P_GRADE_T, P_GRADE_N = 22, 23                # > 0: graded steps, N of them over [0, T] (paper scheme, converged mode)
P_TORQUE_LEVER = 24                          # torque lever R - P_TORQUE_LEVER alpha in the Verlet schemes (= P_LEVER
                                             # but for LAMMPS' pairs: slip from full radii, torque from R_i - d/2)
P_R1, P_R2, P_INV_I1, P_INV_I2, P_W2 = 25, 26, 27, 28, 29   # two spheres: radii, 1/inertias (0: fixed), target's spin
P_TCONE = 30                                 # the paper scheme's Coulomb test with a tangential dashpot: 0 the
                                             # spring's first, 1 spring plus dashpot (tangential_damping.CONES)
N_PARAMS = 31

# per-impact integer slots
I_NORMAL, I_END, I_TANGENTIAL, I_INTEGRATOR = 0, 1, 2, 3
N_INTS = 4

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
