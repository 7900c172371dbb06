"""TEMPORARY stub until the presets land."""
from dataclasses import dataclass
from harness.errors import UserError

@dataclass(frozen=True)
class Material:
    name: str
    E: float
    nu: float
    rho: float
    radius: float
    mu: float | None
    e_n: float | None
    source: str

MATERIALS = {"paper": Material("paper", 70e9, 0.3, 2650.0, 5e-3, 0.3, None, "stub")}

def get_material(name):
    try:
        return MATERIALS[name]
    except KeyError:
        raise UserError(f"unknown material {name!r}") from None
