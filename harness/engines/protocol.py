"""What an engine is to harness: the declared protocol every adapter implements (the reference solver included), and
the declared options an adapter takes (docs/engines.md)."""
from dataclasses import dataclass
from typing import Protocol

from ..errors import UserError


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


class Engine(Protocol):
    """An engine adapter: one subpackage of harness/engines and one line of its registry (engines/__init__.py)."""
    NAME: str
    OPTIONS: dict          # option name -> Option, declared by the adapter and surfaced by `--engine-option`
    INPUT_SUFFIX: str      # of the rendered input (harness render), "" for the reference
    COUNTERPARTS: dict           # harness law -> the engine's name of its model

    def available(self) -> bool:
        """The engine is installed here (for YADE: in the flavour asked for, double by default)."""

    def status(self, law_name: str, options: dict | None = None) -> Status:
        """Installed (in the flavour the options ask for), and able to run `law_name` (a verified dialect exists)?"""

    def version(self) -> str:
        """The engine's version, read without writing into the user's directory."""

    def walls(self, law_name: str, options: dict | None = None) -> tuple:
        """The walls its inputs model for the law (with the options given): 'same' (the sphere's material), and
        'other', 'rigid' where they can."""

    def supports(self, law_name: str) -> bool:
        """Has a counterpart of the law and a verified dialect of it."""

    def target_reason(self, law_name: str, scene) -> str:
        """Why its inputs cannot put the sphere against the scene's target (a wall, or a sphere: scene.spheres), ''
        when they can."""

    def dialect(self, law_name: str, options: dict, target: str = "wall"):
        """The law as this engine computes it (a harness.laws.Law), for the options given, against a wall or a
        sphere (the engine's two-sphere dialect, reduced to the equivalent wall impact)."""

    def run(self, runs: list) -> list:
        """Each run of the plan (one batch: a law, an e_n, every impact) as (results frame, failure or None)."""

    def render(self, run) -> tuple:
        """(file name, text) of the input a run would give the engine (harness render)."""


def status_of(name, installed, missing_reason, supported, law_name):
    """An external engine's Status for a law: installed (else what was looked for, `missing_reason()`), with a dialect
    of the law (`supported`)."""
    if not installed:
        return Status(name, False, missing_reason())
    if not supported:
        return Status(name, False, f"{name} has no counterpart of {law_name}")
    return Status(name, True)


def check_options(name, declared, options):
    """The options given, validated against an engine's declared ones: one clear line for an unknown key or value."""
    options = dict(options or {})
    for key, value in options.items():
        if key not in declared:
            raise UserError(f"unknown {name} option {key!r}; known: {', '.join(declared) or 'none'}")
        if value not in declared[key].values:
            raise UserError(f"{name} option {key} takes {' or '.join(declared[key].values)}, got {value!r}")
    return options
