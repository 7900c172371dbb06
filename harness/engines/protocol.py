"""What an engine declares beside its hooks (base.Engine): the options it takes, and its status (docs/engines.md)."""
import math
from dataclasses import dataclass

from ..infra.errors import UserError


@dataclass(frozen=True)
class Option:
    """An engine option: the values it takes (the first is the default) and what it does."""
    values: tuple
    help: str

    @property
    def default(self):
        return self.values[0]


@dataclass(frozen=True)
class Status:
    """Can an engine run a law here? When not, why: what was looked for and where."""
    name: str
    available: bool
    reason: str = ""


@dataclass(frozen=True)
class InputRange:
    """The restitution coefficients e an engine's inputs take: low < e <= high where low is excluded, else
    low <= e <= high."""
    low: float
    high: float = 1.0
    low_open: bool = False

    @property
    def lowest(self):
        """The lowest e it takes: low, or the next double above it where low is excluded."""
        return math.nextafter(self.low, math.inf) if self.low_open else self.low

    def __str__(self):
        return f"{'(' if self.low_open else '['}{self.low:g}, {self.high:g}]"


def check_options(name, declared, options):
    """The options given, validated against an engine's declared ones: one clear line for an unknown key or value."""
    from .user_inputs import INPUT_OPTION          # an engine input travels as an option (harness.engines.user_inputs)
    options = dict(options or {})
    for key, value in options.items():
        if key == INPUT_OPTION:
            continue
        if key not in declared:
            raise UserError(f"unknown {name} option {key!r}; known: {', '.join(declared) or 'none'}")
        if value not in declared[key].values:
            raise UserError(f"{name} option {key} takes {' or '.join(declared[key].values)}, got {value!r}")
    return options
