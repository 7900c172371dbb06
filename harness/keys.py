"""A run's key for stores and caches: Run.key with the engine's version and a digest of the harness code that runs
it, so that a changed engine build, law or harness code never reuses a stored result."""
import hashlib
from functools import lru_cache
from pathlib import Path

from .engines import ENGINES


def run_key(run):
    """The run's key with its engine's version and a digest of the code that runs it (the reference's solver and
    sub-models, an engine's adapter and templates): changed code never reuses a stored result."""
    return run.key(f"{ENGINES[run.engine].version()}+{code_digest(run.engine)}")


@lru_cache(maxsize=None)
def code_digest(engine):
    """sha256 of the source files that determine an engine's results in harness."""
    root = Path(__file__).resolve().parent
    folders = [root / "engines" / engine] + ([root / "solver", root / "submodels"] if engine == "reference" else [])
    digest = hashlib.sha256()
    for path in sorted(p for folder in folders for p in folder.rglob("*") if p.suffix in (".py", ".j2")):
        digest.update(path.read_bytes())
    return digest.hexdigest()[:12]
