"""Generated from harness/submodels/registry.py by `python -m harness.submodels.generate`: do not edit.

The steppers this copy of the solver compiles (a copy specialised to one batch's law, specialise.py,
writes its own, with that batch's stepper alone, and numba drops the branches of the others), a
row's step by its stepper's code, and its stepper's forces at first touch.
"""
import math

from numba import njit

from .schemes import (first_touch_paper, first_touch_velocity_verlet, step_leapfrog, step_leapfrog_sphere,
                      step_paper, step_velocity_verlet)
from .pair import step_leapfrog_pair, step_leapfrog_scalar_pair, step_verlet_pair

PAPER = True
VELOCITY_VERLET = True
LEAPFROG = True
LEAPFROG_SPHERE = True
VERLET_PAIR = True
LEAPFROG_PAIR = True
LEAPFROG_SCALAR_PAIR = True
STEPPERS = ('PAPER', 'VELOCITY_VERLET', 'LEAPFROG', 'LEAPFROG_SPHERE', 'VERLET_PAIR', 'LEAPFROG_PAIR',
            'LEAPFROG_SCALAR_PAIR')


@njit(cache=True, inline="always")
def step_with(stepper, s, st, o, ot, p, ints, h, scratch, ext):
    """Step (s, st) by h into (o, ot) with the row's stepper; returns its end-of-contact indicator."""
    if PAPER and stepper == 0:
        return step_paper(s, st, o, ot, p, ints, h, scratch, ext)
    if VELOCITY_VERLET and stepper == 1:
        return step_velocity_verlet(s, st, o, ot, p, ints, h, scratch, ext)
    if LEAPFROG and stepper == 2:
        return step_leapfrog(s, st, o, ot, p, ints, h, scratch, ext)
    if LEAPFROG_SPHERE and stepper == 3:
        return step_leapfrog_sphere(s, st, o, ot, p, ints, h, scratch, ext)
    if VERLET_PAIR and stepper == 4:
        return step_verlet_pair(s, st, o, ot, p, ints, h, scratch, ext)
    if LEAPFROG_PAIR and stepper == 5:
        return step_leapfrog_pair(s, st, o, ot, p, ints, h, scratch, ext)
    if LEAPFROG_SCALAR_PAIR and stepper == 6:
        return step_leapfrog_scalar_pair(s, st, o, ot, p, ints, h, scratch, ext)
    return math.nan                   # a stepper this copy does not compile (never planned)


@njit(cache=True, inline="always")
def first_touch_with(stepper, s, st, p, ints, ext):
    """The forces of a sphere at first touch that its stepper applies before the first step (the state at
    first touch, s and st, updated)."""
    if PAPER and stepper == 0:
        first_touch_paper(s, st, p, ints, ext)
    if VELOCITY_VERLET and stepper == 1:
        first_touch_velocity_verlet(s, st, p, ints, ext)
