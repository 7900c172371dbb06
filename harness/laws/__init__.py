"""Contact laws as compositions of sub-models (normal, damping, end rule, tangential, tangential dashpot); their
names and labels are in the light registration table (table.py), the composed laws (named.py: LAWS, Law, compose,
get_law, replace_submodels, with their compiled kernels) load on first use."""
COMPOSED = ("LAWS", "Law", "compose", "get_law", "replace_submodels")

__all__ = list(COMPOSED)


def __getattr__(name):
    """The composed laws' names, imported on first use and kept here."""
    if name not in COMPOSED:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    from . import named
    globals().update({key: getattr(named, key) for key in COMPOSED})
    return globals()[name]
