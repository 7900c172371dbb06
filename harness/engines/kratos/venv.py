"""Which Kratos runs: a Python interpreter that imports KratosMultiphysics and its DEMApplication, probed once per
path (without importing Kratos) for the installed distributions' versions and the DEMApplication's compiled
library."""
import json
import os
from functools import lru_cache

from ...infra.programs import which
from ..runner import EngineFailure, run_engine, scratch

PYTHON_VARIABLE = "HARNESS_KRATOS_PYTHON"     # another interpreter with Kratos (a custom install, a test's fake)
PROBE_TIMEOUT_S = 30.0
PROBE = """import importlib.metadata as m, importlib.util as u, json, os
spec = u.find_spec("KratosMultiphysics")
folder = os.path.dirname(spec.origin) if spec and spec.origin else ""
library = os.path.join(folder, ".libs", "libKratosDEMCore.so")
print(json.dumps({"version": m.version("KratosMultiphysics"), "dem": m.version("KratosDEMApplication"),
                  "library": library if os.path.isfile(library) else ""}))
"""


def probe(python):
    """{version, dem, library} of the interpreter `python` names (an absolute path or a name on PATH); {} where it
    is missing or has no Kratos."""
    path = which(python)
    if path is None:
        return {}
    return _probe(path, os.stat(path).st_mtime_ns)


@lru_cache(maxsize=None)
def _probe(python, mtime_ns):
    with scratch("kratos-version") as workdir:
        try:
            run_engine([python, "-c", PROBE], workdir, PROBE_TIMEOUT_S)
            with open(os.path.join(workdir, "engine.log")) as handle:
                found = json.loads(handle.read().strip().splitlines()[-1])
        except (EngineFailure, OSError, ValueError, IndexError):
            return {}
    return found if isinstance(found, dict) else {}
