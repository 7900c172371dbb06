"""LIGGGHTS 3.8.0 as an engine (docs/engines.md): one batched deck per (law, e_n), run as a subprocess; its dialects
are in dialect.py, its input and output in deck.py, its binary in binary.py."""
from ..batches import render_input
from ..protocol import status_of
from .binary import BINARY_VARIABLE, available, binary, missing_reason, version
from .deck import (OBSERVE_DUMP, OTHER_WALL_MODELS, TEMPLATES, deck, read_dump, read_observation, render_batch, run_batch, run_deck,
                   run_together, settings)
from .dialect import PAIR_DIALECTS, DIALECTS, COUNTERPARTS, OPTIONS, dialect

NAME = "liggghts"
INPUT_SUFFIX = ".in"


def walls(law_name, options=None):
    """hooke, hertz and hooke/hysteresis against any wall (a second atom type), thornton_ning against the sphere's
    material only."""
    return ("same", "other", "rigid") if COUNTERPARTS.get(law_name) in OTHER_WALL_MODELS else ("same",)


def target_reason(law_name, scene):
    """Why its inputs cannot put the sphere against the scene's target ('' when they can): `pair_style gran` between
    two spheres for hertz-mindlin (hertz), linear-spring-dashpot (hooke) and walton-braun (hooke/hysteresis)."""
    if not scene.spheres:
        return ""
    if law_name not in PAIR_DIALECTS:
        return f"its {law_name} inputs have no sphere target yet"
    return ""


def supports(law_name):
    return law_name in COUNTERPARTS and law_name in DIALECTS


def status(law_name, options=None):
    """Installed (the binary named, or `liggghts` on PATH), with a dialect of the law?"""
    return status_of(NAME, available(), missing_reason, supports(law_name), law_name)


def run(runs):
    """(results frame, failure or None) of each run; the runs share one process."""
    return run_together(runs, version())


def render(run):
    """(file name, deck text) of one run (harness render)."""
    return render_input(NAME, INPUT_SUFFIX, render_batch, run)


__all__ = ["BINARY_VARIABLE", "DIALECTS", "COUNTERPARTS", "NAME", "OBSERVE_DUMP", "OPTIONS", "TEMPLATES", "available",
           "binary", "deck", "dialect", "read_dump", "read_observation", "render", "render_batch", "run", "run_batch", "run_deck",
           "settings", "status", "supports", "target_reason", "version", "walls"]
