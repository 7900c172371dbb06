"""Compile only what a batch needs: a copy of the solver package under its own name that compiles only the batch's
stepper (its switches.py) and, for a batch of one law, whose dispatch module holds only that law's normal and
tangential kernels, so numba types none of the others (docs/performance.md#first-use-compiling-the-kernels)."""
import importlib
import os
import sys
import threading
import types
from pathlib import Path

from numba.core import config

from ..infra.files import write_text
from ..submodels.generate import dispatch_source, switches_source
from ..submodels.registry import code_of, kernels

SOLVER = os.path.dirname(os.path.abspath(__file__))
_LOADING = threading.Lock()


COMPILED_ALONE = ("mindlin-deresiewicz", "walton-braun")   # tangential kernels costly to compile (a history of their
                                                          # own); the others are cheap and compiled together, so
                                                          # that a comparison's variants of its spring share one copy


def specialised(module, stepper, normal=None, tangential=None):
    """`module` (kernel or adaptive) of the solver specialised to one stepper (submodels/stepping.py) and, given a
    normal kernel, to it and either its tangential kernel (one of COMPILED_ALONE) or all the cheap ones: the package
    `harness.solver_<stepper>[_n<normal>[_t<tangential>]]`, a copy of the solver's modules with its own switches.py
    and dispatch.py, written under numba's cache directory (named by the compiled sources). numba names a cache by
    its source file, so the copy is what keeps the specialised functions' caches apart from the general ones'. None
    where the cache directory cannot be written (the general kernels run then)."""
    alone = {code_of("tangential", name) for name in COMPILED_ALONE}
    label = stepper.lower()
    kept_normal = kept_tangential = None
    if normal is not None:
        label += f"_n{normal}_t{tangential}" if tangential in alone else f"_n{normal}"
        kept_normal = {normal}
        kept_tangential = {tangential} if tangential in alone else set(range(len(kernels("tangential")))) - alone
    with _LOADING:
        return load(label, lambda: generated(stepper, kept_normal, kept_tangential), module)


def generated(stepper, kept_normal, kept_tangential):
    """The modules a specialised copy writes in place of the solver's: switches.py, dispatch.py, and extension.py,
    which re-exports the solver's own (its empty slot is compiled when imported: once is enough)."""
    extension = ('"""The solver\'s extension table and calls."""\n'
                 "from ..solver.extension import BELOW, FORCE, KINK, RESIDUAL, SIGNATURE, SLOPE, call, missing, table  "
                 "# noqa: F401\n")
    return {"switches.py": switches_source(stepper), "dispatch.py": dispatch_source(kept_normal, kept_tangential),
            "extension.py": extension}


def load(label, generate, module):
    """Write (when changed) and import (once) the specialised package, the solver's modules but those `generate()`
    returns (file name -> text); its `module`."""
    name = f"harness.solver_{label}"
    if name not in sys.modules:
        directory = os.path.join(config.CACHE_DIR, "specialised", label)
        files = {file_name: Path(SOLVER, file_name).read_text() for file_name in os.listdir(SOLVER)
                 if file_name.endswith(".py") and file_name != "__init__.py"}
        files.update(generate())
        try:
            os.makedirs(directory, exist_ok=True)
            for file_name, text in files.items():
                path = Path(directory, file_name)
                if not path.exists() or path.read_text() != text:
                    write_text(path, text)
        except OSError:
            return None
        package = types.ModuleType(name)
        package.__path__ = [directory]
        package.__package__ = name
        sys.modules[name] = package
    return importlib.import_module(f"{name}.{module}")
