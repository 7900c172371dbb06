"""One contact of a small system, in the x-z plane with spins about y: its geometry (sphere-wall, sphere-sphere),
its forces through the sub-model dispatch (normal force or incremental step, dashpot, end rule, tangential spring
and Coulomb rule: friction.friction), and its history, created at first overlap and cleared at separation.

A contact joins body i and body j (or a wall: j = WALL_BELOW at z = 0, WALL_ABOVE at z = ceiling); its normal n
points from j to i, its tangent is t = (n_z, -n_x), and the slip of i's contact point against j's is
V_s = (v_i - v_j).t - R_i w_i - R_j w_j (a wall: V_s = v_x - R w below). The force on i is F_n n + F_t t, on j its
opposite, and each body's torque is -R F_t."""
import math

from numba import njit

from ..infra.jit import compiled
from ..submodels.tangential.state import N_TSTATE, T_AOLD
from . import layout as L
from .dispatch import NORMAL_HISTORY, TANGENTIAL_NONE, end_clip, normal_step, tangential_stiffness
from .friction import friction
from .schemes import damping_power
from .state import N_STATE, S_ALPHA, S_AMAX, S_FEL, S_FN, S_FS, S_FT, S_HISTORY, S_NOLD, reset_history

B_X, B_Z, B_VX, B_VZ, B_W, B_M, B_I, B_R = 0, 1, 2, 3, 4, 5, 6, 7    # a body's columns
N_BODY = 8
WALL_BELOW, WALL_ABOVE = -1, -2              # a contact's second body, when it is a wall
C_ENERGY = N_STATE                           # a contact's state: the impact state's slots, then the elastic work
N_CONTACT = N_STATE + 1                      # of its normal force so far


@njit(cache=True, inline="always")
def geometry(bodies, i, j, ceiling):
    """(overlap alpha, n_x, n_z) of the contact of body i with body j or a wall."""
    if j == WALL_BELOW:
        return bodies[i, B_R] - bodies[i, B_Z], 0.0, 1.0
    if j == WALL_ABOVE:
        return bodies[i, B_Z] + bodies[i, B_R] - ceiling, 0.0, -1.0
    dx, dz = bodies[i, B_X] - bodies[j, B_X], bodies[i, B_Z] - bodies[j, B_Z]
    d = math.sqrt(dx * dx + dz * dz)
    if d == 0.0:
        return math.nan, 0.0, 1.0
    return bodies[i, B_R] + bodies[j, B_R] - d, dx / d, dz / d


@njit(cache=True, inline="always")
def relative_motion(bodies, i, j, nx, nz, shorter):
    """(d alpha/dt, slip V_s) of body i against body j or a wall, from the bodies' velocities and spins, each spin's
    lever its body's radius less `shorter` (c alpha of a dialect's lever R - c alpha; 0 for the paper's R)."""
    vx, vz, spin = bodies[i, B_VX], bodies[i, B_VZ], (bodies[i, B_R] - shorter) * bodies[i, B_W]
    if j >= 0:
        vx, vz = vx - bodies[j, B_VX], vz - bodies[j, B_VZ]
        spin += (bodies[j, B_R] - shorter) * bodies[j, B_W]
    return -(vx * nx + vz * nz), vx * nz - vz * nx - spin


@compiled
def clear(c, st, code):
    """A contact's history out of contact: its state, its tangential history, its normal law's reset history."""
    for k in range(N_CONTACT):
        c[k] = 0.0
    for k in range(N_TSTATE):
        st[k] = 0.0
    reset_history(code, c)


@compiled
def contact_forces(c, st, ot, p, ints, h, scratch, history, alpha, alpha_rate, slip, ext):
    """(F_n, F_t) of a contact at overlap alpha > 0 approached at d alpha/dt with slip V_s, after a step h: the
    normal force (normal_step: a law's force, or an incremental law's step from the last one), the dashpot
    c0 alpha^p d alpha/dt, the end rule; the tangential force through friction (spring increment V_s h, the law's
    Coulomb rule). Updates the contact's state `c` and tangential history `st` (ot, scratch, history: work)."""
    code = ints[L.I_NORMAL]
    f_el, a = normal_step(code, p, p[L.RADIUS], alpha, c[S_ALPHA], c[S_FEL], c[S_AMAX],
                          c[S_HISTORY:S_HISTORY + NORMAL_HISTORY], history, ext)
    c0 = p[L.DAMPING_C0]
    dashpot = c0 * damping_power(alpha, p[L.DAMPING_POWER]) * alpha_rate if c0 != 0.0 else 0.0
    f_n = end_clip(ints[L.I_END], p, f_el + dashpot)
    f_t, f_s = 0.0, 0.0
    if ints[L.I_TANGENTIAL] != TANGENTIAL_NONE:
        for k in range(N_TSTATE):
            ot[k] = st[k]
        f_t, f_s = friction(c, ot, p, ints, ints[L.I_TANGENTIAL], h, scratch, alpha, a, f_n, slip, True, False,
                            p[L.RADIUS] - p[L.LEVER] * alpha)
        for k in range(N_TSTATE):
            st[k] = ot[k]
    c[C_ENERGY] += 0.5 * (c[S_FEL] + f_el) * (alpha - c[S_ALPHA])
    for k in range(NORMAL_HISTORY):
        c[S_HISTORY + k] = history[k]
    c[S_ALPHA], c[S_FEL], c[S_FN], c[S_FT], c[S_FS], c[S_NOLD] = alpha, f_el, f_n, f_t, f_s, abs(f_n)
    if alpha > c[S_AMAX]:
        c[S_AMAX] = alpha
    return f_n, f_t


@compiled
def stored_energy(c, st, p, ints):
    """Energy a contact holds: the elastic work of its normal force (trapezoid over its steps) and its tangential
    spring's F_s^2/(2 k_t) at the last contact radius."""
    energy = c[C_ENERGY]
    code = ints[L.I_TANGENTIAL]
    if code != TANGENTIAL_NONE and c[S_FS] != 0.0:
        k_t = tangential_stiffness(code, p, st[T_AOLD])
        if k_t > 0.0:
            energy += 0.5 * c[S_FS] * c[S_FS] / k_t
    return energy
