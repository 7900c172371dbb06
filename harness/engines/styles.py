"""What figures draw each engine with: each registered engine's colour and dialect line style, as it declares them
(views/style.py draws with them; this module is the only part of the engines a view reads)."""
from . import ENGINES


def engine_styles():
    """(engine -> colour, dialect label -> line style, [(engine, line style)] of the engines with formulas of their
    own) of every registered engine, as each declares them (Engine.COLOUR, Engine.DASHES)."""
    return ({name: engine.COLOUR for name, engine in ENGINES.items() if engine.COLOUR},
            {engine.dialect_label: engine.DASHES for engine in ENGINES.values() if engine.DASHES},
            [(name, engine.DASHES) for name, engine in ENGINES.items() if engine.DASHES and name != "reference"])
