"""Contact laws as compositions of sub-models (normal, damping, end rule, tangential, tangential dashpot)."""
from .law import Law
from .named import LAWS, compose, get_law

__all__ = ["LAWS", "Law", "compose", "get_law"]
