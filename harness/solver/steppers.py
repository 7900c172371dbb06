"""One step on the contact ODE, and the step's interpolant: an explicit Runge-Kutta pair (Dormand-Prince 5(4)) or,
for Walton-Braun's stiff tangential spring, an L-stable singly diagonally implicit one (SDIRK4(3))."""
import math

import numpy as np
from numba import njit

from ..infra.jit import compiled
from . import layout as L
from .contact_ode import A_FN, M_TANGENTIAL, N_Y, STICK, Y_ALPHA, Y_FS, coulomb_cone, evaluate, spring_w_of
from .dispatch import TANGENTIAL_IMPLICIT

# Dormand-Prince 5(4) (the ODE is autonomous: no nodes needed): stage coefficients, whose last row holds the
# fifth-order weights (FSAL), and the error weights b - b* of the embedded fourth-order solution
DP_A = np.array([
    [0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    [1.0 / 5.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    [3.0 / 40.0, 9.0 / 40.0, 0.0, 0.0, 0.0, 0.0],
    [44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0, 0.0, 0.0, 0.0],
    [19372.0 / 6561.0, -25360.0 / 2187.0, 64448.0 / 6561.0, -212.0 / 729.0, 0.0, 0.0],
    [9017.0 / 3168.0, -355.0 / 33.0, 46732.0 / 5247.0, 49.0 / 176.0, -5103.0 / 18656.0, 0.0],
    [35.0 / 384.0, 0.0, 500.0 / 1113.0, 125.0 / 192.0, -2187.0 / 6784.0, 11.0 / 84.0]])
DP_E = np.array([71.0 / 57600.0, 0.0, -71.0 / 16695.0, 71.0 / 1920.0, -17253.0 / 339200.0, 22.0 / 525.0,
                 -1.0 / 40.0])
STAGES = 7

@compiled
def dp_step(p, ints, y, mode, h, k, y_new, stage, aux, scale, tol, ext):
    """One Dormand-Prince step of length h from y (k[0] = dy/dt at y) into y_new, k[6] = dy/dt at y_new (FSAL),
    aux the forces at y_new; returns the error norm: max over components of |error| / (tol x its scale)."""
    for s in range(1, STAGES):
        for i in range(N_Y):
            acc = 0.0
            for j in range(s):
                acc += DP_A[s, j] * k[j, i]
            stage[i] = y[i] + h * acc
        evaluate(p, ints, stage, mode, math.nan, k[s], aux, ext)
    for i in range(N_Y):
        y_new[i] = stage[i]                           # the last stage is the fifth-order solution (FSAL)
    err = 0.0
    for i in range(N_Y):
        e = 0.0
        for j in range(STAGES):
            e += DP_E[j] * k[j, i]
        e = abs(h * e) / (tol * scale[4 + i])
        if not e <= err:
            err = e if e == e else math.inf
    return err


@compiled
def hermite(y, y_end, f_start, f_end, h, theta, out):
    """State at step fraction theta on the cubic Hermite interpolant of the step (values and rates at both ends)."""
    h00, h10 = (1.0 + 2.0 * theta) * (1.0 - theta) ** 2, theta * (1.0 - theta) ** 2
    h01, h11 = theta * theta * (3.0 - 2.0 * theta), theta * theta * (theta - 1.0)
    for i in range(N_Y):
        out[i] = h00 * y[i] + h10 * h * f_start[i] + h01 * y_end[i] + h11 * h * f_end[i]


# SDIRK4(3) of Hairer & Wanner (Solving ODEs II, IV.6, "SDIRK4"): gamma = 1/4, L-stable, stiffly accurate (the last
# stage is the fourth-order solution); SD_E = b - b^ against the embedded third-order weights
SD_GAMMA = 0.25
SD_A = np.array([
    [0.25, 0.0, 0.0, 0.0, 0.0],
    [0.5, 0.25, 0.0, 0.0, 0.0],
    [17.0 / 50.0, -1.0 / 25.0, 0.25, 0.0, 0.0],
    [371.0 / 1360.0, -137.0 / 2720.0, 15.0 / 544.0, 0.25, 0.0],
    [25.0 / 24.0, -49.0 / 48.0, 125.0 / 16.0, -85.0 / 12.0, 0.25]])
SD_E = np.array([-9.0 / 48.0, -81.0 / 96.0, 25.0 / 32.0, 0.0, 0.25])
SD_STAGES = 5
NEWTON_ITERATIONS = 10
NEWTON_SHARE = 1e-2         # a stage is solved when its equation's residual is below this share of the tolerance
NEWTON_ROUND_OFF = 1e-13    # ... or at round-off (relative to each component's scale)
JACOBIAN_STEP = 1e-7        # finite-difference step, relative to each unknown's scale
W_SCALE = 1.0               # scale of w = x^(1/3), which lies in [0, 2^(1/3)]
W_SWITCH = 0.5              # w below which the implicit step solves for w rather than F_s (x^(1/3)' <= 4/3 above)
MAX_REFRESHES = 3           # new Jacobians per step where Newton stalls, before the step is shortened
J_START, J_END, J_NOW = 0, 1, 2     # Jacobians kept: at the step's start, at its end, where Newton stalled


@njit(cache=True, inline="always")
def solves_for_w(ints, mode, y, w):
    """The stage unknowns hold w in place of F_s: Walton-Braun's spring while it sticks near the cone (w below
    W_SWITCH, where F_s' ~ x^(1/3) has a steep slope) or from first touch (mu N = 0: F_s does not tell x). Away
    from the cone F_s itself is the unknown: there F_s = -d mu N (1 - (1 - d sigma*) w^3) would tie F_s's
    precision to mu N's, lost as mu N -> 0 at the release."""
    return (TANGENTIAL_IMPLICIT[ints[L.I_TANGENTIAL]] and mode[M_TANGENTIAL] == STICK
            and (w < W_SWITCH or y[Y_ALPHA] <= 0.0))


@compiled
def state_of(p, ints, z, mode, use_w, y, dy, aux, ext):
    """y = Phi(z) and dy/dt there: z is y, with w = x^(1/3) in place of F_s if use_w."""
    for i in range(N_Y):
        y[i] = z[i]
    evaluate(p, ints, y, mode, z[Y_FS] if use_w else math.nan, dy, aux, ext)


@compiled
def lu_factor(a, pivot):
    """In-place LU factorisation with partial pivoting of the small square matrix a; a zero pivot (an unknown the
    equations do not see, e.g. w where N = 0 and V_s = 0) is left for lu_solve to skip."""
    n = a.shape[0]
    for col in range(n):
        best = col
        for row in range(col + 1, n):
            if abs(a[row, col]) > abs(a[best, col]):
                best = row
        pivot[col] = best
        if best != col:
            for j in range(n):
                a[col, j], a[best, j] = a[best, j], a[col, j]
        if a[col, col] == 0.0:
            continue
        for row in range(col + 1, n):
            factor = a[row, col] / a[col, col]
            a[row, col] = factor
            for j in range(col + 1, n):
                a[row, j] -= factor * a[col, j]


@compiled
def lu_solve(a, pivot, b):
    """Solve in place with lu_factor's result; a zero pivot's unknown is set to 0."""
    n = a.shape[0]
    for col in range(n):                              # the row swaps first, in order (lu_factor swapped whole rows,
        b[col], b[pivot[col]] = b[pivot[col]], b[col]  # multipliers included), then the unit lower triangle
    for col in range(n):
        for row in range(col + 1, n):
            b[row] -= a[row, col] * b[col]
    for col in range(n - 1, -1, -1):
        acc = b[col]
        for j in range(col + 1, n):
            acc -= a[col, j] * b[j]
        b[col] = acc / a[col, col] if a[col, col] != 0.0 else 0.0


@compiled
def jacobian(p, ints, z, mode, use_w, scale, d_phi, d_rate, work, aux, ext):
    """dPhi/dz and d(f o Phi)/dz at z by forward differences; returns the evaluations spent."""
    base_y, base_f, ys, fs, zz = work[6], work[7], work[2], work[5], work[8]
    state_of(p, ints, z, mode, use_w, base_y, base_f, aux, ext)
    for j in range(N_Y):
        size = JACOBIAN_STEP * max(abs(z[j]), W_SCALE if j == Y_FS and use_w else scale[4 + j])
        for i in range(N_Y):
            zz[i] = z[i]
        zz[j] += size
        state_of(p, ints, zz, mode, use_w, ys, fs, aux, ext)
        for i in range(N_Y):
            d_phi[i, j] = (ys[i] - base_y[i]) / size
            d_rate[i, j] = (fs[i] - base_f[i]) / size
    return N_Y + 1


@compiled
def newton_matrix(jac, which, hg, newton, pivot):
    """LU factors of dPhi/dz - h gamma d(f o Phi)/dz from Jacobian `which`."""
    for i in range(N_Y):
        for j in range(N_Y):
            newton[i, j] = jac[which, 0, i, j] - hg * jac[which, 1, i, j]
    lu_factor(newton, pivot)


@compiled
def sdirk_step(p, ints, y, w, mode, h, k, y_new, work, jac, lu, pivot, aux, scale, tol, spring, ext):
    """One SDIRK4(3) step of length h from y (k[0] = dy/dt at y; w its Walton-Braun spring's x^(1/3)) into
    y_new, k[1..5] the stage rates, k[6] = dy/dt at y_new, spring[0] = w at y_new. Each stage is solved by
    simplified Newton on z (y, with w in place of F_s near the cone: solves_for_w), with the Jacobian at the
    step's start (jac[J_START], taken if jac[J_START, 2, 0, 0] is not 1) or, where Newton stalls, at its iterate;
    a stage is solved when the residual of its equation is within a share of the tolerance. The error estimate is
    filtered by (I - h gamma J)^-1 (Hairer & Wanner IV.8), which keeps it meaningful for the stiff spring, with J
    at the step's end (jac[J_END], the next step's start), where F_s sees w again if mu N started at 0. Returns
    (error norm as dp_step's, or inf if Newton fails; evaluations)."""
    z0, z, ys, base, dz, fs = work[0], work[1], work[2], work[3], work[4], work[5]
    use_w = solves_for_w(ints, mode, y, w)
    for i in range(N_Y):
        z0[i] = y[i]
    if use_w:
        z0[Y_FS] = w
    evaluations = 0
    hg = h * SD_GAMMA
    if jac[J_START, 2, 0, 0] != 1.0 or jac[J_START, 2, 0, 1] != use_w:
        evaluations += jacobian(p, ints, z0, mode, use_w, scale, jac[J_START, 0], jac[J_START, 1], work, aux, ext)
        jac[J_START, 2, 0, 0], jac[J_START, 2, 0, 1] = 1.0, use_w
        if use_w and aux[A_FN] == 0.0:                        # first touch: F_s is blind to w where mu N = 0,
            for i in range(N_Y):                              # so the Jacobian is taken a first stage ahead
                z[i] = z0[i] + (hg * k[0, i] if i != Y_FS else 0.0)
            evaluations += jacobian(p, ints, z, mode, use_w, scale, jac[J_START, 0], jac[J_START, 1], work, aux, ext)
            jac[J_START, 2, 0, 0] = 0.0                       # (for this step length only)
    newton_matrix(jac, J_START, hg, lu, pivot)
    refreshes = 0
    for i in range(N_Y):
        z[i] = z0[i]
    for s in range(SD_STAGES):
        for i in range(N_Y):
            acc = 0.0
            for j in range(s):
                acc += SD_A[s, j] * k[1 + j, i]
            base[i] = y[i] + h * acc
        last = math.inf
        solved = False
        iteration = 0
        while iteration < NEWTON_ITERATIONS:
            iteration += 1
            state_of(p, ints, z, mode, use_w, ys, fs, aux, ext)
            evaluations += 1
            size = 0.0
            for i in range(N_Y):
                dz[i] = -(ys[i] - base[i] - hg * fs[i])
                size = max(size, abs(dz[i]) / (tol * scale[4 + i]))
            if not size < math.inf:
                return math.inf, evaluations
            if iteration > 1 and (size <= NEWTON_SHARE or size * tol <= NEWTON_ROUND_OFF):
                solved = True                         # (after one correction at least: the guess's own residual,
                break                                 # h gamma f, can be below the tolerance on a short step)
            if size > last or iteration == NEWTON_ITERATIONS:    # stalling: a Jacobian where the stage is
                if refreshes == MAX_REFRESHES:
                    return math.inf, evaluations
                refreshes += 1
                evaluations += jacobian(p, ints, z, mode, use_w, scale, jac[J_NOW, 0], jac[J_NOW, 1], work, aux, ext)
                newton_matrix(jac, J_NOW, hg, lu, pivot)
                last, iteration = math.inf, 0
                continue
            last = size
            lu_solve(lu, pivot, dz)
            for i in range(N_Y):
                z[i] += dz[i]
        if not solved:
            return math.inf, evaluations
        for i in range(N_Y):                          # the stage's rate from its equation (exact for stiff parts)
            k[1 + s, i] = (ys[i] - base[i]) / hg
    for i in range(N_Y):
        y_new[i] = ys[i]
        k[6, i] = fs[i]
    spring[0] = z[Y_FS] if use_w else spring_w_of(ints[L.I_TANGENTIAL], y_new, mode, coulomb_cone(p, ints, aux[A_FN]))
    evaluations += jacobian(p, ints, z, mode, use_w, scale, jac[J_END, 0], jac[J_END, 1], work, aux, ext)
    jac[J_END, 2, 0, 0], jac[J_END, 2, 0, 1] = 1.0, use_w
    newton_matrix(jac, J_END, hg, lu, pivot)
    for i in range(N_Y):
        acc = 0.0
        for j in range(SD_STAGES):
            acc += SD_E[j] * k[1 + j, i]
        dz[i] = h * acc
    lu_solve(lu, pivot, dz)
    err = 0.0
    for i in range(N_Y):
        e = 0.0
        for j in range(N_Y):
            e += jac[J_END, 0, i, j] * dz[j]
        e = abs(e) / (tol * scale[4 + i])
        if not e <= err:
            err = e if e == e else math.inf
    return err, evaluations
