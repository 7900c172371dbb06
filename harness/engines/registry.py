"""The registry of the engines, one line each: name -> Engine. A name `engine@selector` (builds.py) is one build of
an engine, resolved on first use."""
import os
import re

from ..infra.errors import UserError
from .kratos import ENGINE as KRATOS
from .lammps import ENGINE as LAMMPS
from .liggghts import ENGINE as LIGGGHTS
from .names import EXTERNAL
from .reference import ENGINE as REFERENCE
from .yade import ENGINE as YADE
from .builds import ALL, select

VERSION = re.compile(r"\d[0-9A-Za-z.+-]*")   # how a build's version is written: 2021.9.29, 2023.02a


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
        if code == "reference":
            raise UserError(f"{name}: the reference solver has no builds; name it `reference`")
        if selector != ALL and os.sep not in selector and not VERSION.fullmatch(selector):
            raise UserError(f"{name}: a build is named by its version (e.g. {code}@2021.9.29), {code}@all or "
                            f"{code}@/path/to/its/binary")
        chosen = select(self[code], selector)
        for build in chosen:
            self.resolved[build.NAME] = build
        if len(chosen) == 1:
            self.resolved[name] = chosen[0]
        return chosen


ENGINES = Registry({engine.NAME: engine for engine in (REFERENCE, LIGGGHTS, YADE, LAMMPS, KRATOS)})
if tuple(ENGINES) != ("reference", *EXTERNAL):
    raise ImportError(f"harness.engines.EXTERNAL {EXTERNAL} does not name the registered engines {tuple(ENGINES)}")


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
