"""The stepping sub-models of a law, each by name with the code the compiled steppers dispatch on: the integrator
(time stepping), the Coulomb rule (what the friction cap bounds), the geometry (what moves and how the normal and
the shear history follow) and the touch rule (whether a sphere placed at gap 0 is in contact); which (integrator,
geometry) pairs a stepper implements (docs/design.md)."""
from dataclasses import dataclass


@dataclass(frozen=True)
class Stepping:
    """One choice of a stepping field: `name` (what --with takes), `code` (what the kernels dispatch on), and what it
    computes."""
    family: str
    name: str
    code: int
    summary: str
    pair: bool = False          # geometry: two spheres in their relative motion (the pair steppers' parameters)
    brief: str = ""             # what it does in a few words, where its name does not say it


INTEGRATOR_PAPER, INTEGRATOR_VELOCITY_VERLET, INTEGRATOR_LEAPFROG = 0, 1, 2
COULOMB_SPRING, COULOMB_TOTAL, COULOMB_TOTAL_CASES, COULOMB_SPRING_FIRST = 0, 1, 2, 3
GEOMETRY_WALL, GEOMETRY_STAND_IN_SPHERE, GEOMETRY_PAIR, GEOMETRY_PAIR_VECTOR = 0, 1, 2, 3
TOUCH_GAP, TOUCH_OVERLAP = 0, 1

INTEGRATORS = (
    Stepping("integrator", "paper", INTEGRATOR_PAPER,
             "second-order splitting on u = m alpha_dot + D(alpha), release and regime changes located in the step"),
    Stepping("integrator", "velocity-verlet", INTEGRATOR_VELOCITY_VERLET,
             "half kick, drift, forces from the half-step velocities, half kick; release at the step"),
    Stepping("integrator", "leapfrog", INTEGRATOR_LEAPFROG,
             "forces at x(t) from v(t - h/2), then v(t + h/2), then x(t + h); contact while the overlap is >= 0"),
)
COULOMB_RULES = (
    Stepping("coulomb", "spring-first", COULOMB_SPRING_FIRST,
             "the spring tested alone: beyond mu |F_n| it is capped and is the whole force; below it the tangential "
             "dashpot is added and the sum clipped to mu |F_n| (the paper's; its scheme's dashpot option 'total' "
             "holds the spring within the cone first)", brief="spring first, then spring + dashpot clipped"),
    Stepping("coulomb", "spring", COULOMB_SPRING,
             "the spring capped at mu |F_n|; the tangential dashpot added only below the cap, the sum not clipped",
             brief="tangential dashpot unclipped"),
    Stepping("coulomb", "total", COULOMB_TOTAL,
             "spring plus dashpot capped together at mu |F_n|; a capped total leaves the spring F_t + c_t V_s",
             brief="spring + dashpot clipped together"),
    Stepping("coulomb", "total-cases", COULOMB_TOTAL_CASES,
             "spring plus dashpot capped together at mu |F_n|; a spring beyond mu |F_n| on the total's side is cut to "
             "it (the dashpot dropped), else the dashpot alone is shortened and the spring kept",
             brief="spring + dashpot clipped by four cases"),
)
GEOMETRIES = (
    Stepping("geometry", "wall", GEOMETRY_WALL, "a sphere against a flat wall: the normal fixed, scalar shear"),
    Stepping("geometry", "stand-in-sphere", GEOMETRY_STAND_IN_SPHERE,
             "a fixed sphere of the normal model's stand-in radius plays the wall: overlap from the centres, the "
             "normal turning, the shear vector turned with it, forces at the middle of the overlap"),
    Stepping("geometry", "pair", GEOMETRY_PAIR,
             "two spheres in their relative motion, the normal turning; scalar shear kept along the tangent", True),
    Stepping("geometry", "pair-vector", GEOMETRY_PAIR_VECTOR,
             "two spheres in their relative motion, the normal turning; the shear vector turned with the normal",
             True),
)
TOUCHES = (
    Stepping("touch", "gap", TOUCH_GAP,
             "contact from gap 0: a sphere placed touching feels the force of zero overlap before its first step (a "
             "constant normal dashpot's -c_n v_n; the velocity-Verlet wall's tangential dashpot, -c_t V_s)"),
    Stepping("touch", "overlap", TOUCH_OVERLAP,
             "contact from overlap > 0: no force before the first step; the first kick is force-free"),
)

STEPPERS = {      # (integrator, geometry) -> the stepper that computes it (solver/switches.py) and its Coulomb rules
    ("paper", "wall"): ("PAPER", ("spring-first",)),
    ("velocity-verlet", "wall"): ("VELOCITY_VERLET", ("spring", "total", "spring-first")),
    ("leapfrog", "wall"): ("LEAPFROG", ("spring", "total", "total-cases", "spring-first")),
    ("leapfrog", "stand-in-sphere"): ("LEAPFROG_SPHERE", ("spring",)),
    ("velocity-verlet", "pair"): ("VERLET_PAIR", ("spring", "total", "spring-first")),
    ("leapfrog", "pair-vector"): ("LEAPFROG_PAIR", ("spring",)),
    ("leapfrog", "pair"): ("LEAPFROG_SCALAR_PAIR", ("spring", "total", "total-cases", "spring-first")),
}
TOUCH_STEPPERS = {("velocity-verlet", "wall"): ("gap", "overlap"), ("leapfrog", "wall"): ("gap", "overlap"),
                  ("leapfrog", "pair"): ("gap", "overlap")}     # the others apply 'gap' only
