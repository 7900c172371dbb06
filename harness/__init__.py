"""harness: cross-validation of DEM contact force models (Thornton, Cummins & Cleary 2013).

From Python, the commands with the command line's option names as keywords (docs/user-guide.md, "Python"):
`run` (the reference solver's results table), `compare` (a Comparison: verdicts, tables, .report(dir), .plot(column)),
`calibrate`, `cost`, `paper`, `benchmark`, `campaign` and `explain` (what your own engine input computes); `columns`
describes every results column with its unit;
`plot` draws a results table as the paper's figures."""

import importlib as _importlib
import sys as _sys
import types as _types

from .infra.version import __version__

_COMMANDS = ("run", "compare", "calibrate", "cost", "paper", "benchmark", "campaign", "plot", "explain")
__all__ = [*_COMMANDS, "columns", "__version__"]


def __getattr__(name):
    """The commands and `columns`, imported on first use: `import harness` loads neither numba nor pandas."""
    if name in _COMMANDS:
        from .api import notebook
        return getattr(notebook, name)
    if name == "columns":
        from .data.descriptions import columns
        return columns()
    raise AttributeError(f"module 'harness' has no attribute {name!r}")


def __dir__():
    """What tab completion offers: the public API beside what is loaded."""
    return sorted(set(globals()) | set(__all__))


class _Harness(_types.ModuleType):
    """The package, pickled by name."""

    def __reduce__(self):
        """Pickled by name, as any module (Dask's workers pickle what refers to the package)."""
        return _importlib.import_module, (self.__name__,)


_sys.modules[__name__].__class__ = _Harness
