"""Slots of the tangential history every kernel step carries (the springs' own and what event location reads)."""
T_AUX1, T_AUX2, T_MODE, T_DIR, T_AOLD = 0, 1, 2, 3, 4     # xi or T*, T**, mode, direction, a at the step's start
T_MARGIN = 5          # |trial spring force| - mu F_n of the last step (> 0: capped, sliding); read by event location
T_STEP = 6            # length of the last step, to compare margins of steps of unequal length
T_HELD = 7            # the margin of what holds the contact on the cone: T_MARGIN, or in the paper scheme with a
N_TSTATE = 8          # tangential dashpot |spring + dashpot| - mu F_n
