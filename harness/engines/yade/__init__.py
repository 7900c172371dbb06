"""YADE 2023.02a as an engine (docs/engines.md): one batched script per (law, e_n), run as a Python module without the
yade launcher; its dialects are in dialect.py, its input and output in script.py, its interpreter and flavours in
flavours.py. It also checks its own arithmetic (precision.py)."""
import os

from ...infra.errors import UserError
from ...infra.programs import which
from ..base import Engine, SceneScripts
from ..builds import sha256
from .dialect import COUNTERPARTS, DIALECTS, OPTIONS, PAIR_DIALECTS, check_options, dialect
from .flavours import (ARITHMETIC, FLAVOURS, PYTHON_VARIABLE, available, environment, flavour_path, missing_reason,
                       python, version)
from .precision import HIGH, precision_runs
from .script import (OBSERVE_FILE, TEMPLATES, read_batch, read_observation, read_result, render_batch, run_inputs,
                     run_script, script, typed)

LEAPFROG = ("hertz-mindlin", "linear-spring-dashpot")


class Yade(SceneScripts, Engine):
    NAME = "yade"
    STARTS_APART = ("wall",)
    INPUT_SUFFIX, INPUT_NAME = ".py", "harness_yade.py"
    EXECUTABLE, VARIABLE = "/usr/bin/python3.11", PYTHON_VARIABLE
    VERIFIED = ("2023.02a",)    # Debian 12's, the release its dialects were read from and checked on
    OPTIONS, COUNTERPARTS, DIALECTS, PAIR_DIALECTS = OPTIONS, COUNTERPARTS, DIALECTS, PAIR_DIALECTS
    KNOWN_CAUSES = {
        ("hertz-mindlin", "e_n off target"): "Thornton 2013 App. B fit degrades above e_n 0.95 (docs/laws.md)",
        ("linear-spring-dashpot", "e_n off target"):
            "ViscEl uses the reduced mass m/2 against a wall; CundallStrack has no damping (docs/yade-dialect.md)",
        ("linear-spring-dashpot", "energy gain"): "CundallStrack's k_s = nu k_n is negative for nu < 0",
        **{(model, "Coulomb bound"):
           "its formulas in the reference do the same: its tangential dashpot added unclipped below the spring's cap "
           "(Coulomb rule spring); with the paper's rule alone the bound holds (docs/findings.md)"
           for model in LEAPFROG},
    }
    COLOUR, DASHES = "tab:green", ":"
    CITATION = {"key": "smilauer2021", "type": "book", "title": "Yade Documentation",
                "author": "{\\v{S}}milauer, V{\\'a}clav and others", "edition": "3rd",
                "publisher": "The Yade Project", "year": "2021", "doi": "10.5281/zenodo.5705394"}
    STARTUP_S, SPHERE_STEP_S = 1.6, 2.0e-6      # bench_accuracy_cost.py: a start-up of 1.57 s
    CONTACT_LINES = ("material = ", "other = ", "InteractionLoop(")
    render_batch, run_inputs = staticmethod(render_batch), staticmethod(run_inputs)
    read_batch = staticmethod(read_batch)
    def available(self, flavour="double"):
        """Debian's python3.11 and the flavour's module directory are both there."""
        return available(flavour or "double")

    def missing_reason(self, flavour="double"):
        return missing_reason(flavour or "double")

    def version(self):
        return version()

    def build(self):
        """Debian's YADE: its version, and the library that holds its contact laws (libpkg_dem.so) with its hash."""
        library = os.path.join(os.path.dirname(flavour_path("double")), "libpkg_dem.so")
        return {"version": self.version(), "binary": library, "sha256": sha256(library),
                "origin": f"Debian package yade, a module of {python()}"}

    def prefix_binary(self, prefix):
        return None                     # one build: Debian's

    def at(self, binary, origin):
        if os.path.realpath(binary) != os.path.realpath(which(self.binary()) or self.binary()):
            raise UserError("YADE runs as a module of Debian's python3.11; another build is not supported yet")
        return super().at(binary, origin)

    def flavour(self, options):
        """The flavour (precision) that runs: double unless the options ask for another."""
        return check_options(options).get("precision", "double")

    def arithmetic(self, options):
        return ARITHMETIC[self.flavour(options)]

    def walls(self, law_name, options=None):
        """hertz-mindlin against any wall (FrictMat: E and nu mixed as harness mixes them), the others, and a user's
        own input (its one material), against the sphere's own material only."""
        if "input" in dict(options or {}):
            return ("same",)
        return ("same", "other", "rigid") if law_name == "hertz-mindlin" else ("same",)

    def target_reason(self, law_name, scene, options=None):
        """A user's own input (the option `input`) runs against a free target sphere of the projectile's density (its
        one material on both spheres; ViscEl would take a held target's mass into m_R); the paper's inputs against
        the targets PAIR_DIALECTS holds."""
        if "input" not in dict(options or {}) or not scene.spheres:
            return super().target_reason(law_name, scene)
        projectile, target = scene.spheres
        if target.fixed:
            return "your own input runs against a free target sphere only"
        if target.rho != projectile.rho:
            return "your own input gives both spheres its one material: a target of the projectile's density only"
        return ""

    def composition(self, law_name, options, target):
        return dialect(law_name, options, target)

    def typed_inputs(self, lines):
        return typed(lines)

    def precision_runs(self, law, scene, options):
        """A double run beside an mpfr150 one (precision.py), when the comparison runs in double."""
        if self.flavour(options) != "double":
            return ()
        return precision_runs(law, scene, self.dialect, dict(options or {}).get("input"))


ENGINE = Yade()

__all__ = ["ARITHMETIC", "COUNTERPARTS", "DIALECTS", "ENGINE", "FLAVOURS", "HIGH", "OBSERVE_FILE", "OPTIONS",
           "PAIR_DIALECTS", "PYTHON_VARIABLE", "TEMPLATES", "dialect", "environment", "flavour_path", "python",
           "read_observation", "read_result", "render_batch", "run_script", "script"]
