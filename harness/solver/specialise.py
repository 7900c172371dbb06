"""Compile only what a batch's law needs: a copy of the solver package under its own name whose dispatch module holds
only the law's normal and tangential kernels, so numba types none of the others
(docs/performance.md#first-use-compiling-the-kernels)."""
import importlib
import os
import sys
import threading
import types
from pathlib import Path

from numba.core import config

from ..files import write_text
from ..submodels.generate import source
from ..submodels.registry import code_of
from .dispatch import TANGENTIAL_VISCOUS

SOLVER = os.path.dirname(os.path.abspath(__file__))
_LOADING = threading.Lock()


COMPILED_ALONE = ("mindlin-deresiewicz", "walton-braun")   # tangential kernels costly to compile (a history of their
                                                          # own); the others are cheap and compiled together, so
                                                          # that a comparison's variants of its spring share one copy


def specialised_kernel(normal, tangential):
    """The kernel module of the solver specialised to one normal kernel and either its tangential kernel (one of
    COMPILED_ALONE) or all the cheap ones: the package `harness.solver_n<normal>[_t<tangential>]`, a copy of the
    solver's modules with its own dispatch.py, written under numba's cache directory (named by the compiled sources).
    numba names a cache by its source file, so the copy is what keeps the specialised functions' caches apart from
    the general ones'. None where the cache directory cannot be written (the general kernels run then)."""
    alone = {code_of("tangential", name) for name in COMPILED_ALONE}
    kept = {tangential} if tangential in alone else set(range(len(TANGENTIAL_VISCOUS))) - alone
    label = f"n{normal}_t{tangential}" if tangential in alone else f"n{normal}"
    with _LOADING:
        return load(label, {normal}, kept)


def load(label, normal, tangential):
    """Write (when changed) and import (once) the specialised package; its kernel module."""
    name = f"harness.solver_{label}"
    if name not in sys.modules:
        directory = os.path.join(config.CACHE_DIR, "specialised", label)
        files = {module: Path(SOLVER, module).read_text() for module in os.listdir(SOLVER)
                 if module.endswith(".py") and module not in ("__init__.py", "dispatch.py")}
        files["dispatch.py"] = source(normal, tangential)
        try:
            os.makedirs(directory, exist_ok=True)
            for module, text in files.items():
                path = Path(directory, module)
                if not path.exists() or path.read_text() != text:
                    write_text(path, text)
        except OSError:
            return None
        package = types.ModuleType(name)
        package.__path__ = [directory]
        package.__package__ = name
        sys.modules[name] = package
    return importlib.import_module(f"{name}.kernel")
