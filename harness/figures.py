"""What figures are drawn over and with: the paper's Psi1* axis and the name of its elastic curve (harness.paper
computes the set, views/paper_html.py draws it), and each registered engine's colour and dialect line style
(views/style.py draws with them; the views import no engine)."""
import numpy as np

from .engines import ENGINES

PSI1_GRID = tuple(float(x) for x in np.round(np.r_[np.arange(0.05, 0.21, 0.05), np.arange(0.25, 14.0001, 0.25)], 6))
# the paper's Psi1* axis, from below its first published point (0.15)
ELASTIC = "hertz-mindlin (elastic)"        # e = 1, no dashpots: the elastic companion paper's reference curve


def engine_styles():
    """(engine -> colour, dialect label -> line style, [(engine, line style)] of the engines with formulas of their
    own) of every registered engine, as each declares them (Engine.COLOUR, Engine.DASHES)."""
    return ({name: engine.COLOUR for name, engine in ENGINES.items() if engine.COLOUR},
            {engine.dialect_label: engine.DASHES for engine in ENGINES.values() if engine.DASHES},
            [(name, engine.DASHES) for name, engine in ENGINES.items() if engine.DASHES and name != "reference"])
