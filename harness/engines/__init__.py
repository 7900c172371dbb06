"""The engines: one subpackage each holding a subclass of base.Engine, and this registry, one line each."""
from . import lammps, liggghts, reference, yade

ENGINES = {
    "reference": reference.ENGINE,
    "liggghts": liggghts.ENGINE,
    "yade": yade.ENGINE,
    "lammps": lammps.ENGINE,
}
EXTERNAL = tuple(name for name in ENGINES if name != "reference")     # the engines harness checks


def get_engine(name):
    from ..errors import UserError
    if name not in ENGINES:
        raise UserError(f"unknown engine {name!r}; known: {', '.join(ENGINES)}")
    return ENGINES[name]


def known_cause(dialect, model, kind):
    """The documented cause of a finding of `model` in `dialect`, from the engine whose dialect it is
    (Engine.KNOWN_CAUSES), or ''."""
    return next((engine.known_cause(model, kind) for engine in ENGINES.values() if engine.dialect_label == dialect), "")
