"""Normal damping sub-models: c(alpha) = c0 alpha^power with c0 calibrated from the target e_n; the kernel needs no
dispatch for them (c0 and power are parameters)."""
from dataclasses import dataclass

SLOTS = ("c0", "power")     # every dashpot's c(alpha) = c0 alpha^power: its columns of the kernel rows


@dataclass(frozen=True)
class Dashpot:
    """Kernel coefficients c0, power and the equivalent damping ratio g (0 where none is defined)."""
    c0: float
    power: float
    g: float
