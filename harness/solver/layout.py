"""Generated from harness/submodels/registry.py by `python -m harness.submodels.generate`: do not edit.

The columns of a kernel row (docs/design.md): the impact's own, then each family's block, in which a
kernel's SLOTS take the first columns, named FAMILY_KERNEL_SLOT.
"""

MASS = 0    # the sphere's (or the pair's reduced) mass
INERTIA = 1    # its moment of inertia
RADIUS = 2    # its (or the pair's equivalent) radius R
DT = 3    # the time step
GRAVITY = 4    # gravity towards the wall
MU = 5    # the friction coefficient
VZ0 = 6    # incident velocity along the normal (< 0 approaching)
VX0 = 7    # incident tangential velocity
W0 = 8    # initial spin omega_y
MAX_STEPS = 9    # the step cap
GRADE_T = 10    # graded steps: their span T (0: uniform steps)
GRADE_N = 11    # graded steps: how many over T
LEVER = 12    # c of the slip's lever arm R - c alpha (paper 0)
TORQUE_LEVER = 13    # c of the torque's lever R - c alpha (R_i - c alpha between two spheres)
SLIP_RADIUS = 14    # slip form: 0 -> V_t - lever omega; r1 > 0 -> (r1 + R)/(r1 + R - d) V_t - R omega
ALPHA0 = 15    # the signed overlap at the row's start: 0 at first touch, < 0 after a free approach (approach.py)
X0 = 16    # the start's offset along the tangent from the touching position (two spheres, a stand-in sphere)
Z0 = 17    # the start's offset along the normal from the touching position (> 0 apart)
FIRST_H = 18    # the first step where it is not dt: the paper scheme's, from the exact touch to the next step (0: dt)
DAMPING_C0 = 19    # the normal dashpot c = c0 alpha^power
DAMPING_POWER = 20
TANGENTIAL_DAMPING_PREFACTOR = 21    # the tangential dashpot c_t = prefactor sqrt(k_t) + share c_n(alpha)
TANGENTIAL_DAMPING_CONE = 22    # the paper scheme's Coulomb test (CONE_CODES)
TANGENTIAL_DAMPING_SHARE = 23    # a share of the normal dashpot c_n (0: none)
NORMAL_LINEAR_K_N = 24
NORMAL_HERTZ_E_STAR = 24
NORMAL_WALTON_BRAUN_K1 = 24
NORMAL_WALTON_BRAUN_K2 = 25
NORMAL_THORNTON_E_STAR = 24
NORMAL_THORNTON_P_Y = 25
NORMAL_THORNTON_ALPHA_Y = 26
NORMAL_THORNTON_F_Y = 27
NORMAL_STRONGE_E_STAR = 24
NORMAL_STRONGE_ALPHA_Y = 25
NORMAL_STRONGE_F_Y = 26
NORMAL_LUDING_PEAK_K1 = 24
NORMAL_LUDING_PEAK_K2_MAX = 25
NORMAL_LUDING_PEAK_D_LIM = 26
NORMAL_THORNTON_NING_E_STAR = 24
NORMAL_THORNTON_NING_A_Y = 25
NORMAL_LUDING_INCREMENTAL_K1 = 24
NORMAL_LUDING_INCREMENTAL_KP = 25
NORMAL_LUDING_INCREMENTAL_DELT_P_MAX = 26
NORMAL_LUDING_INCREMENTAL_DELT_P_NULL = 27
TANGENTIAL_LINEAR_K_T = 28
TANGENTIAL_MINDLIN_INCREMENTAL_G = 28
TANGENTIAL_MINDLIN_RESCALE_G = 28
TANGENTIAL_MINDLIN_TOTAL_G = 28
TANGENTIAL_MINDLIN_DERESIEWICZ_G = 28
TANGENTIAL_WALTON_BRAUN_K_T0 = 28
TANGENTIAL_VISCOUS_LINEAR_K_T = 28
TANGENTIAL_VISCOUS_MINDLIN_G = 28
TANGENTIAL_MINDLIN_TOTAL_RESCALE_G = 28
TANGENTIAL_MINDLIN_FORCE_RESCALE_G = 28
TANGENTIAL_CONTACT_RADIUS_SPRING_K = 28
TANGENTIAL_MINDLIN_UNLOADING_G = 28
GEOMETRY_STAND_IN_SPHERE_RADIUS = 29
GEOMETRY_PAIR_CENTRES_LESS_RADIUS = 29
GEOMETRY_PAIR_R1 = 30
GEOMETRY_PAIR_R2 = 31
GEOMETRY_PAIR_INV_I1 = 32
GEOMETRY_PAIR_INV_I2 = 33
GEOMETRY_PAIR_W2 = 34
GEOMETRY_PAIR_VECTOR_CENTRES_LESS_RADIUS = 29
GEOMETRY_PAIR_VECTOR_R1 = 30
GEOMETRY_PAIR_VECTOR_R2 = 31
GEOMETRY_PAIR_VECTOR_INV_I1 = 32
GEOMETRY_PAIR_VECTOR_INV_I2 = 33
GEOMETRY_PAIR_VECTOR_W2 = 34

NORMAL_BLOCK, NORMAL_BLOCK_END = 24, 28
END_BLOCK, END_BLOCK_END = 28, 28
TANGENTIAL_BLOCK, TANGENTIAL_BLOCK_END = 28, 29
INTEGRATOR_BLOCK, INTEGRATOR_BLOCK_END = 29, 29
COULOMB_BLOCK, COULOMB_BLOCK_END = 29, 29
GEOMETRY_BLOCK, GEOMETRY_BLOCK_END = 29, 35
TOUCH_BLOCK, TOUCH_BLOCK_END = 35, 35
BLOCKS = {'normal': 24, 'end': 28, 'tangential': 28, 'integrator': 29, 'coulomb': 29, 'geometry': 29, 'touch': 35}
N_PARAMS = 35

I_NORMAL = 0
I_END = 1
I_TANGENTIAL = 2
I_INTEGRATOR = 3
I_COULOMB = 4
I_GEOMETRY = 5
I_TOUCH = 6
I_STEPPER = 7    # the row's stepper (submodels/stepping.py STEPPERS)
N_INTS = 8
