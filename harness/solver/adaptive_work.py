"""The adaptive integrator's work arrays, allocated by the caller so that nothing it compiles allocates (or counts
references), a row's views of them as one record (Work), and the element copies it makes between them (a slice
assignment would compile numba's shape-error message)."""
from collections import namedtuple

import numpy as np
from numba import njit

from ..infra.jit import compiled
from .contact_ode import N_AUX, N_EVENTS, N_MODE, N_Y
from .steppers import STAGES

VECTORS = (9, N_Y, N_MODE, N_Y, N_Y, N_Y, N_AUX, N_AUX, N_EVENTS, N_EVENTS, N_EVENTS, 2)   # Work's vectors' lengths
VECTOR_ENDS = tuple(int(x) for x in np.cumsum(VECTORS))


def work_arrays(rows):
    """Zeroed work arrays of `rows` impacts, allocated here so that nothing compiled allocates: the vectors (one row
    of VECTORS each), the stage rates, the implicit stepper's work rows, Jacobians, LU factors and pivots."""
    return (np.zeros((rows, VECTOR_ENDS[-1])), np.zeros((rows, STAGES, N_Y)), np.zeros((rows, 9, N_Y)),
            np.zeros((rows, 3, 3, N_Y, N_Y)), np.zeros((rows, N_Y, N_Y)), np.zeros((rows, N_Y), dtype=np.int64))


Work = namedtuple("Work", (
    "scale", "y", "mode", "y_new", "stage", "dy", "aux", "aux_new", "g_start", "g_end", "g", "spring",   # vectors
    "k", "rows", "jac", "lu", "pivot"))     # stage rates, the implicit stepper's work rows, Jacobians, LU, pivots


@njit(cache=True, inline="always")
def row_work(vec, k, rows, jac, lu, pivot):
    """One row's Work: its vectors (scale, y, mode, y_new, stage, dy, aux, aux_new, g_start, g_end, g, spring:
    views of its row of VECTORS) and its other work arrays."""
    e = VECTOR_ENDS
    return Work(vec[0:e[0]], vec[e[0]:e[1]], vec[e[1]:e[2]], vec[e[2]:e[3]], vec[e[3]:e[4]], vec[e[4]:e[5]],
                vec[e[5]:e[6]], vec[e[6]:e[7]], vec[e[7]:e[8]], vec[e[8]:e[9]], vec[e[9]:e[10]], vec[e[10]:e[11]],
                k, rows, jac, lu, pivot)


@compiled
def copy_into(target, source):
    """target[:] = source, element by element."""
    for i in range(len(target)):
        target[i] = source[i]
