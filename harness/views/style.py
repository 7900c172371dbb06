"""How every figure draws a curve: one colour per engine and one line style per dialect (each engine declares its
own), the same in every figure; an engine's own run wide and pale under the thin line of its formulas in the
reference, so both stay visible."""
from itertools import cycle

from ..engines.styles import engine_styles

COLOURS, DASHES, _ = engine_styles()
_spare_colours = cycle(["tab:red", "tab:brown", "tab:pink", "tab:olive", "tab:cyan"])
_spare_dashes = cycle([(0, (5, 1, 1, 1)), (0, (1, 2))])


def colour(engine):
    if engine not in COLOURS:
        COLOURS[engine] = next(_spare_colours)
    return COLOURS[engine]


def dashes(dialect):
    if dialect not in DASHES:
        DASHES[dialect] = next(_spare_dashes)
    return DASHES[dialect]


def curve(engine, dialect):
    """matplotlib keywords of the (engine, dialect) curve."""
    if engine == "reference":
        return {"color": colour(engine), "ls": dashes(dialect), "lw": 1.6 if dialect == "paper" else 1.0,
                "zorder": 3}
    return {"color": colour(engine), "ls": dashes(dialect), "lw": 3.0, "alpha": 0.55, "zorder": 2}


STYLE_WORDS = {"-": "solid", "--": "dashed", ":": "dotted", "-.": "dash-dotted"}


def dialect_styles():
    """'dashed: liggghts' formulas; dotted: yade's; ...' for each engine's dialect line style (the report's legend)."""
    words = [f"{STYLE_WORDS.get(style, 'own style')}: {name}'s formulas" for name, style in engine_styles()[2]]
    return "; ".join(words)


def label(engine, dialect):
    """The legend's words for a curve."""
    if engine == "reference" and dialect == "paper":
        return "paper law"
    if engine == "reference":
        return f"{dialect} formulas (reference)"
    return f"{engine} run" if engine == dialect else f"{engine} ({dialect})"
