"""Two spheres stepped in their relative motion, the normal turning as they pass each other: velocity Verlet or
leapfrog with a scalar shear along the tangent (geometry pair), leapfrog with the shear vector turned with the normal
(geometry pair-vector) (docs/two-spheres.md). Both read the pair geometry's slots (pair-vector's are the same
columns)."""
import math

from numba import njit

from ..infra.jit import compiled
from ..submodels.tangential.state import N_TSTATE, T_STEP
from . import layout as L
from .dispatch import NORMAL_HISTORY, TANGENTIAL_NONE, end_clip, normal_step, tangential_stiffness, touch_contact
from .friction import friction, normal_share
from .schemes import damping_power
from .state import (N_STATE, S_ALPHA, S_AMAX, S_DW2, S_FEL, S_FN, S_FS, S_FT, S_HISTORY, S_NOLD, S_NX, S_NZ, S_SX,
                    S_SZ, S_VX, S_VZ, S_W, S_X, S_Z, reset_history)

# the pair geometry's slots: both radii, inverse inertias (0: a fixed target), the target's spin, R1 + R2 - R*
R1, R2, INV_I1, INV_I2 = L.GEOMETRY_PAIR_R1, L.GEOMETRY_PAIR_R2, L.GEOMETRY_PAIR_INV_I1, L.GEOMETRY_PAIR_INV_I2
W2, OFFSET = L.GEOMETRY_PAIR_W2, L.GEOMETRY_PAIR_CENTRES_LESS_RADIUS


@compiled
def carry_and_spins(s, st, o, ot, p):
    """Copy the state into the step's output; both spins: the target's from its change, the projectile's from the
    equivalent spin w* = (R1 w1 + R2 w2)/R*."""
    for k in range(N_STATE):
        o[k] = s[k]
    for k in range(N_TSTATE):
        ot[k] = st[k]
    w2 = p[W2] + s[S_DW2]
    return (p[L.RADIUS] * s[S_W] - p[R2] * w2) / p[R1], w2


@njit(cache=True, inline="always")
def pair_forces(s, ot, o, p, ints, h, scratch, ext, alpha, amax, nx, nz, vx, vz, w1, w2):
    """In contact along n: the normal force (dashpot on u.n, clipped at 0 without tension) and the tangential force
    from the slip u.t - (l1 w1 + l2 w2), t = (n_z, -n_x), l_i = R_i - lever d, by the law's Coulomb rule
    (friction.friction). Returns (F_n, F_t, F_s, F_el)."""
    radius = p[L.RADIUS]
    f_el, a = normal_step(ints[L.I_NORMAL], p, radius, alpha, s[S_ALPHA], s[S_FEL], amax,
                          s[S_HISTORY:S_HISTORY + NORMAL_HISTORY], o[S_HISTORY:S_HISTORY + NORMAL_HISTORY], ext)
    c = p[L.DAMPING_C0] * damping_power(alpha, p[L.DAMPING_POWER]) if p[L.DAMPING_C0] != 0.0 else 0.0
    f_n = end_clip(ints[L.I_END], p, f_el - c * (vx * nx + vz * nz))
    f_t, f_s = 0.0, 0.0
    code = ints[L.I_TANGENTIAL]
    if code != TANGENTIAL_NONE:
        c_slip = p[L.LEVER]
        slip = (vx * nz - vz * nx) - ((p[R1] - c_slip * alpha) * w1 + (p[R2] - c_slip * alpha) * w2)
        f_t, f_s = friction(s, ot, p, ints, code, h, scratch, alpha, a, f_n, slip, True, False, radius)
    return f_n, f_t, f_s, f_el


@compiled
def step_verlet_pair(s, st, o, ot, p, ints, h, scratch, ext):
    """Velocity Verlet on both spheres, as the relative motion
    r = x1 - x2 (mass m*) and each sphere's spin (the projectile's from the equivalent spin w* = (R1 w1 + R2 w2)/R*,
    the target's from its change): half kicks with the last force, drift, then from r the overlap R1 + R2 - |r| and
    the normal n = r/|r|, which turns as the spheres pass each other; slip u.t - (l1 w1 + l2 w2) along t = (n_z, -n_x)
    with levers l_i = R_i - lever d, torques -(R_i - torque d) F_t on each; the tangential history kept along t at
    its length; the law's Coulomb rule (friction.friction); contact while the overlap is > 0. Returns the overlap."""
    m, radius = p[L.MASS], p[L.RADIUS]
    r1, r2, inv1, inv2 = p[R1], p[R2], p[INV_I1], p[INV_I2]
    c_torque = p[L.TORQUE_LEVER]
    centres = radius + p[OFFSET]
    w1, w2 = carry_and_spins(s, st, o, ot, p)
    vx = s[S_VX] + 0.5 * h * (s[S_FN] * s[S_NX] + s[S_FT] * s[S_NZ]) / m
    vz = s[S_VZ] + 0.5 * h * (s[S_FN] * s[S_NZ] - s[S_FT] * s[S_NX]) / m
    w1 -= 0.5 * h * (r1 - c_torque * s[S_ALPHA]) * s[S_FT] * inv1
    w2 -= 0.5 * h * (r2 - c_torque * s[S_ALPHA]) * s[S_FT] * inv2
    x, z = s[S_X] + h * vx, s[S_Z] + h * vz
    dist = math.sqrt(x * x + (z + p[OFFSET]) * (z + p[OFFSET]))
    alpha = centres - dist
    amax = s[S_AMAX]
    f_n, f_t, f_s, f_el, nx, nz = 0.0, 0.0, 0.0, 0.0, 0.0, 0.0
    reset_history(ints[L.I_NORMAL], o)
    if alpha > 0.0:
        nx, nz = x / dist, (z + p[OFFSET]) / dist
        f_n, f_t, f_s, f_el = pair_forces(s, ot, o, p, ints, h, scratch, ext, alpha, amax, nx, nz, vx, vz, w1, w2)
    else:
        for k in range(N_TSTATE):
            ot[k] = 0.0
    w1 -= 0.5 * h * (r1 - c_torque * alpha) * f_t * inv1
    w2 -= 0.5 * h * (r2 - c_torque * alpha) * f_t * inv2
    o[S_VX] = vx + 0.5 * h * (f_n * nx + f_t * nz) / m
    o[S_VZ] = vz + 0.5 * h * (f_n * nz - f_t * nx) / m
    o[S_W], o[S_DW2] = (r1 * w1 + r2 * w2) / radius, w2 - p[W2]
    o[S_X], o[S_Z], o[S_ALPHA], o[S_AMAX] = x, z, alpha, alpha if alpha > amax else amax
    o[S_FN], o[S_FT], o[S_FS], o[S_FEL], o[S_NOLD], o[S_NX], o[S_NZ] = f_n, f_t, f_s, f_el, abs(f_n), nx, nz
    ot[T_STEP] = h
    return alpha


@njit(cache=True, inline="always")
def leapfrog_kick_drift(s, o, p, h, fx, fz, torque, w1, w2, x, alpha, amax):
    """The leapfrog's closing half: u += h F/m*, spins -= h (R_i - torque d) T/I_i, r += h u, into the output."""
    m = p[L.MASS]
    vx, vz = s[S_VX] + h * fx / m, s[S_VZ] + h * fz / m
    c_torque = p[L.TORQUE_LEVER]
    w1 -= h * (p[R1] - c_torque * alpha) * torque * p[INV_I1]
    w2 -= h * (p[R2] - c_torque * alpha) * torque * p[INV_I2]
    o[S_VX], o[S_VZ] = vx, vz
    o[S_X], o[S_Z] = x + h * vx, s[S_Z] + h * vz
    o[S_W], o[S_DW2] = (p[R1] * w1 + p[R2] * w2) / p[L.RADIUS], w2 - p[W2]
    o[S_ALPHA], o[S_AMAX] = alpha, amax


@compiled
def step_leapfrog_pair(s, st, o, ot, p, ints, h, scratch, ext):
    """Leapfrog on both spheres with the shear force a vector turned with the normal, as the relative motion
    r = x1 - x2 (mass m*) and each sphere's spin: forces at r(t) from the half-step velocities, then u += h F/m*,
    spins += h T_i/I_i, r += h u. Overlap d = R1 + R2 - |r|, normal n = r/|r|; the normal dashpot
    sees u.n, the slip noRatch's alpha_f u.t - (R1 w1 + R2 w2) along t = (n_z, -n_x) with
    alpha_f = (R1 + R2)/(R1 + R2 - d); the shear force is a vector in the plane, turned with the normal
    (S -= S x (n_old x n)) and incremented by -k_s slip h t (k_s not reduced as it falls); normal force
    clipped at 0, the spring capped at mu F_n, else the dashpot -c_s slip t added; torques -(R_i - d/2) (n x F)_y on
    each. Contact while d >= 0; the first negative overlap applies no force and ends it (returns -1)."""
    radius = p[L.RADIUS]
    r1, r2 = p[R1], p[R2]
    c_slip = p[L.LEVER]
    centres = radius + p[OFFSET]
    w1, w2 = carry_and_spins(s, st, o, ot, p)
    vx, vz = s[S_VX], s[S_VZ]
    x, z = s[S_X], s[S_Z] + p[OFFSET]
    dist = math.sqrt(x * x + z * z)
    alpha = centres - dist
    amax = s[S_AMAX] if s[S_AMAX] > alpha else alpha
    f_n, f_t, f_el, sx, sz, nx, nz, torque = 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0
    fx, fz = 0.0, 0.0
    in_contact = alpha >= 0.0
    if in_contact:
        nx, nz = x / dist, z / dist
        if s[S_NX] != 0.0 or s[S_NZ] != 0.0:
            axis = s[S_NZ] * nx - s[S_NX] * nz            # y component of n_old x n
            sx, sz = s[S_SX] + axis * s[S_SZ], s[S_SZ] - axis * s[S_SX]
        f_el, a = normal_step(ints[L.I_NORMAL], p, radius, alpha, s[S_ALPHA], s[S_FEL], amax,
                              s[S_HISTORY:S_HISTORY + NORMAL_HISTORY], o[S_HISTORY:S_HISTORY + NORMAL_HISTORY], ext)
        noratch = 1.0 if p[L.SLIP_RADIUS] == 0.0 else (p[L.SLIP_RADIUS] + radius) / (p[L.SLIP_RADIUS] + radius - alpha)
        c = p[L.DAMPING_C0] * damping_power(alpha, p[L.DAMPING_POWER]) if p[L.DAMPING_C0] != 0.0 else 0.0
        f_n = end_clip(ints[L.I_END], p, f_el - c * (vx * nx + vz * nz))
        code = ints[L.I_TANGENTIAL]
        tx, tz = nz, -nx
        if code != TANGENTIAL_NONE:
            slip = noratch * (vx * tx + vz * tz) - ((r1 - c_slip * alpha) * w1 + (r2 - c_slip * alpha) * w2)
            k_s = tangential_stiffness(code, p, a)
            sx, sz = sx - k_s * slip * h * tx, sz - k_s * slip * h * tz
            limit = p[L.MU] * abs(f_n)
            if sx * sx + sz * sz > limit * limit:
                ratio = limit / math.sqrt(sx * sx + sz * sz)
                sx, sz = sx * ratio, sz * ratio
                fx, fz = sx, sz
            else:
                damping = p[L.TANGENTIAL_DAMPING_PREFACTOR]
                c_s = damping * math.sqrt(k_s) if damping != 0.0 else 0.0
                if p[L.TANGENTIAL_DAMPING_SHARE] != 0.0:
                    c_s += normal_share(p, alpha)
                fx, fz = sx - c_s * slip * tx, sz - c_s * slip * tz
            torque = nz * fx - nx * fz                    # (n x F)_y: the normal force has no moment
            f_t = fx * tx + fz * tz
        fx, fz = fx + f_n * nx, fz + f_n * nz
    else:
        for k in range(N_TSTATE):
            ot[k] = 0.0
        reset_history(ints[L.I_NORMAL], o)
    leapfrog_kick_drift(s, o, p, h, fx, fz, torque, w1, w2, x, alpha, amax)
    o[S_FN], o[S_FT], o[S_FS], o[S_FEL], o[S_NOLD] = f_n, f_t, math.sqrt(sx * sx + sz * sz), f_el, abs(f_n)
    o[S_NX], o[S_NZ], o[S_SX], o[S_SZ] = nx, nz, sx, sz
    ot[T_STEP] = h
    return 1.0 if in_contact else -1.0


@compiled
def step_leapfrog_scalar_pair(s, st, o, ot, p, ints, h, scratch, ext):
    """Leapfrog on both spheres with a scalar shear along the tangent, as the relative motion r = x1 - x2 (mass m*)
    and each sphere's spin: forces at r(t) from the half-step velocities, then u += h F/m*, spins += h T_i/I_i,
    r += h u. Overlap R1 + R2 - |r|, normal n = r/|r|; slip u.t - (l1 w1 + l2 w2) along t = (n_z, -n_x) with levers
    l_i = R_i - lever d, torques -(R_i - torque d) F_t on each; the law's Coulomb rule (friction.friction); contact
    while the overlap is >= 0 (touch 'overlap': forces from overlap > 0); the first negative overlap ends it."""
    radius = p[L.RADIUS]
    w1, w2 = carry_and_spins(s, st, o, ot, p)
    vx, vz = s[S_VX], s[S_VZ]
    x, z = s[S_X], s[S_Z] + p[OFFSET]
    dist = math.sqrt(x * x + z * z)
    alpha = radius + p[OFFSET] - dist
    amax = s[S_AMAX] if s[S_AMAX] > alpha else alpha
    touching = alpha >= 0.0
    in_contact = touch_contact(ints[L.I_TOUCH], p, alpha)
    f_n, f_t, f_s, f_el, nx, nz = 0.0, 0.0, 0.0, 0.0, 0.0, 0.0
    if in_contact:
        nx, nz = x / dist, z / dist
        f_n, f_t, f_s, f_el = pair_forces(s, ot, o, p, ints, h, scratch, ext, alpha, amax, nx, nz, vx, vz, w1, w2)
    else:
        for k in range(N_TSTATE):
            ot[k] = 0.0
        reset_history(ints[L.I_NORMAL], o)
    leapfrog_kick_drift(s, o, p, h, f_n * nx + f_t * nz, f_n * nz - f_t * nx, f_t, w1, w2, x, alpha, amax)
    o[S_FN], o[S_FT], o[S_FS], o[S_FEL], o[S_NOLD], o[S_NX], o[S_NZ] = f_n, f_t, f_s, f_el, abs(f_n), nx, nz
    ot[T_STEP] = h
    return 1.0 if touching else -1.0
