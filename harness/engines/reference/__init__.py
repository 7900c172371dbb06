"""The reference solver as an engine (docs/engines.md): it runs any law, the paper's or an engine's dialect, in the
compiled kernels of harness/solver, at a number of steps per contact, a time step or converged."""
import os

from ...laws.table import LAWS
from ...infra.version import __version__
from ..base import Engine


class Reference(Engine):
    NAME, DIALECT, INPUT_SUFFIX = "reference", "paper", ""
    COUNTERPARTS = {name: "paper" for name in LAWS}
    DIALECTS = PAIR_DIALECTS = {name: {} for name in LAWS}    # the paper's own formulas (against a sphere: R1, R2)
    KNOWN_CAUSES = {
        ("hertz-mindlin", "e_n off target"): "Thornton 2013 App. B fit degrades above e_n 0.95 (docs/laws.md)",
        ("stronge", "energy gain"): "the provisional reconstruction gains energy for 1 < V/V_y < 1.55 (README)",
    }
    COLOUR, DASHES = "black", "-"
    STARTUP_S, SPHERE_STEP_S = 0.0, 0.6e-6

    def available(self, flavour=None):
        return True

    def version(self):
        return __version__

    def sources(self):
        """Its subpackage, the solver and the sub-models."""
        root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
        return super().sources() + (os.path.join(root, "solver"), os.path.join(root, "submodels"))

    def walls(self, law_name, options=None):
        """Every wall: the contact's E* and G* carry it."""
        return ("same", "other", "rigid")

    def with_options(self, law_name, overrides, options=None, target="wall"):
        """None needed: it runs the law asked for, replacements and all."""
        return dict(options or {})

    def run(self, runs):
        """(results frame, None) of each run: `simulate` of its dialect at its resolution."""
        from ...solver.resolution import CONVERGED
        from ...solver.simulate import simulate
        out = []
        for run in runs:
            converged = run.resolution == CONVERGED
            frame, _ = simulate(run.dialect, run.scene, converged=converged,
                                steps_per_contact=1000 if converged else run.resolution)
            out.append((frame, None))
        return out

    def render(self, run):
        from ...infra.errors import UserError
        raise UserError("the reference solver reads no input file; `harness render` writes engines' inputs")


ENGINE = Reference()
