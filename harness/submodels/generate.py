"""Write harness/solver/dispatch.py from the registry: kernel codes, capability tables and one if-chain per dispatch
point whose default is an error value (NaN) or the neutral element a point defines (no force below contact, no
dent, no kink, no history), never another law. Run `python -m harness.submodels.generate` after adding a kernel to
the registry; tests/test_registry.py fails while the file is out of date."""
import sys
from pathlib import Path

from .registry import NORMAL_KERNELS, TANGENTIAL_KERNELS

TARGET = Path(__file__).resolve().parent.parent / "solver" / "dispatch.py"
NAN2 = "math.nan, math.nan"

# dispatch point -> (arguments, what a kernel without it returns: None means an error value)
NORMAL = {
    "force": ("p1, p2, p3, p4, radius, alpha, alpha_max", None),
    "below": ("p1, p2, p3, p4, alpha", "0.0"),
    "slope": ("p1, p2, p3, p4, radius, alpha, loading, f, a", None),
    "residual": ("p1, p2, p3, p4, radius, alpha_max", "0.0"),
    "kink": ("p1, p2, p3, p4", "0.0"),
}
EXTENSION_CALL = {   # how each normal point reaches a kernel registered at run time (solver.extension)
    "force": "FORCE, p1, p2, p3, p4, radius, alpha, alpha_max, 0.0, 0.0)",
    "below": "BELOW, p1, p2, p3, p4, 0.0, alpha, 0.0, 0.0, 0.0)[0]",
    "slope": "SLOPE, p1, p2, p3, p4, radius, alpha, 1.0 if loading else 0.0, f, a)",
    "residual": "RESIDUAL, p1, p2, p3, p4, radius, 0.0, alpha_max, 0.0, 0.0)[0]",
    "kink": "KINK, p1, p2, p3, p4, 0.0, 0.0, 0.0, 0.0, 0.0)[0]",
}
TANGENTIAL = {
    "stiffness": ("p1, a", "math.nan"),
    "spring": ("f_s, dd, a_mid, a, a_old, p1, mu, n_new, n_old, st, scratch, midpoint", "math.nan"),
    "after_cap": ("f_s, p1, a, st", "None"),
    "force_from_w": ("d, star, cone, w", "math.nan"),
    "w_from_force": ("d, star, cone, f_s", "math.nan"),
    "edge_w": ("d, star, sign", "math.nan"),
    "onset_w": ("p1, v_s, rise", "math.nan"),
}


def alias(family, kernel):
    """How the generated module names a kernel's module: its family and module name."""
    return f"{family}_{kernel.module.rpartition('.')[2]}"


def imports(kernels, family):
    lines = []
    for kernel in kernels:
        if kernel.module:
            package, _, module = kernel.module.rpartition(".")
            line = f"from {package.replace('harness.', '..', 1)} import {module} as {alias(family, kernel)}"
            if line not in lines:
                lines.append(line)
    return lines


def chain(name, family, kernels, arguments, default, extension=None, only=None):
    """One dispatch function: an if-chain over the kernels that define `name` (those whose codes are in `only`, when
    given), then the default."""
    decorator = "@compiled"
    tail = ", ext" if family == "normal" else ""
    lines = [decorator, f"def {family}_{name}(code, {arguments}{tail}):"]
    for code, kernel in enumerate(kernels):
        attribute = dict(kernel.functions).get(name)
        if attribute and kept(code, only):
            call = f"{alias(family, kernel)}.{attribute}({arguments})"
            lines.append(f"    if code == {code}:")
            lines.append(f"        {'return ' if default != 'None' else ''}{call}")
            if default == "None":
                lines.append("        return")
    if extension:
        lines.append("    if code >= N_NORMAL:")
        lines.append(f"        return call(ext, code - N_NORMAL, {extension}")
    lines.append(f"    return {NAN2 if default is None else default}" if default != "None" else "    return")
    return "\n".join(lines)


def normal_step(only=None):
    """An incremental law's own step; every other kernel's force, its history untouched."""
    arguments = "p1, p2, p3, p4, radius, alpha, alpha_old, f_old, alpha_max, history, new_history"
    lines = ["@compiled", f"def normal_step(code, {arguments}, ext):"]
    for code, kernel in enumerate(NORMAL_KERNELS):
        if "step" in dict(kernel.functions) and kept(code, only):
            lines += [f"    if code == {code}:", f"        return {alias('normal', kernel)}.step({arguments})"]
    lines.append("    return normal_force(code, p1, p2, p3, p4, radius, alpha, alpha_max, ext)")
    return "\n".join(lines)


def kept(code, only):
    return only is None or code in only


def capability_table(name, values, dtype):
    return f"{name} = np.array({list(values)!r}, dtype=np.{dtype})"


def source(normal=None, tangential=None):
    """The dispatch module: every kernel, or only the normal and tangential kernels whose codes are given (the
    codes, tables and defaults unchanged), so that numba types nothing else (solver/specialise.py)."""
    history = max(len(k.history_reset) for k in NORMAL_KERNELS)
    resets = [list(k.history_reset) + [0.0] * (history - len(k.history_reset)) for k in NORMAL_KERNELS]
    parts = [
        '"""Generated from harness/submodels/registry.py by `python -m harness.submodels.generate`: do not edit.\n\n'
        "Kernel codes, capability tables and the dispatch of every compiled sub-model function (docs/design.md).\n"
        '"""',
        "import math\n\nimport numpy as np\n",
        "\n".join(["from ..jit import compiled"] + imports(NORMAL_KERNELS, "normal")
                  + imports(TANGENTIAL_KERNELS, "tangential")),
        "from .extension import BELOW, FORCE, KINK, RESIDUAL, SLOPE, call",
        "",
        f"N_NORMAL = {len(NORMAL_KERNELS)}",
        "\n".join(f"NORMAL_{k.name.upper().replace('-', '_')} = {c}" for c, k in enumerate(NORMAL_KERNELS)),
        f"NORMAL_HISTORY = {history}",
        f"NORMAL_RESET = np.array({resets!r}, dtype=np.float64)",
        f"NORMAL_INCREMENTAL = {tuple(c for c, k in enumerate(NORMAL_KERNELS) if k.history_reset)!r}",
        "\n".join(f"TANGENTIAL_{k.name.upper().replace('-', '_').replace(':', '_')} = {c}"
                  for c, k in enumerate(TANGENTIAL_KERNELS)),
        capability_table("TANGENTIAL_VISCOUS", [k.viscous for k in TANGENTIAL_KERNELS], "bool_"),
        capability_table("TANGENTIAL_IMPLICIT", [k.implicit for k in TANGENTIAL_KERNELS], "bool_"),
        capability_table("TANGENTIAL_LOG_RATE", [k.log_rate for k in TANGENTIAL_KERNELS], "int64"),
        f"TANGENTIAL_ANY_IMPLICIT = {any(k.implicit for c, k in enumerate(TANGENTIAL_KERNELS) if kept(c, tangential))}"
        "   # numba drops the implicit stepper where False",
        "",
    ]
    for name, (arguments, default) in NORMAL.items():
        parts += ["", chain(name, "normal", NORMAL_KERNELS, arguments, default, EXTENSION_CALL[name], normal), ""]
    parts += ["", normal_step(normal), ""]
    for name, (arguments, default) in TANGENTIAL.items():
        parts += ["", chain(name, "tangential", TANGENTIAL_KERNELS, arguments, default, None, tangential), ""]
    return "\n".join(parts).rstrip() + "\n"


def main():
    TARGET.write_text(source())
    print(f"wrote {TARGET}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
