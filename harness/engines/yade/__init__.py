"""YADE 2023.02a as an engine (docs/engines.md): one batched script per (law, e_n), run as a Python module without the
yade launcher; its dialects are in dialect.py, its input and output in script.py, its interpreter and flavours in
flavours.py. It also checks its own arithmetic (precision.py)."""
from ..batches import render_input
from ..protocol import status_of
from .dialect import DIALECTS, COUNTERPARTS, OPTIONS, PAIR_DIALECTS, check_options, dialect
from .flavours import (ARITHMETIC, FLAVOURS, PYTHON_VARIABLE, available, environment, flavour_path, missing_reason,
                       python, version)
from .precision import HIGH, precision_runs
from .script import (OBSERVE_FILE, TEMPLATES, read_observation, read_result, render_batch, run_batch, run_script,
                     run_together, script)

NAME = "yade"
INPUT_SUFFIX = ".py"


def walls(law_name, options=None):
    """hertz-mindlin against any wall (FrictMat: E and nu mixed as harness mixes them), the others against the
    sphere's own material only."""
    return ("same", "other", "rigid") if law_name == "hertz-mindlin" else ("same",)


def target_reason(law_name, scene):
    """Why its inputs cannot put the sphere against the scene's target ('' when they can): Ig2_Sphere_Sphere_ScGeom
    between two spheres for hertz-mindlin."""
    if scene.spheres and law_name not in PAIR_DIALECTS:
        return f"its {law_name} inputs have no sphere target yet"
    return ""


def supports(law_name):
    return law_name in COUNTERPARTS and law_name in DIALECTS


def status(law_name, options=None):
    """Debian's python3.11 and the chosen flavour's module directory, with a dialect of the law?"""
    precision = check_options(options).get("precision", "double")
    return status_of(NAME, available(precision), lambda: missing_reason(precision), supports(law_name), law_name)


def run(runs):
    """(results frame, failure or None) of each run; the runs of one flavour share one interpreter."""
    return run_together(runs, version())


def render(run):
    """(file name, script text) of one run (harness render)."""
    return render_input(NAME, INPUT_SUFFIX, render_batch, run)


def arithmetic(options):
    """The floating-point arithmetic of a run with these options."""
    return ARITHMETIC[check_options(options).get("precision", "double")]


__all__ = ["ARITHMETIC", "DIALECTS", "FLAVOURS", "COUNTERPARTS", "NAME", "OBSERVE_FILE", "OPTIONS", "PAIR_DIALECTS",
           "PYTHON_VARIABLE", "TEMPLATES",
           "arithmetic", "available", "dialect", "environment", "flavour_path", "HIGH", "precision_runs", "python",
           "read_observation", "read_result", "render", "render_batch", "run", "run_batch", "run_script", "script",
           "status", "supports", "target_reason", "version", "walls"]
