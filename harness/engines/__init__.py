"""Engine adapters: which engines exist, whether each is installed, and why one is skipped."""
from dataclasses import dataclass

from . import liggghts, yade

ADAPTERS = {"liggghts": liggghts, "yade": yade}   # name -> adapter module (available, version, supports, dialect...)
INSTALLED = {name: adapter.available for name, adapter in ADAPTERS.items()}


@dataclass(frozen=True)
class EngineStatus:
    """Availability of one external engine for a law, with the reason when it cannot run."""
    name: str
    available: bool
    reason: str


def engine_status(name, law_name):
    """Can `name` run `law_name` here? Missing engine, unsupported law or unverified dialect each say so."""
    if name not in ADAPTERS:
        return EngineStatus(name, False, f"unknown engine {name!r}")
    adapter = ADAPTERS[name]
    if not adapter.available():
        return EngineStatus(name, False, f"{name} is not installed (apt-get install -y {name}, or bash tools/setup.sh)")
    if law_name not in adapter.MODELS:
        return EngineStatus(name, False, f"{name} has no counterpart of {law_name}")
    if not adapter.supports(law_name):
        return EngineStatus(name, False, f"{name} runs {adapter.MODELS[law_name]} for {law_name}, but harness has "
                                         f"no verified {name} dialect of it yet, so it cannot check agreement")
    return EngineStatus(name, True, "")
