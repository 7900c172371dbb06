"""The engines: one subpackage each holding a subclass of base.Engine, and their registry (registry.py: ENGINES,
get_engine, known_cause), loaded on first use so that the engines' names alone cost no import."""
from .names import EXTERNAL  # noqa: F401  (the engines harness checks)

REGISTERED = ("ENGINES", "Registry", "get_engine", "known_cause")


def __getattr__(name):
    """The registry's names, imported on first use and kept here."""
    if name not in REGISTERED:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    from . import registry
    globals().update({key: getattr(registry, key) for key in REGISTERED})
    return globals()[name]
