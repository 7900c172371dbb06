"""The state vector of one impact in the compiled integrators: its slots, and an incremental law's history."""
from numba import njit

from .dispatch import N_NORMAL, NORMAL_HISTORY, NORMAL_RESET

S_ALPHA, S_VZ, S_VX, S_W, S_AMAX, S_FN, S_FT, S_FS, S_NOLD, S_U, S_FEL, S_C = 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11
S_HISTORY = 12                               # an incremental normal law's history (NORMAL_HISTORY slots)
S_X = S_HISTORY + NORMAL_HISTORY             # stand-in sphere: position, normal, shear force
S_Z, S_NX, S_NZ, S_SX, S_SZ = S_X + 1, S_X + 2, S_X + 3, S_X + 4, S_X + 5
S_DW2 = S_X + 6                              # two spheres: the change of the target's spin so far
N_STATE = S_X + 7


@njit(cache=True, inline="always")
def reset_history(code, state):
    """An incremental normal law's history at first touch and after a contact (none for the other laws)."""
    if code < N_NORMAL:
        for k in range(NORMAL_HISTORY):
            state[S_HISTORY + k] = NORMAL_RESET[code, k]
