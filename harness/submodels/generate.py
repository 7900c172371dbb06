"""Write, from the registry, the solver's generated modules: layout.py (the columns of a kernel row: the impact's
own, then a block per family in which each kernel's SLOTS take the first columns, named FAMILY_KERNEL_SLOT),
dispatch.py (codes, capability tables and one if-chain per dispatch point, passing each kernel its slots by name;
the default is an error value or the neutral element a point defines, never another law) and switches.py (the
steppers compiled and a row's step by its stepper). Run `python -m harness.submodels.generate` after adding a
module to the registry; tests/test_registry.py fails while a file is out of date."""
import re
import sys
from pathlib import Path

from . import damping, tangential_damping
from .base import N_SLOTS
from .families import FAMILIES
from .registry import BUILT_IN, NORMAL_KERNELS
from .stepping import STEPPER_NAMES

SOLVER = Path(__file__).resolve().parent.parent / "solver"
STEPPER_MODULES = ("schemes", "pair")      # where the steppers are: step_<stepper> for each of STEPPER_NAMES
HEADER = ('"""Generated from harness/submodels/registry.py by `python -m harness.submodels.generate`: do not edit.'
          '\n\n{}\n"""')

OWN = (     # the impact's own columns, before the families' blocks
    ("mass", "the sphere's (or the pair's reduced) mass"), ("inertia", "its moment of inertia"),
    ("radius", "its (or the pair's equivalent) radius R"), ("dt", "the time step"),
    ("gravity", "gravity towards the wall"), ("mu", "the friction coefficient"),
    ("vz0", "incident velocity along the normal (< 0 approaching)"), ("vx0", "incident tangential velocity"),
    ("w0", "initial spin omega_y"), ("max_steps", "the step cap"),
    ("grade_t", "graded steps: their span T (0: uniform steps)"), ("grade_n", "graded steps: how many over T"),
    ("lever", "c of the slip's lever arm R - c alpha (paper 0)"),
    ("torque_lever", "c of the torque's lever R - c alpha (R_i - c alpha between two spheres)"),
    ("slip_radius", "slip form: 0 -> V_t - lever omega; r1 > 0 -> (r1 + R)/(r1 + R - d) V_t - R omega"),
    ("alpha0", "the signed overlap at the row's start: 0 at first touch, < 0 after a free approach (approach.py)"),
    ("x0", "the start's offset along the tangent from the touching position (two spheres, a stand-in sphere)"),
    ("z0", "the start's offset along the normal from the touching position (> 0 apart)"),
    ("first_h", "the first step where it is not dt: the paper scheme's, from the exact touch to the next step (0: dt)"),
)
FORMS = (("damping", damping.SLOTS, ("the normal dashpot c = c0 alpha^power", "")),
         ("tangential_damping", tangential_damping.SLOTS,
          ("the tangential dashpot c_t = prefactor sqrt(k_t) + share c_n(alpha)",
           "the paper scheme's Coulomb test (CONE_CODES)", "a share of the normal dashpot c_n (0: none)")))


def ident(text):
    """A kernel's or slot's name as part of a Python constant: upper case, '-' and ':' as '_'."""
    return re.sub(r"[-:]", "_", text).upper()


def widths():
    """{family: the columns of its block}: its largest SLOTS (normal: room for a kernel registered at run time)."""
    out = {family: max((len(k.slots) for k in BUILT_IN[family]), default=0) for family in FAMILIES}
    out["normal"] = max(out["normal"], N_SLOTS)
    return out


def columns():
    """[(constant, column, comment)] of the layout, and {family: first column}."""
    out, column = [], 0
    for name, comment in OWN:
        out.append((ident(name), column, comment))
        column += 1
    for form, slots, comments in FORMS:
        for slot, comment in zip(slots, comments):
            out.append((f"{ident(form)}_{ident(slot)}", column, comment))
            column += 1
    starts = {}
    for family, width in widths().items():
        starts[family] = column
        for kernel in BUILT_IN[family]:
            for k, slot in enumerate(kernel.slots):
                out.append((f"{ident(family)}_{ident(kernel.name)}_{ident(slot)}", column + k, ""))
        column += width
    return out, starts, column


def layout_source():
    named, starts, total = columns()
    lines = [HEADER.format("The columns of a kernel row (docs/design.md): the impact's own, then each family's block, "
                           "in which a\nkernel's SLOTS take the first columns, named FAMILY_KERNEL_SLOT."), ""]
    lines += [f"{name} = {column}" + (f"    # {comment}" if comment else "") for name, column, comment in named]
    lines += [""] + [f"{ident(f)}_BLOCK, {ident(f)}_BLOCK_END = {starts[f]}, {starts[f] + w}"
                     for f, w in widths().items()]
    lines += [f"BLOCKS = {starts!r}", f"N_PARAMS = {total}", ""]
    lines += [f"I_{ident(f)} = {i}" for i, f in enumerate(FAMILIES)]
    lines += [f"I_STEPPER = {len(FAMILIES)}    # the row's stepper (submodels/stepping.py STEPPERS)",
              f"N_INTS = {len(FAMILIES) + 1}"]
    return "\n".join(lines) + "\n"


def wrapped(head, names):
    """`head` followed by the names, in parentheses over lines of at most 120 columns where they do not fit one."""
    line = head + ", ".join(names)
    if len(line) <= 110:
        return line
    lines, current = [], head + "("
    for name in names:
        if len(current) + len(name) + 2 > 110:
            lines.append(current.rstrip())
            current = " " * (len(head) + 1)
        current += name + ", "
    return "\n".join(lines + [current[:-2] + ")"])


def alias(family, kernel):
    """How the generated module names a kernel's module: its family and module name."""
    return f"{family}_{kernel.module.rpartition('.')[2]}"


def imports(family, kernels):
    """The imports of the kernel modules that define a dispatch point."""
    lines = []
    for kernel in kernels:
        if kernel.module and kernel.functions:
            package, _, module = kernel.module.rpartition(".")
            line = f"from {package.replace('harness.', '..', 1)} import {module} as {alias(family, kernel)}"
            if line not in lines:
                lines.append(line)
    return lines


def slot_arguments(family, kernel):
    return ", ".join(f"p[{ident(family)}_{ident(kernel.name)}_{ident(slot)}]" for slot in kernel.slots)


def call(family, kernel, point, arguments, indent):
    """The call of a kernel's point with its slots read from the row, over lines of at most 120 columns."""
    own = slot_arguments(family, kernel) if point.slotted else ""
    return wrapped_call(f"{alias(family, kernel)}.{point.name}(", ", ".join(a for a in (own, arguments) if a), indent)


def wrapped_call(head, arguments, indent):
    """head + arguments (a string of them, or a list) + ')' after `indent` columns, continued under the parenthesis
    as needed."""
    lines, current = [], head
    for argument in (arguments.split(", ") if isinstance(arguments, str) else arguments):
        if indent + len(current) + len(argument) + 2 > 120 and current != head and not current.endswith("("):
            lines.append(current.rstrip())
            current = " " * len(head)
        current += argument + ", "
    lines.append(current[:-2] + ")")
    return ("\n" + " " * indent).join(lines)


EXTENSION_CALL = {   # how each normal point reaches a kernel registered at run time (solver.extension)
    "force": "FORCE, p[NORMAL_BLOCK:NORMAL_BLOCK_END], radius, alpha, alpha_max, 0.0, 0.0)",
    "below": "BELOW, p[NORMAL_BLOCK:NORMAL_BLOCK_END], 0.0, alpha, 0.0, 0.0, 0.0)[0]",
    "slope": "SLOPE, p[NORMAL_BLOCK:NORMAL_BLOCK_END], radius, alpha, 1.0 if loading else 0.0, f, a)",
    "residual": "RESIDUAL, p[NORMAL_BLOCK:NORMAL_BLOCK_END], radius, 0.0, alpha_max, 0.0, 0.0)[0]",
    "kink": "KINK, p[NORMAL_BLOCK:NORMAL_BLOCK_END], 0.0, 0.0, 0.0, 0.0, 0.0)[0]",
}


def signature(family, point):
    arguments = ", ".join(a for a in (("p" if point.slotted else ""), point.arguments,
                                      ("ext" if family == "normal" else "")) if a)
    return f"def {family}_{point.name}(code, {arguments}):"


def chain(family, point, kernels, only=None):
    """One dispatch function: an if-chain over the kernels that define the point (those whose codes are in `only`,
    when given), then the default."""
    lines = ["@compiled", signature(family, point)]
    returns = point.default != "None"
    for code, kernel in enumerate(kernels):
        if point.name in kernel.functions and kept(code, only):
            head = "return " if returns else ""
            lines += [f"    if code == {code}:",
                      f"        {head}{call(family, kernel, point, point.arguments, 8 + len(head))}"]
            if not returns:
                lines.append("        return")
    if family == "normal" and point.name in EXTENSION_CALL:
        arguments, tail = EXTENSION_CALL[point.name].rsplit(")", 1)
        lines += ["    if code >= N_NORMAL:",        # (the tail's columns counted as an indent)
                  wrapped_call("        return call(", f"ext, code - N_NORMAL, {arguments}", len(tail)) + tail]
    default = {None: "math.nan, math.nan", "None": ""}.get(point.default, point.default)
    lines.append(f"    return {default}".rstrip())
    return "\n".join(lines)


def normal_step(only=None):
    """An incremental law's own step; every other kernel's force, its history untouched."""
    point = FAMILIES["normal"].point("step")
    lines = ["@compiled", signature("normal", point)]
    for code, kernel in enumerate(NORMAL_KERNELS):
        if "step" in kernel.functions and kept(code, only):
            lines += [f"    if code == {code}:", f"        return {call('normal', kernel, point, point.arguments, 15)}"]
    lines.append("    return normal_force(code, p, radius, alpha, alpha_max, ext)")
    return "\n".join(lines)


def kept(code, only):
    return only is None or code in only


def capability_tables(family, kernels):
    """A table per capability (bool or int) of the family, by code."""
    out = []
    for name, (kind, _) in FAMILIES[family].capabilities.items():
        if kind in (bool, int):
            values = ", ".join(repr(getattr(k, name.lower())) for k in kernels)
            dtype = "np.bool_" if kind is bool else "np.int64"
            out.append(wrapped_call(f"{ident(family)}_{name} = np.array([", f"{values}], dtype={dtype}", 0))
    return out


def dispatch_source(normal=None, tangential=None):
    """The dispatch module: every kernel, or only the normal and tangential kernels whose codes are given (the
    codes, tables and defaults unchanged), so that numba types nothing else (solver/specialise.py)."""
    only = {"normal": normal, "tangential": tangential}
    history = max(len(k.history_reset) for k in NORMAL_KERNELS)
    resets = [list(k.history_reset) + [0.0] * (history - len(k.history_reset)) for k in NORMAL_KERNELS]
    used = sorted({f"{ident(f)}_{ident(k.name)}_{ident(s)}" for f, ks in BUILT_IN.items() for k in ks for s in k.slots
                   if any(p.name in k.functions for p in FAMILIES[f].points if p.slotted)})
    parts = [
        HEADER.format("Kernel codes, capability tables and the dispatch of every compiled sub-model function "
                      "(docs/design.md)."),
        "import math\n\nimport numpy as np\n",
        "\n".join(["from ..infra.jit import compiled"]
                  + [line for f, ks in BUILT_IN.items() for line in imports(f, ks)]),
        "from .extension import BELOW, FORCE, KINK, RESIDUAL, SLOPE, call",
        wrapped("from .layout import ", ["NORMAL_BLOCK", "NORMAL_BLOCK_END"] + used) + "  # noqa: F401",
        "",
        f"N_NORMAL = {len(NORMAL_KERNELS)}",
    ]
    for family, kernels in BUILT_IN.items():
        parts.append("\n".join(f"{ident(family)}_{ident(k.name)} = {c}" for c, k in enumerate(kernels)))
        parts += capability_tables(family, kernels)
    defined = re.findall(r"^([A-Z][A-Z0-9_]*) = ", "\n".join(parts), re.M)
    if len(defined) != len(set(defined)):
        raise SystemExit(f"generated constants defined twice: {sorted({d for d in defined if defined.count(d) > 1})}")
    tangential_kernels = BUILT_IN["tangential"]
    parts += [
        f"NORMAL_HISTORY = {history}",
        wrapped_call("NORMAL_RESET = np.array([", [*map(repr, resets[:-1]), f"{resets[-1]!r}], dtype=np.float64"], 0),
        f"NORMAL_INCREMENTAL = {tuple(c for c, k in enumerate(NORMAL_KERNELS) if k.history_reset)!r}",
        f"TANGENTIAL_ANY_IMPLICIT = {any(k.implicit for c, k in enumerate(tangential_kernels) if kept(c, tangential))}"
        "   # numba drops the implicit stepper where False",
        "",
    ]
    for family, kernels in BUILT_IN.items():
        for point in FAMILIES[family].points:
            if point.name != "step":
                parts += ["", chain(family, point, kernels, only.get(family)), ""]
        if family == "normal":
            parts += ["", normal_step(normal), ""]
    return "\n".join(parts).rstrip() + "\n"


def stepper_function(name, prefix="step", required=True):
    """(module, function) of the stepper `name`'s <prefix>_<name> in one of STEPPER_MODULES (None if absent and not
    required)."""
    function = f"{prefix}_{name.lower()}"
    for module in STEPPER_MODULES:
        if re.search(rf"^def {function}\(", (SOLVER / f"{module}.py").read_text(), re.M):
            return module, function
    if required:
        raise SystemExit(f"no function {function} for stepper {name} in solver/{', solver/'.join(STEPPER_MODULES)}")
    return None


def switches_source(stepper=None):
    """switches.py: each stepper's flag (True where this copy compiles it: all, or `stepper` alone), the step of a
    row by its stepper's code, and the first-touch forces of the steppers that have one (first_touch_<stepper>)."""
    steps = [stepper_function(name) for name in STEPPER_NAMES]
    touches = [stepper_function(name, "first_touch", False) for name in STEPPER_NAMES]
    lines = [HEADER.format("The steppers this copy of the solver compiles (a copy specialised to one batch's law, "
                           "specialise.py,\nwrites its own, with that batch's stepper alone, and numba drops the "
                           "branches of the others), a\nrow's step by its stepper's code, and its stepper's forces "
                           "at first touch."),
             "import math\n\nfrom numba import njit\n"]
    for module in STEPPER_MODULES:
        names = sorted(f for m, f in steps + [t for t in touches if t] if m == module)
        if names:
            lines.append(wrapped(f"from .{module} import ", names))
    lines += [""] + [f"{name} = {stepper is None or name == stepper}" for name in STEPPER_NAMES]
    lines += [wrapped_call("STEPPERS = (", ", ".join(map(repr, STEPPER_NAMES)), 0), "", "",
              '@njit(cache=True, inline="always")', "def step_with(stepper, s, st, o, ot, p, ints, h, scratch, ext):",
              '    """Step (s, st) by h into (o, ot) with the row\'s stepper; returns its end-of-contact indicator."""']
    for code, (name, (_, function)) in enumerate(zip(STEPPER_NAMES, steps)):
        lines += [f"    if {name} and stepper == {code}:",
                  f"        return {function}(s, st, o, ot, p, ints, h, scratch, ext)"]
    lines += ["    return math.nan                   # a stepper this copy does not compile (never planned)", "", "",
              '@njit(cache=True, inline="always")', "def first_touch_with(stepper, s, st, p, ints, ext):",
              '    """The forces of a sphere at first touch that its stepper applies before the first step (the state '
              'at\n    first touch, s and st, updated)."""']
    for code, (name, found) in enumerate(zip(STEPPER_NAMES, touches)):
        if found:
            lines += [f"    if {name} and stepper == {code}:", f"        {found[1]}(s, st, p, ints, ext)"]
    return "\n".join(lines) + "\n"


def sources():
    """{file name in solver/: its generated text}."""
    return {"layout.py": layout_source(), "dispatch.py": dispatch_source(), "switches.py": switches_source()}


def main():
    for name, text in sources().items():
        (SOLVER / name).write_text(text)
        print(f"wrote {SOLVER / name}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
