"""Contact laws as compositions of sub-models (normal, damping, end rule, tangential, tangential dashpot)."""
from .law import Law, compose, get_law
from .named import LAWS

__all__ = ["LAWS", "Law", "compose", "get_law"]
