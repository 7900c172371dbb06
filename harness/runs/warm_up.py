"""Compile ahead of time what the commands' first runs compile, into numba's cache: for each law, the reference runs
of a compare over every engine (the paper scheme and each engine's dialect on the reference solver) and the exact
limit (the adaptive integrator: --converged, cost, the paper's sliding thresholds), each on one impact."""
from ..infra.compiling import spent
from ..engines import ENGINES, EXTERNAL
from .execute import execute
from ..laws import LAWS
from ..solver.resolution import CONVERGED
from .plan import compare_plan, reference_runs
from .request import Request


def warm_up_runs(law_name):
    """The reference runs that compile what `law_name` needs: one e_n, one angle, each scheme and kernel once."""
    request = Request.from_keywords(law_name, en=(0.5,), angles=(30.0,))
    law, scene = request.law, request.scene
    engines = {ENGINES[name]: {} for name in EXTERNAL if ENGINES[name].supports(law_name)}
    runs = [run for run in compare_plan(law, scene, request.resolution, engines) if run.engine == "reference"]
    return runs + reference_runs(law, scene, CONVERGED)


def compile_laws(laws=tuple(LAWS), progress=None):
    """Run each law's warm-up runs (compiling what numba's cache lacks); {law: seconds spent compiling it}."""
    if progress:
        progress.expect(len(laws))
    seconds = {}
    for name in laws:
        before = spent()
        execute(warm_up_runs(name))
        seconds[name] = spent() - before
        if progress:
            progress.advance(name)
    return seconds
