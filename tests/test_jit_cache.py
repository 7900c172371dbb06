"""numba's cache of harness is named by a digest of every compiled source, so a changed callee is never served from
a caller compiled against its older code (numba checks a cached function against its own file only)."""
import importlib
import pkgutil

from numba import config
from numba.core.registry import CPUDispatcher

import harness.solver
import harness.submodels
from harness.infra.sources import source_digest


def compiled_functions():
    for package in (harness.solver, harness.submodels):
        for module in pkgutil.walk_packages(package.__path__, package.__name__ + "."):
            for value in vars(importlib.import_module(module.name)).values():
                cached = isinstance(value, CPUDispatcher) and value._cache is not None
                if cached and hasattr(value._cache, "_cache_path"):
                    yield value


def test_every_cached_kernel_lives_in_the_directory_of_the_current_sources():
    digest = source_digest("solver", "submodels", "infra/jit.py")
    paths = {f"{f.py_func.__module__}.{f.__name__}": f._cache._cache_path for f in compiled_functions()}
    assert len(paths) > 50
    assert config.CACHE_DIR.endswith(digest)
    assert {name for name, path in paths.items() if not path.startswith(config.CACHE_DIR)} == set()


def test_the_digest_follows_every_compiled_source(tmp_path, monkeypatch):
    import harness.infra.sources as sources
    for name in ("solver", "submodels"):
        (tmp_path / name).mkdir()
        (tmp_path / name / "a.py").write_text("x = 1\n")
    (tmp_path / "infra").mkdir()
    (tmp_path / "infra" / "jit.py").write_text("")
    monkeypatch.setattr(sources, "ROOT", tmp_path)
    before = sources.source_digest("solver", "submodels", "infra/jit.py")
    (tmp_path / "submodels" / "a.py").write_text("x = 2\n")
    after = sources.source_digest("solver", "submodels", "infra/jit.py")
    (tmp_path / "infra" / "jit.py").write_text("# changed\n")
    assert len({before, after, sources.source_digest("solver", "submodels", "infra/jit.py")}) == 3
