"""Which (integrator, geometry) pairs a stepper implements (solver/switches.py), and the Coulomb and touch rules each
applies (docs/design.md). The stepping sub-models themselves are modules of submodels/integrator, coulomb, geometry
and touch, numbered by the registry."""

EVERY = "every registered rule"     # a stepper that applies the Coulomb rule through its dispatch takes every one

STEPPERS = {      # (integrator, geometry) -> the stepper that computes it (solver/switches.py) and its Coulomb rules
    ("paper", "wall"): ("PAPER", ("spring-first",)),
    ("velocity-verlet", "wall"): ("VELOCITY_VERLET", EVERY),
    ("leapfrog", "wall"): ("LEAPFROG", EVERY),
    ("leapfrog", "stand-in-sphere"): ("LEAPFROG_SPHERE", ("spring",)),
    ("velocity-verlet", "pair"): ("VERLET_PAIR", EVERY),
    ("leapfrog", "pair-vector"): ("LEAPFROG_PAIR", ("spring",)),
    ("leapfrog", "pair"): ("LEAPFROG_SCALAR_PAIR", EVERY),
}
TOUCH_STEPPERS = {("velocity-verlet", "wall"): ("gap", "overlap"), ("leapfrog", "wall"): ("gap", "overlap"),
                  ("leapfrog", "pair"): ("gap", "overlap")}     # the others apply 'gap' only
STEPPER_NAMES = tuple(name for name, _ in STEPPERS.values())    # a stepper's code: its place here
