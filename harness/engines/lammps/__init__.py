"""LAMMPS (29 Sep 2021) as an engine (docs/engines.md): one batched deck per (law, e_n) through `fix wall/gran
granular`, run as a subprocess; its dialects are in dialect.py, its input and output in deck.py, its binary in
binary.py."""
from ..batches import render_input
from ..protocol import status_of
from .binary import BINARY_VARIABLE, available, binary, missing_reason, version
from .deck import OBSERVE_DUMP, TEMPLATES, deck, read_batch, render_batch, run_batch, run_together, settings
from .dialect import (COUNTERPARTS, DIALECTS, HISTORY_STYLES, OPTIONS, PAIR_DIALECTS, check_options, dialect, walls,
                      words)

NAME = "lammps"
INPUT_SUFFIX = ".in"


def target_reason(law_name, scene):
    """Why its inputs cannot put the sphere against the scene's target ('' when they can): pair granular between
    two atoms for every law it has."""
    if scene.spheres and law_name not in PAIR_DIALECTS:
        return f"its {law_name} inputs have no sphere target"
    return ""


def supports(law_name):
    return law_name in COUNTERPARTS and law_name in DIALECTS


def status(law_name, options=None):
    """Installed (the binary named, or `lmp` on PATH), with a dialect of the law?"""
    return status_of(NAME, available(), missing_reason, supports(law_name), law_name)


def run(runs):
    """(results frame, failure or None) of each run; the runs share one process per core."""
    return run_together(runs, version())


def render(run):
    """(file name, deck text) of one run (harness render)."""
    return render_input(NAME, INPUT_SUFFIX, render_batch, run)


__all__ = ["BINARY_VARIABLE", "COUNTERPARTS", "DIALECTS", "HISTORY_STYLES", "NAME", "OBSERVE_DUMP", "OPTIONS", "TEMPLATES", "available",
           "binary", "check_options", "deck", "dialect", "missing_reason", "read_batch", "render", "render_batch", "run",
           "run_batch", "run_together", "settings", "status", "supports", "target_reason", "version", "words", "walls"]
