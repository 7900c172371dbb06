"""One step of an explicit Runge-Kutta pair on the contact ODE, and the step's interpolant."""
import math

import numpy as np
from numba import njit

from .contact_ode import N_Y, evaluate

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

@njit(cache=True)
def dp_step(p, ints, y, mode, h, k, y_new, stage, aux, scale, tol):
    """One Dormand-Prince step of length h from y (k[0] = dy/dt at y) into y_new, k[6] = dy/dt at y_new (FSAL),
    aux the forces at y_new; returns the error norm: max over components of |error| / (tol x its scale)."""
    for s in range(1, STAGES):
        for i in range(N_Y):
            acc = 0.0
            for j in range(s):
                acc += DP_A[s, j] * k[j, i]
            stage[i] = y[i] + h * acc
        evaluate(p, ints, stage, mode, k[s], aux)
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


@njit(cache=True)
def hermite(y, y_end, f_start, f_end, h, theta, out):
    """State at step fraction theta on the cubic Hermite interpolant of the step (values and rates at both ends)."""
    h00, h10 = (1.0 + 2.0 * theta) * (1.0 - theta) ** 2, theta * (1.0 - theta) ** 2
    h01, h11 = theta * theta * (3.0 - 2.0 * theta), theta * theta * (theta - 1.0)
    for i in range(N_Y):
        out[i] = h00 * y[i] + h10 * h * f_start[i] + h01 * y_end[i] + h11 * h * f_end[i]
