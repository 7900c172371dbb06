"""The scene kinds: one registration table (SCENES) of what each scene takes, the effects it needs and the closed
forms a run of it must reproduce."""
import math
from dataclasses import dataclass
from numbers import Integral, Real

from ..infra.errors import UserError
from . import closed_forms

EFFECT_WORDS = ("gravity", "several-contacts", "long-contact", "wall", "pair")   # what a scene may ask a simulation for


@dataclass(frozen=True)
class Parameter:
    """A scene's parameter: its name, default, unit ('-' when it has none), meaning and the values it takes (a
    number kind with its bounds, or the choices)."""
    name: str
    default: object
    unit: str
    meaning: str
    kind: type = float
    low: float | None = None
    high: float | None = None
    low_open: bool = False
    choices: tuple = ()

    def allowed(self):
        """The values the parameter takes, in words."""
        if self.choices:
            return "one of " + ", ".join(str(c) for c in self.choices)
        kind = "an integer" if self.kind is int else "a number"
        low = "" if self.low is None else f"{'>' if self.low_open else '>='} {self.low:g}"
        high = "" if self.high is None else f"<= {self.high:{'d' if self.kind is int else 'g'}}"
        return kind + (" " + " and ".join(b for b in (low, high) if b) if low or high else "")

    def checked(self, scene, value):
        """The value if the parameter takes it, else a UserError naming the scene, the parameter and what it takes."""
        if self.choices:
            good = value in self.choices and type(value) is type(self.default)
        elif self.kind is int:
            good = isinstance(value, Integral) and not isinstance(value, bool) and self.within(value)
        else:
            good = (isinstance(value, Real) and not isinstance(value, bool) and math.isfinite(value)
                    and self.within(value))
        if not good:
            raise UserError(f"scene {scene}: {self.name} = {value!r} is not {self.allowed()}")
        return value

    def within(self, value):
        above = self.low is None or (value > self.low if self.low_open else value >= self.low)
        return above and (self.high is None or value <= self.high)


@dataclass(frozen=True)
class Check:
    """A closed-form check: the quantity a run is measured on, the closed form giving what it must be, the tolerance
    (relative to the expected value, or absolute) and the source the closed form comes from."""
    name: str
    quantity: str
    closed_form: object
    tolerance: float
    relative: bool
    source: str

    @property
    def equation(self):
        """The closed form's equation: its docstring up to the first colon."""
        return self.closed_form.__doc__.split(":", 1)[0]


@dataclass(frozen=True)
class SceneKind:
    """A scene kind: NAME, a one-line SUMMARY, its PARAMETERS, the EFFECTS it needs (every one a run of it may need,
    where a parameter chooses among them: EFFECTS_CHOSEN), its CHECKS and whether a command RUNS it yet."""
    NAME: str
    SUMMARY: str
    PARAMETERS: tuple
    EFFECTS: frozenset
    CHECKS: tuple
    RUNS: bool = False

    def values(self, given=None):
        """Every parameter's value: the defaults, replaced by those `given` ({name: value}), each checked."""
        given = dict(given or {})
        known = {p.name: p for p in self.PARAMETERS}
        unknown = sorted(set(given) - set(known))
        if unknown:
            takes = ", ".join(known) or "no parameters"
            raise UserError(f"scene {self.NAME} has no parameter {unknown[0]} (it takes {takes})")
        values = {name: p.checked(self.NAME, given.get(name, p.default)) for name, p in known.items()}
        for rule in RULES.get(self.NAME, ()):
            rule(values)
        return values

    def effects(self, values):
        """The effects a run of this scene with these parameter values needs: EFFECTS, or fewer where a value
        chooses among them."""
        if self.NAME not in EFFECTS_CHOSEN:
            return self.EFFECTS
        parameter, effects = EFFECTS_CHOSEN[self.NAME]
        return effects[values[parameter]]


def only_between_two_walls(values):
    """A preload needs a top wall to press with it."""
    if values["preload"] and values["walls"] != 2:
        raise UserError(f"scene stack: preload = {values['preload']!r} needs walls = 2 (a top wall to press with)")


RULES = {"stack": (only_between_two_walls,)}   # checks across a scene's parameters, after each one's own
# scene: (the parameter that chooses among its effects, {that parameter's value: the effects a run needs})
EFFECTS_CHOSEN = {"impact": ("target", {"wall": frozenset({"wall"}), "sphere": frozenset({"pair"})})}

GRAVITY = Parameter("g", 9.81, "m/s^2", "gravitational acceleration, pointing down (along the wall's normal)", low=0.0,
                    low_open=True)
NEWTON = "Newton's second law"

SCENES = {kind.NAME: kind for kind in (
    SceneKind("impact", "a sphere hits a wall or a sphere once, from first touch to separation (the paper's scene, "
              "which --en, --angles, --speed and the other scene options set)",
              (Parameter("target", "wall", "-", "what the sphere hits", kind=str, choices=("wall", "sphere")),),
              frozenset({"wall", "pair"}), (), RUNS=True),
    SceneKind("free-fall", "a sphere in flight under gravity, touching nothing",
              (Parameter("height", 0.1, "m", "starting height of the sphere's centre"),
               Parameter("v0", 0.0, "m/s", "starting vertical speed, up positive"),
               Parameter("duration", 0.1, "s", "time simulated", low=0.0, low_open=True), GRAVITY),
              frozenset({"gravity"}),
              (Check("height", "z(t), the centre's height", closed_forms.free_fall_height, 1e-9, True, NEWTON),),
              RUNS=True),
    SceneKind("bounce", "a sphere dropped on a wall, bouncing a stated number of times",
              (Parameter("height", 0.1, "m", "drop height of the sphere's lowest point above the wall", low=0.0,
                         low_open=True),
               Parameter("bounces", 3, "-", "number of bounces simulated", kind=int, low=1, high=1000), GRAVITY),
              frozenset({"gravity", "wall"}),
              (Check("rebound-speed-ratio", "v_(k+1)/v_k, rebound over incident speed of each bounce "
                                            "(linear spring-dashpot laws)",
                     closed_forms.linear_bounce_restitution, 1e-3, False,
                     "Schaefer, Dippel & Wolf 1996"),
               Check("apex-height", "h_k, the height of the k-th apex above the wall (linear spring-dashpot laws)",
                     closed_forms.linear_bounce_apex, 1e-2, True, "Newton 1687")),
              RUNS=True),
    SceneKind("slide-to-roll", "a sphere set sliding (and spinning) on a wall under gravity until it rolls",
              (Parameter("v0", 1.0, "m/s", "starting speed along the wall"),
               Parameter("w0", 0.0, "rad/s", "starting spin, positive in the sense of rolling with v0"), GRAVITY),
              frozenset({"gravity", "wall", "long-contact"}),
              (Check("slip-end-time", "t_s, when the contact point stops slipping", closed_forms.slip_end_time,
                     1e-2, True, "Routh 1905"),
               Check("rolling-speed", "v_f, the speed once rolling", closed_forms.rolling_speed, 1e-2, True,
                     "Routh 1905")), RUNS=True),
    SceneKind("rest", "a sphere settled on a wall under gravity and held for a stated number of steps",
              (Parameter("steps", 1_000_000, "-", "steps held at rest after settling", kind=int, low=1, high=10 ** 9),
               GRAVITY),
              frozenset({"gravity", "wall", "long-contact"}),
              (Check("hertz-static-overlap", "delta, the overlap at rest (Hertz normal laws)",
                     closed_forms.hertz_static_overlap, 1e-3, True, "Johnson 1985"),
               Check("linear-static-overlap", "delta, the overlap at rest (linear normal laws)",
                     closed_forms.linear_static_overlap, 1e-3, True, "Hooke's law")), RUNS=True),
    SceneKind("stack", "a column of equal spheres at rest on a wall, or between two walls, under gravity",
              (Parameter("spheres", 3, "-", "number of spheres in the column", kind=int, low=2, high=100),
               Parameter("walls", 1, "-", "walls: 1 below the column, 2 below and above it", kind=int,
                         choices=(1, 2)),
               Parameter("preload", 0.0, "N", "force the top wall presses on the column with (walls = 2 only)",
                         low=0.0),
               GRAVITY),
              frozenset({"gravity", "wall", "pair", "several-contacts", "long-contact"}),
              (Check("contact-force", "F_i, the force in the contact below the i-th sphere from the top",
                     closed_forms.stack_contact_force, 1e-3, True, "Newton's first law"),), RUNS=True),
)}


def scene_kind(name):
    """The scene kind called `name`, or a UserError listing the scenes."""
    if name not in SCENES:
        raise UserError(f"unknown scene {name!r} (scenes: {', '.join(SCENES)})")
    return SCENES[name]
