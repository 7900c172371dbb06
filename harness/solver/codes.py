"""What the kernels write back: the output columns of a row and its statuses (the parameter and integer columns
are the generated layout.py; the sub-models' codes the generated dispatch.py)."""

# outputs
O_VZ, O_VX, O_W, O_TC, O_FMAX, O_AMAX, O_STEPS, O_STATUS = 0, 1, 2, 3, 4, 5, 6, 7
O_ACCEPTED = 8              # adaptive integrator: accepted steps (O_STEPS counts its force evaluations)
O_STICKING = 9              # kernel: steps ending with |F_t| strictly inside the Coulomb cone (F_n > 0) or on its
                            # other side from the step before (a dashpot can carry it across); adaptive:
                            # stick phases begun, first touch included (an implicit spring: one more, never on it)
O_ALPHA, O_X, O_Z = 10, 11, 12   # kernel: the last state's overlap and position (for the free flight after it)
N_OUT = 13

STATUS_OK = 0
STATUS_NO_SEPARATION = 1
STATUS_NONFINITE = 2
