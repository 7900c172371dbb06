"""The reference solver as an engine (docs/engines.md): it runs any law, the paper's or an engine's dialect, in the
compiled kernels of harness/solver, at a number of steps per contact, a time step or converged."""
from ...version import __version__
from ...laws import LAWS, compose
from ..protocol import Status

NAME = "reference"
INPUT_SUFFIX = ""
OPTIONS = {}
COUNTERPARTS = {name: "paper" for name in LAWS}


def available(option=None):
    return True


def status(law_name, options=None):
    return Status(NAME, True)


def version():
    return __version__



def walls(law_name, options=None):
    """Every wall: the contact's E* and G* carry it."""
    return ("same", "other", "rigid")

def supports(law_name):
    return law_name in LAWS


def target_reason(law_name, scene):
    """'': a wall, or a sphere (the equivalent wall impact, harness.two_spheres)."""
    return ""


def dialect(law_name, options=None, target="wall"):
    """The paper's law: the reference's own formulas (against a sphere too: levers R1, R2)."""
    return compose(law_name)


def run(runs):
    """(results frame, None) of each run: `simulate` of its dialect at its resolution."""
    from ...plan import CONVERGED
    from ...solver.reference import simulate
    out = []
    for run in runs:
        converged = run.resolution == CONVERGED
        frame, _ = simulate(run.dialect, run.scene, converged=converged,
                            steps_per_contact=1000 if converged else run.resolution)
        out.append((frame, None))
    return out


def render(run):
    from ...errors import UserError
    raise UserError("the reference solver reads no input file; `harness render` writes engines' inputs")
