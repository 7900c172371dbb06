"""LIGGGHTS 3.8.0 as an engine (docs/engines.md): one batched deck per (law, e_n), run as a subprocess; its dialects
are in dialect.py, its input and output in deck.py."""
import re

from ..base import SCENES_BEYOND_IMPACT, Engine
from ..protocol import InputRange
from .deck import (BINARY_VARIABLE, MIN_RESTITUTION, OBSERVE_DUMP, OTHER_WALL_MODELS, TEMPLATES, deck, read_batch,
                   read_dump, read_observation, render_batch, run_deck, run_inputs, settings, typed)
from .dialect import COUNTERPARTS, DIALECTS, OPTIONS, PAIR_DIALECTS, dialect

STEPPING = ("hertz-mindlin", "linear-spring-dashpot")


class Liggghts(Engine):
    NAME = "liggghts"
    STARTS_APART = ("wall",)
    EXECUTABLE = PACKAGE = "liggghts"
    VERIFIED = ("3.8.0",)       # Debian 12's, the release its dialects were read from and checked on
    VARIABLE = BINARY_VARIABLE
    OPTIONS, COUNTERPARTS, DIALECTS, PAIR_DIALECTS = OPTIONS, COUNTERPARTS, DIALECTS, PAIR_DIALECTS
    WITH = {("tangential-damping", "none"): {"tangential_damping": "off"},
            ("end", "no-tension"): {"limitForce": "on"},
            ("tangential", "viscous:linear"): {"tangential": "no_history"},
            ("tangential", "viscous:mindlin"): {"tangential": "no_history"}}
    KNOWN_CAUSES = {
        ("thornton", "e_n off target"):
            "thornton_ning unloads with R unmodified, so Thornton's p_y calibration misses (docs/liggghts-dialect.md)",
        ("linear-spring-dashpot", "friction at mu = 0"):
            "hooke's zero shear history at first touch passes the Coulomb test, so its tangential dashpot acts",
        ("thornton", "energy gain"): "thornton_ning's tangential damping has the wrong sign (docs/liggghts-dialect.md)",
        ("thornton", "Coulomb bound"): "thornton_ning's tangential damping has the wrong sign: it pushes "
                                       "(docs/liggghts-dialect.md)",
        **{(model, "Coulomb bound"):
           "its formulas in the reference do the same: its tangential dashpot added unclipped below the spring's cap "
           "(Coulomb rule spring) and the cap following |F_n| while the contact pulls (end tension); the physics "
           "verdict gives the share of each (docs/findings.md)"
           for model in STEPPING},
    }
    COLOUR, DASHES = "tab:orange", "--"
    CITATION = {"key": "kloss2012", "type": "article",
                "title": "Models, algorithms and validation for opensource DEM and CFD-DEM",
                "author": "Kloss, Christoph and Goniva, Christoph and Hager, Alice and Amberger, Stefan and Pirker, "
                          "Stefan", "journal": "Progress in Computational Fluid Dynamics", "volume": "12",
                "number": "2/3", "pages": "140--152", "year": "2012", "doi": "10.1504/PCFD.2012.047457"}
    STARTUP_S, SPHERE_STEP_S = 0.5, 0.05e-6
    CONTACT_LINES = ("fix m", "fix p", "pair_style", "fix wall ")
    render_batch = staticmethod(render_batch)
    read_batch = staticmethod(read_batch)

    SCENE_KINDS = SCENES_BEYOND_IMPACT   # harness run --scene (scene.py)

    def scene_reason(self, kind, law_name, options=None):
        from .scene import scene_reason
        return super().scene_reason(kind, law_name, options) or scene_reason(kind, law_name)

    def render_scene(self, kind, case, grid, options=None):
        from .scene import render_scene
        return render_scene(kind, case, grid, options)

    def read_scene(self, kind, case, grid, directory):
        from ..scene_output import read_scene_output
        from .scene import read_forces
        return read_scene_output("LIGGGHTS", kind, case, grid, directory, read_forces)

    def run_inputs(self, flavour, count, timeout_s, workdir):
        return run_inputs(self.binary(), count, timeout_s, workdir)

    def read_version(self, text):
        """'3.8.0' from the banner the binary prints."""
        match = re.search(r"LIGGGHTS-PUBLIC ([0-9.]+)", text)
        return match.group(1) if match else "unknown"

    def walls(self, law_name, options=None):
        """hooke, hertz and hooke/hysteresis against any wall (a second atom type), thornton_ning against the
        sphere's material only."""
        return ("same", "other", "rigid") if COUNTERPARTS.get(law_name) in OTHER_WALL_MODELS else ("same",)

    def composition(self, law_name, options, target):
        return dialect(law_name, options, target)

    def restitution_inputs(self, law_name):
        """coefficientRestitution in (0.05, 1], which LIGGGHTS refuses outside, where the law's deck gives it e
        (hooke/hysteresis' deck gives it 1: its e_n lies in the stiffnesses)."""
        if COUNTERPARTS.get(law_name) == "hooke/hysteresis":
            return self.RESTITUTION_INPUTS
        return InputRange(MIN_RESTITUTION, 1.0, low_open=True)

    def typed_inputs(self, lines):
        return typed(lines)


ENGINE = Liggghts()

__all__ = ["BINARY_VARIABLE", "COUNTERPARTS", "DIALECTS", "ENGINE", "OBSERVE_DUMP", "OPTIONS", "PAIR_DIALECTS",
           "TEMPLATES", "deck", "dialect", "read_dump", "read_observation", "render_batch", "run_deck", "settings"]
