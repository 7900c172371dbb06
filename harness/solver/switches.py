"""The steppers this copy of the solver compiles: every one here; a copy specialised to one batch's law
(specialise.py) writes its own, with that batch's stepper alone, and numba drops the branches of the others."""
PAPER = VELOCITY_VERLET = LEAPFROG = LEAPFROG_SPHERE = VERLET_PAIR = LEAPFROG_PAIR = LEAPFROG_SCALAR_PAIR = True
STEPPERS = ("PAPER", "VELOCITY_VERLET", "LEAPFROG", "LEAPFROG_SPHERE", "VERLET_PAIR", "LEAPFROG_PAIR",
            "LEAPFROG_SCALAR_PAIR")
