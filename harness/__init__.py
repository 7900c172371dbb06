"""harness: cross-validation of DEM contact force models (Thornton, Cummins & Cleary 2013).

`harness.run(model, **keywords)` returns the reference solver's results table; `harness.compare(model, **keywords)`
returns a Comparison; `harness.calibrate(model, engine, **keywords)` a Calibration; the keywords are the command
line's option names (docs/user-guide.md)."""

from .version import __version__
__all__ = ["run", "compare", "calibrate", "__version__"]


def __getattr__(name):
    """run and compare, imported on first use (the solver compiles its kernels then, not on `import harness`)."""
    if name in ("run", "compare", "calibrate"):
        from . import api
        return getattr(api, name)
    raise AttributeError(f"module 'harness' has no attribute {name!r}")
