"""The engines: one subpackage each holding a subclass of base.Engine, and this registry, one line each. A name
`engine@selector` (builds.py) is one build of an engine, resolved on first use."""
from ..errors import UserError
from . import lammps, liggghts, reference, yade
from .builds import select


class Registry(dict):
    """name -> Engine for the registered engines; `engine@selector` -> the build it selects, kept once resolved
    under the selector and under the build's own name (never among the registered engines a loop sees)."""

    def __init__(self, engines):
        super().__init__(engines)
        self.resolved = {}

    def __missing__(self, name):
        if name not in self.resolved:
            code, at, selector = name.partition("@")
            if not at or not dict.__contains__(self, code):
                raise KeyError(name)
            self.resolve(name)
        return self.resolved[name]

    def resolve(self, name):
        """The engines a name asks for: the registered engine, or each build `engine@selector` selects."""
        if dict.__contains__(self, name):
            return [self[name]]
        code, at, selector = name.partition("@")
        if not at or not dict.__contains__(self, code):
            raise UserError(f"unknown engine {name!r}; known: {', '.join(self)} (and ENGINE@VERSION, ENGINE@all, "
                            f"ENGINE@/path/to/its/binary)")
        chosen = select(self[code], selector)
        for build in chosen:
            self.resolved[build.NAME] = build
        if len(chosen) == 1:
            self.resolved[name] = chosen[0]
        return chosen


ENGINES = Registry({
    "reference": reference.ENGINE,
    "liggghts": liggghts.ENGINE,
    "yade": yade.ENGINE,
    "lammps": lammps.ENGINE,
})
EXTERNAL = tuple(name for name in ENGINES if name != "reference")     # the engines harness checks


def get_engine(name):
    """The engine a name asks for (a registered engine or one build of it); one clear line for an unknown one."""
    if "@" in name:
        chosen = ENGINES.resolve(name)
        if len(chosen) != 1:
            raise UserError(f"{name} names {len(chosen)} builds; here one is needed")
        return chosen[0]
    if name not in ENGINES:
        raise UserError(f"unknown engine {name!r}; known: {', '.join(ENGINES)}")
    return ENGINES[name]


def known_cause(dialect, model, kind):
    """The documented cause of a finding of `model` in `dialect`, from the engine whose dialect it is
    (Engine.KNOWN_CAUSES), or ''."""
    code = dialect.partition("@")[0]
    return next((engine.known_cause(model, kind) for engine in ENGINES.values() if engine.dialect_label == code), "")
