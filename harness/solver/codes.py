"""Integer codes by which the compiled kernel selects sub-models; one table, shared by plan and kernel."""

# normal elastic/plastic part: F_el(alpha, alpha_max)
NORMAL_LINEAR = 0          # k alpha                                  (MODELS 2.1)
NORMAL_HERTZ = 1           # k alpha^3/2                              (paper eq. 1)
NORMAL_WALTON_BRAUN = 2    # K1 alpha loading, K2 (alpha - alpha0) unloading (MODELS 2.4)
NORMAL_THORNTON = 3        # Hertz, linear plastic, Hertz unloading with R_p (MODELS 2.6)
NORMAL_STRONGE = 4         # Hertz, F_y (2 alpha/alpha_y - 1), Hertz unloading with R_c (MODELS 2.5)
NORMAL_LUDING = 5          # LIGGGHTS hooke/hysteresis: k2 = k1 + (k2max - k1) d_max/d_lim (engine dialect)
NORMAL_THORNTON_NING = 6   # LIGGGHTS thornton_ning: incremental 2E* a dd, a capped at a_y (engine dialect)
NORMAL_LUDING_YADE = 7     # YADE Law2_ScGeom_LudingPhys_Basic, kc = 0 (engine dialect, leapfrog only)

# end-of-contact rule
END_ALPHA = 0              # tension allowed, contact ends when alpha returns to 0
END_FORCE = 1              # no tension: F clipped at 0, contact ends when F returns to 0

# tangential part
TANGENTIAL_NONE = 0                # mu = 0 or no tangential motion: no tangential model, no rotation
TANGENTIAL_LINEAR = 1              # dF = -k_t V_s dt, Coulomb cap              (MODELS 3)
TANGENTIAL_MINDLIN_INCREMENTAL = 2 # dF = -8 G* a V_s dt, no rescale            (MODELS 3)
TANGENTIAL_MINDLIN_RESCALE = 3     # F <- F a/a_old on unloading, then dF = -8 G* a V_s dt (paper eq. 18b)
TANGENTIAL_MINDLIN_TOTAL = 4       # F = -8 G* a xi, xi total displacement       (MODELS 3)
TANGENTIAL_MINDLIN_DERESIEWICZ = 5 # Thornton & Yin (1991) theta_k rule          (MODELS 3)
TANGENTIAL_WALTON_BRAUN = 6        # k_t0 [1 - (T - T*)/(mu N - T*)]^1/3         (MODELS 3)
TANGENTIAL_VISCOUS_LINEAR = 7      # no spring: F = -min(c_t |V_s|, mu F_n) sign V_s, c_t from k_t = p1 (no_history)
TANGENTIAL_VISCOUS_MINDLIN = 8     # the same with c_t from k_t = 8 G* a              (LIGGGHTS no_history)

# integrator
INTEGRATOR_PAPER = 0            # second-order splitting on u = m alpha_dot + D(alpha), release located in-step
INTEGRATOR_VELOCITY_VERLET = 1  # LIGGGHTS nve/sphere: forces from half-step velocities, release at the step
INTEGRATOR_LEAPFROG = 2         # YADE NewtonIntegrator: forces at x(t) from v(t - h/2), then v, then x
INTEGRATORS = {"paper": INTEGRATOR_PAPER, "velocity-verlet": INTEGRATOR_VELOCITY_VERLET,
               "leapfrog": INTEGRATOR_LEAPFROG}

# per-impact parameter slots (columns of the float parameter matrix)
P_MASS, P_INERTIA, P_RADIUS, P_DT, P_GRAVITY, P_MU = 0, 1, 2, 3, 4, 5
P_N1, P_N2, P_N3, P_N4 = 6, 7, 8, 9          # normal-model parameters (meaning per model)
P_DAMP_C0, P_DAMP_POWER = 10, 11             # c(alpha) = c0 alpha^power
P_T1, P_T2 = 12, 13                          # tangential-model parameters
P_TDAMP = 14                                 # tangential dashpot: c_t = P_TDAMP sqrt(k_t), 0 = none
P_LEVER = 15                                 # lever arm R - P_LEVER alpha (paper 0)
P_VZ0, P_VX0, P_W0 = 16, 17, 18              # initial velocities (vz < 0 approaching), spin omega_y
P_MAXSTEPS = 19
P_SLIP_R1 = 20                               # slip form: 0 -> V_t - lever omega; r1 > 0 -> YADE noRatch
P_BIG_R = 21                                 # > 0: the wall is a fixed sphere of this radius (YADE Luding set-up)
P_GRADE_T, P_GRADE_N = 22, 23                # > 0: graded steps, N of them over [0, T] (paper scheme, converged mode)
N_PARAMS = 24

# per-impact integer slots
I_NORMAL, I_END, I_TANGENTIAL, I_INTEGRATOR = 0, 1, 2, 3
N_INTS = 4

# outputs
O_VZ, O_VX, O_W, O_TC, O_FMAX, O_AMAX, O_STEPS, O_STATUS = 0, 1, 2, 3, 4, 5, 6, 7
O_ACCEPTED = 8              # adaptive integrator: accepted steps (O_STEPS counts its force evaluations)
O_STICKING = 9              # kernel: steps ending with |F_t| strictly inside the Coulomb cone (F_n > 0); adaptive:
                            # stick phases begun, first touch included (Walton-Braun's spring: one more, never on it)
N_OUT = 10

STATUS_OK = 0
STATUS_NO_SEPARATION = 1
STATUS_NONFINITE = 2
