"""What each family of compiled sub-models declares, and the check that refuses a module lacking it.

Every kernel module, whatever its family, declares NAME (what a law names it by), SUMMARY (one line of what it
computes), SLOTS (the names of its parameters, each a column of the kernel rows) and its family's capabilities, and
defines the family's dispatch points as compiled functions whose first parameters are its SLOTS, in order.
generate.py writes, from these declarations, the codes, the column layout and one dispatch function per point."""
import inspect
from dataclasses import dataclass

from ..infra.errors import UserError

REQUIRED = object()        # a capability a module must declare


@dataclass(frozen=True)
class Point:
    """A dispatch point: its arguments after the slots, what a module without it returns in the dispatch (None: an
    error value, NaN; 'None': the point returns nothing), and whether it takes the module's slots."""
    name: str
    arguments: str
    default: str | None = None
    slotted: bool = True


@dataclass(frozen=True)
class Family:
    """A family of kernel modules: its dispatch points, its capabilities {NAME: (type, default or REQUIRED)}, the
    most slots a module may declare, and the points a module must define (`required(module)`)."""
    name: str
    points: tuple
    capabilities: dict
    max_slots: int
    required: object          # module -> {point it must define: why, '' or a note}

    def point(self, name):
        return next(p for p in self.points if p.name == name)


def normal_required(m):
    """An incremental law defines `step` (and HISTORY_RESET), any other `force`; ADAPTIVE requires force and slope
    (the adaptive integrator's: without them --converged would fall back to the slower ladder)."""
    needed = {"step": ""} if hasattr(m, "step") or hasattr(m, "HISTORY_RESET") else {"force": ""}
    if getattr(m, "ADAPTIVE", False) is True:
        needed.setdefault("force", " (ADAPTIVE)")
        needed["slope"] = " (ADAPTIVE)"
    return needed


def tangential_required(m):
    """`stiffness`; a spring (not VISCOUS) `spring`; an IMPLICIT one its four event points."""
    needed = ["stiffness"] + ([] if getattr(m, "VISCOUS", False) else ["spring"])
    return {n: "" for n in needed} | {n: " (IMPLICIT)" for n in ("force_from_w", "w_from_force", "edge_w", "onset_w")
                                      if getattr(m, "IMPLICIT", False)}


NORMAL = Family("normal", (
    Point("force", "radius, alpha, alpha_max"),
    Point("below", "alpha", "0.0"),
    Point("slope", "radius, alpha, loading, f, a"),
    Point("residual", "radius, alpha_max", "0.0"),
    Point("kink", "", "0.0"),
    Point("step", "radius, alpha, alpha_old, f_old, alpha_max, history, new_history"),
), {"ADAPTIVE": (bool, REQUIRED), "HISTORY_RESET": (tuple, ())}, 4, normal_required)

TANGENTIAL = Family("tangential", (
    Point("stiffness", "a", "math.nan"),
    Point("spring", "f_s, dd, a_mid, a, a_old, mu, n_new, n_old, st, scratch, midpoint", "math.nan"),
    Point("after_cap", "f_s, a, st", "None"),
    Point("force_from_w", "d, star, cone, w", "math.nan", slotted=False),
    Point("w_from_force", "d, star, cone, f_s", "math.nan", slotted=False),
    Point("edge_w", "d, star, sign", "math.nan", slotted=False),
    Point("onset_w", "v_s, rise", "math.nan"),
), {"ADAPTIVE": (bool, False), "VISCOUS": (bool, False), "IMPLICIT": (bool, False), "LOG_RATE": (int, 0)}, 1,
    tangential_required)

COULOMB = Family("coulomb", (
    Point("cap", "f_s, damping, k_t, slip, limit", "math.nan, math.nan, False"),
    Point("first_touch", "f_d, limit", "f_d"),
), {"BRIEF": (str, "")}, 4, lambda m: {"cap": ""})

END = Family("end", (Point("clip", "f_n", "math.nan"),), {"PULLS": (bool, REQUIRED)}, 4, lambda m: {"clip": ""})

TOUCH = Family("touch", (Point("contact", "alpha", "False"),), {}, 4, lambda m: {"contact": ""})

GEOMETRY = Family("geometry", (), {"TWO_SPHERES": (bool, False), "ADAPTIVE": (bool, False)}, 8, lambda m: {})

INTEGRATOR = Family("integrator", (), {"EXPLICIT": (bool, REQUIRED), "EVENTS": (bool, False),
                                       "ADAPTIVE": (bool, False)}, 4, lambda m: {})

FAMILIES = {f.name: f for f in (NORMAL, END, TANGENTIAL, INTEGRATOR, COULOMB, GEOMETRY, TOUCH)}
STEPPING = ("end", "integrator", "coulomb", "geometry", "touch")   # their slots come from the module's parameters()


def leading_parameters(function, count):
    """The names of a compiled (or plain) function's first `count` parameters."""
    python = getattr(function, "py_func", function)
    return tuple(inspect.signature(python).parameters)[:count]


def problems_of(family, m):
    """What module `m` lacks to be a kernel of `family` (empty when it is complete)."""
    problems = [f"constant {c}" for c, kind in (("NAME", str), ("SUMMARY", str), ("SLOTS", tuple))
                if not isinstance(getattr(m, c, None), kind)]
    problems += [f"constant {c} ({kind.__name__})" for c, (kind, default) in family.capabilities.items()
                 if (default is REQUIRED and not hasattr(m, c)) or (hasattr(m, c) and type(getattr(m, c)) is not kind)]
    slots = getattr(m, "SLOTS", ())
    if isinstance(slots, tuple) and (len(slots) > family.max_slots or len(set(slots)) != len(slots)
                                     or not all(isinstance(s, str) and s.isidentifier() for s in slots)):
        problems.append(f"SLOTS as at most {family.max_slots} distinct names, got {slots!r}")
    if "HISTORY_RESET" in family.capabilities and hasattr(m, "step") and not hasattr(m, "HISTORY_RESET"):
        problems.append("constant HISTORY_RESET (its history at first touch)")
    problems += [f"function {n}{note}" for n, note in family.required(m).items() if not callable(getattr(m, n, None))]
    if isinstance(slots, tuple) and not problems:
        for point in family.points:
            function = getattr(m, point.name, None)
            if function is not None and not callable(function):
                problems.append(f"function {point.name} (defined but not callable)")
            elif function is not None and point.slotted and leading_parameters(function, len(slots)) != slots:
                problems.append(f"function {point.name} taking its SLOTS {', '.join(slots) or '()'} first")
    if family.name in STEPPING and slots and not callable(getattr(m, "parameters", None)):
        problems.append("function parameters(law, scene) (its SLOTS' values)")
    return problems


def check_module(family, m, module):
    """Refuse module `m` (named `module`) as a kernel of `family` with one line naming what it lacks."""
    problems = problems_of(family, m)
    if problems:
        raise UserError(f"{family.name} kernel module {module} lacks {', '.join(problems)}")
