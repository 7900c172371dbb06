"""One step of each integrator: the paper scheme (velocity Verlet on the normal momentum u = m alpha_dot + D(alpha),
linearised implicit-midpoint drift, second order and unconditionally stable in the dashpot), velocity Verlet with
forces from the half-step velocities, leapfrog, and leapfrog against a stand-in sphere, each step_<stepper>
(switches.py dispatches on them); and the first-touch forces of the paper and velocity-Verlet steppers,
first_touch_<stepper>."""
import math

from numba import njit

from ..infra.jit import compiled
from ..submodels.coulomb import clip
from ..submodels.integrator.paper import drift
from ..submodels.tangential.state import N_TSTATE, T_HELD
from ..submodels.tangential.viscous import friction as viscous_friction
from . import layout as L
from .dispatch import (END_PULLS, NORMAL_HISTORY, TANGENTIAL_NONE, TANGENTIAL_VISCOUS, coulomb_first_touch, end_clip,
                       normal_force, normal_kink, normal_step, tangential_stiffness, touch_contact)
from .friction import dashpot_with_share, friction, slip_velocity, tangential_update
from .state import (N_STATE, S_ALPHA, S_AMAX, S_C, S_FEL, S_FN, S_FS, S_FT, S_HISTORY, S_NOLD, S_NX, S_NZ, S_SX,
                    S_SZ, S_U, S_VX, S_VZ, S_W, S_X, S_Z, reset_history)

ONSET_OVERLAP = 1e-12     # overlap, in units of V_n dt, at which first touch's friction is judged


@compiled
def damping_power(alpha, power):
    """alpha^p for the dashpot exponents in use (0, 1/4, 1/2) without the cost of a general pow."""
    if power == 0.0:
        return 1.0
    if power == 0.5:
        return math.sqrt(alpha)
    if power == 0.25:
        return math.sqrt(math.sqrt(alpha))
    return alpha ** power


@compiled
def step_leapfrog(s, st, o, ot, p, ints, h, scratch, ext):
    """Leapfrog: forces from the overlap at x(t) and the half-step velocities v(t - h/2), then
    v(t + h/2) = v(t - h/2) + h F/m and x(t + h) = x(t) + h v(t + h/2). A contact exists while the overlap is
    >= 0 (a sphere placed touching starts in contact with zero force; with touch 'overlap' no force acts until the
    overlap is > 0); the first step with a negative overlap applies no force and ends it (returns -1)."""
    m, inertia, radius, g = p[L.MASS], p[L.INERTIA], p[L.RADIUS], p[L.GRAVITY]
    alpha = s[S_ALPHA]
    amax = s[S_AMAX] if s[S_AMAX] > alpha else alpha
    touching = alpha >= 0.0
    in_contact = touch_contact(ints[L.I_TOUCH], p, alpha)
    f_n, a = 0.0, 0.0
    for k in range(NORMAL_HISTORY):
        o[S_HISTORY + k] = s[S_HISTORY + k]
    if in_contact:                                    # from overlap 0: a constant dashpot acts at first touch
        f_el, a = normal_step(ints[L.I_NORMAL], p, radius, alpha, s[S_ALPHA], s[S_FEL], amax,
                              s[S_HISTORY:S_HISTORY + NORMAL_HISTORY], o[S_HISTORY:S_HISTORY + NORMAL_HISTORY], ext)
        c = p[L.DAMPING_C0] * damping_power(alpha, p[L.DAMPING_POWER]) if p[L.DAMPING_C0] != 0.0 else 0.0
        f_n = end_clip(ints[L.I_END], p, f_el - c * s[S_VZ])
    for k in range(N_TSTATE):
        ot[k] = st[k]
    code = ints[L.I_TANGENTIAL]
    f_t, f_s = 0.0, 0.0
    lever = radius - p[L.LEVER] * alpha
    if code != TANGENTIAL_NONE:
        slip = slip_velocity(p, alpha, s[S_VX], s[S_W], lever)
        f_t, f_s = friction(s, ot, p, ints, code, h, scratch, alpha, a, f_n, slip, in_contact, False, lever)
    vz = s[S_VZ] + h * (f_n / m - g)
    o[S_VZ], o[S_FN], o[S_AMAX] = vz, f_n, amax
    o[S_VX] = s[S_VX] + h * f_t / m
    o[S_W] = s[S_W] - h * lever * f_t / inertia
    o[S_FT], o[S_FS], o[S_NOLD] = f_t, f_s, abs(f_n)
    o[S_ALPHA] = alpha - h * vz
    return 1.0 if touching else -1.0


@compiled
def step_paper(s, st, o, ot, p, ints, h, scratch, ext):
    """Advance state (s, st) by h into (o, ot); returns the end-of-contact indicator (contact while > 0).

    Normal direction in u = m alpha_dot + D(alpha), u' = -F_el(alpha) + m g (Strang splitting: kick, midpoint
    drift, kick), which stays second order although c(alpha) = c0 alpha^p is singular at first touch.
    """
    m, radius, g = p[L.MASS], p[L.RADIUS], p[L.GRAVITY]
    c0, power = p[L.DAMPING_C0], p[L.DAMPING_POWER]
    u_shift = -0.5 * h * (s[S_FEL] - m * g)
    alpha = drift(s[S_ALPHA], -s[S_VZ] + u_shift / m, 0.5 * h * s[S_C] / m, h)
    amax = s[S_AMAX]
    c, d_pot = 0.0, 0.0
    if alpha > 0.0:
        f_el, a = normal_force(ints[L.I_NORMAL], p, radius, alpha, amax, ext)
        if c0 != 0.0:
            q = damping_power(alpha, power)
            c, d_pot = c0 * q, c0 * alpha * q / (power + 1.0)
    else:
        f_el, a = 0.0, 0.0
    u = s[S_U] + u_shift - 0.5 * h * (f_el - m * g)
    alpha_dot = (u - d_pot) / m
    f_n = f_el + c * alpha_dot
    indicator = alpha
    tension = END_PULLS[ints[L.I_END]]
    if alpha > 0.0 and not tension:
        indicator = f_n if f_n < alpha else alpha
    if alpha <= 0.0:
        f_n = 0.0
    o[S_ALPHA], o[S_VZ], o[S_FN], o[S_U], o[S_FEL], o[S_C] = alpha, -alpha_dot, f_n, u, f_el, c
    o[S_AMAX] = alpha if alpha > amax else amax
    tangential_update(s, st, o, ot, p, ints, h, scratch, alpha, a, f_n, f_n > 0.0 or (alpha > 0.0 and tension), True)
    return indicator


@compiled
def step_velocity_verlet(s, st, o, ot, p, ints, h, scratch, ext):
    """Velocity Verlet against a wall: half kick, drift, forces from the half-step velocities, half kick.

    The normal dashpot and the tangential increment see v(t + h/2); the tangential dashpot follows the Coulomb rule
    (friction.friction); the contact ends at the first step with alpha <= 0.
    """
    m, radius, g = p[L.MASS], p[L.RADIUS], p[L.GRAVITY]
    vz_half = s[S_VZ] + 0.5 * h * (s[S_FN] / m - g)
    alpha = s[S_ALPHA] - h * vz_half
    amax = s[S_AMAX]
    f_n, f_el, a = 0.0, 0.0, 0.0
    reset_history(ints[L.I_NORMAL], o)                      # history cleared when out of contact
    if alpha > 0.0:
        f_el, a = normal_step(ints[L.I_NORMAL], p, radius, alpha, s[S_ALPHA], s[S_FEL], amax,
                              s[S_HISTORY:S_HISTORY + NORMAL_HISTORY], o[S_HISTORY:S_HISTORY + NORMAL_HISTORY], ext)
        c = p[L.DAMPING_C0] * damping_power(alpha, p[L.DAMPING_POWER]) if p[L.DAMPING_C0] != 0.0 else 0.0
        f_n = end_clip(ints[L.I_END], p, f_el - c * vz_half)
    o[S_ALPHA], o[S_VZ], o[S_FN], o[S_FEL] = alpha, vz_half + 0.5 * h * (f_n / m - g), f_n, f_el
    o[S_AMAX] = alpha if alpha > amax else amax
    tangential_update(s, st, o, ot, p, ints, h, scratch, alpha, a, f_n, alpha > 0.0, False)
    return alpha


@compiled
def step_leapfrog_sphere(s, st, o, ot, p, ints, h, scratch, ext):
    """Leapfrog against a fixed sphere of radius R_big standing in for the wall (geometry stand-in-sphere): overlap
    (R_big + R) - |x2 - x1|, normal along x2 - x1, contact point in the middle of the overlap, shear force rotated
    with the normal (S -= S x (n_old x n)), forces and torque from the contact-point branch."""
    m, inertia, radius, big = p[L.MASS], p[L.INERTIA], p[L.RADIUS], p[L.GEOMETRY_STAND_IN_SPHERE_RADIUS]
    dx, dz = s[S_X], s[S_Z] + big
    norm = math.sqrt(dx * dx + 0.0 + dz * dz)
    delt = (big + radius) - norm
    for k in range(N_STATE):
        o[k] = s[k]
    if delt < 0.0:                                    # contact over: no force this step, history erased
        fx, fz, torque = 0.0, 0.0, 0.0
        in_contact = False
    else:
        in_contact = True
        nx, nz = dx / norm, dz / norm
        if s[S_NX] != 0.0 or s[S_NZ] != 0.0:          # shear turned about n_old x n (no twist in-plane)
            axis = s[S_NZ] * nx - s[S_NX] * nz        # y component of n_old x n
            sx, sz = s[S_SX], s[S_SZ]
            sx, sz = sx + axis * sz, sz - axis * sx
        else:
            sx, sz = 0.0, 0.0
        f_hys, _ = normal_step(ints[L.I_NORMAL], p, radius, delt, s[S_ALPHA], s[S_FEL], s[S_AMAX],
                               s[S_HISTORY:S_HISTORY + NORMAL_HISTORY], o[S_HISTORY:S_HISTORY + NORMAL_HISTORY], ext)
        reach = big - 0.5 * delt                      # contact point: big sphere centre + reach n
        cx, cz = reach * nx - s[S_X], (-big + reach * nz) - s[S_Z]
        wy = s[S_W]
        rvx, rvz = -(s[S_VX] + wy * cz), -(s[S_VZ] - wy * cx)
        vn = nx * rvx + nz * rvz
        svx, svz = rvx - vn * nx, rvz - vn * nz
        k_s = p[L.TANGENTIAL_LINEAR_K_T]          # a linear shear spring (0 where no tangential model runs)
        sx, sz = sx + k_s * h * svx, sz + k_s * h * svz
        g0 = p[L.DAMPING_C0]
        normal = f_hys + g0 * vn
        max_fs = normal * normal * p[L.MU] * p[L.MU]
        visc_x, visc_z = 0.0, 0.0
        if sx * sx + sz * sz > max_fs:
            ratio = math.sqrt(max_fs) / math.sqrt(sx * sx + sz * sz)
            sx, sz = sx * ratio, sz * ratio
        else:
            visc_x, visc_z = g0 * svx, g0 * svz
        fx = normal * nx + sx + visc_x
        fz = normal * nz + sz + visc_z
        torque = cz * fx - cx * fz
        o[S_NX], o[S_NZ], o[S_SX], o[S_SZ] = nx, nz, sx, sz
        o[S_FN] = normal
    if not in_contact:
        o[S_NX], o[S_NZ], o[S_SX], o[S_SZ], o[S_FN] = 0.0, 0.0, 0.0, 0.0, 0.0
    o[S_VX] = s[S_VX] + h * fx / m
    o[S_VZ] = s[S_VZ] + h * fz / m
    o[S_W] = s[S_W] + h * torque / inertia
    o[S_X] = s[S_X] + h * o[S_VX]
    o[S_Z] = s[S_Z] + h * o[S_VZ]
    o[S_ALPHA] = delt
    for k in range(N_TSTATE):
        ot[k] = st[k]
    return 1.0 if in_contact else -1.0


@njit(cache=True, inline="always")
def loading_kink(p, ints, ext):
    """Overlap at which the loading curve bends (yield of Stronge and Thornton, d_lim of the peak-limited hysteresis);
    0 for the smooth curves."""
    return normal_kink(ints[L.I_NORMAL], p, ext)


@compiled
def first_touch_paper(s, st, p, ints, ext):
    """The paper scheme's tangential force at first touch with a tangential dashpot: -c_t V_s capped by mu F_n
    (finite where both start finite: a constant normal dashpot and a constant k_t), and whether spring and dashpot
    start on the Coulomb cone, judged at a tiny overlap where both rise from 0 (Tsuji's c ~ alpha^1/4 against
    Mindlin's c_t ~ alpha^1/4): a contact that slides from first touch starts with margin 0 and gets the exact
    friction impulse (sliding_kick) from its first step, where the trapezoid of a force ~ t^p loses an order."""
    code, radius, mu = ints[L.I_TANGENTIAL], p[L.RADIUS], p[L.MU]
    if p[L.TANGENTIAL_DAMPING_PREFACTOR] == 0.0 or code == TANGENTIAL_NONE or TANGENTIAL_VISCOUS[code]:
        return
    slip0 = p[L.VX0] - radius * p[L.W0]
    v_n = -p[L.VZ0]
    s[S_FT] = clip(-p[L.TANGENTIAL_DAMPING_PREFACTOR] * math.sqrt(tangential_stiffness(code, p, 0.0)) * slip0,
                   mu * abs(s[S_FN]))
    alpha = ONSET_OVERLAP * v_n * p[L.DT]
    f_el, a = normal_force(ints[L.I_NORMAL], p, radius, alpha, alpha, ext)
    f_n = f_el + p[L.DAMPING_C0] * damping_power(alpha, p[L.DAMPING_POWER]) * v_n
    if p[L.TANGENTIAL_DAMPING_PREFACTOR] * math.sqrt(tangential_stiffness(code, p, a)) * abs(slip0) > mu * f_n:
        st[T_HELD] = 0.0


@compiled
def first_touch_velocity_verlet(s, st, p, ints, ext):
    """Velocity Verlet against a wall, where the touch rule puts a sphere at gap 0 in contact: the setup force,
    the tangential dashpot alone on its empty spring, as the Coulomb rule takes it at first touch (coulomb
    first_touch; viscous friction capped at mu |F_n|)."""
    code = ints[L.I_TANGENTIAL]
    if code == TANGENTIAL_NONE or not touch_contact(ints[L.I_TOUCH], p, 0.0):
        return
    slip0 = p[L.VX0] - p[L.RADIUS] * p[L.W0]
    limit = p[L.MU] * abs(s[S_FN])
    damping = p[L.TANGENTIAL_DAMPING_PREFACTOR]
    shared = p[L.TANGENTIAL_DAMPING_SHARE] != 0.0      # c_t = prefactor sqrt(k_t) + share c_n(0)
    if TANGENTIAL_VISCOUS[code] and shared:
        s[S_FT] = viscous_friction(1.0, dashpot_with_share(p, code, 0.0, 0.0), slip0, limit)
    elif TANGENTIAL_VISCOUS[code]:
        s[S_FT] = viscous_friction(tangential_stiffness(code, p, 0.0), damping, slip0, limit)
    elif shared:
        s[S_FT] = coulomb_first_touch(ints[L.I_COULOMB], p, -dashpot_with_share(p, code, 0.0, 0.0) * slip0, limit)
    else:
        s[S_FT] = coulomb_first_touch(ints[L.I_COULOMB], p,
                                      -damping * math.sqrt(tangential_stiffness(code, p, 0.0)) * slip0, limit)
