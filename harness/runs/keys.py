"""A run's key for stores and caches: Run.key with the engine's version and a digest of the harness code that runs
it, so that a changed engine build, law or harness code never reuses a stored result."""
from functools import lru_cache

from ..engines import ENGINES
from ..infra.sources import source_digest


def run_key(run):
    """The run's key with its engine's version and a digest of the code that runs it (the reference's solver and
    sub-models, an engine's adapter and templates): changed code never reuses a stored result."""
    return run.key(f"{ENGINES[run.engine].version()}+{code_digest(run.engine)}")


@lru_cache(maxsize=None)
def code_digest(engine):
    """sha256 of the source files that determine an engine's results in harness."""
    return source_digest(*ENGINES[engine].sources())
