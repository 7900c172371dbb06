"""Engine adapters: which engines exist, whether each is installed, and why one is skipped."""
import glob
import shutil
from dataclasses import dataclass


@dataclass(frozen=True)
class EngineStatus:
    """Availability of one external engine for a law, with the reason when it cannot run."""
    name: str
    available: bool
    reason: str


def _liggghts_installed():
    from . import liggghts
    return liggghts.available()


def _yade_installed():
    return bool(glob.glob("/usr/lib/x86_64-linux-gnu/yade-*/py")) and shutil.which("python3.11") is not None


INSTALLED = {"liggghts": _liggghts_installed, "yade": _yade_installed}


def _adapters():
    from . import liggghts
    return {"liggghts": liggghts}


ADAPTERS = _adapters()   # engine name -> adapter module (NAME, available, version, supports, dialect, run_batch)


def engine_status(name, law_name):
    """Can `name` run `law_name` here? Missing binary, missing adapter or unsupported law each say so."""
    if name not in INSTALLED:
        return EngineStatus(name, False, f"unknown engine {name!r}")
    if not INSTALLED[name]():
        return EngineStatus(name, False, f"{name} is not installed (apt-get install -y {name}, or bash tools/setup.sh)")
    adapter = ADAPTERS.get(name)
    if adapter is None:
        return EngineStatus(name, False, f"{name} is installed but its adapter is not implemented yet")
    if not adapter.supports(law_name):
        return EngineStatus(name, False, f"{name} has no counterpart of {law_name}")
    return EngineStatus(name, True, "")
