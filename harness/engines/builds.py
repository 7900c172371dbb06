"""An engine's builds: every executable harness finds for an engine, each run as its own engine named
`engine@version`. The default build is the one on PATH (or in the engine's variable); others are prefixes under the
engines directory, one per version (tools/install_lammps.sh makes them), or a path a user names (`lammps@/opt/lmp`).
A selector after `@` is `all`, a path, or the start of a version as `harness engines` prints it."""
import fnmatch
import hashlib
import os
from functools import lru_cache

from ..infra.errors import EngineMissing, UserError
from ..infra.programs import directory_from, which
from ..infra.releases import release_key

DIRECTORY_VARIABLE = "HARNESS_ENGINES_DIR"
DEFAULT_DIRECTORY = "/opt/harness/engines"
ALL = "all"


def directory():
    """Where the engine prefixes are: $HARNESS_ENGINES_DIR (an absolute directory), else /opt/harness/engines."""
    return directory_from(DIRECTORY_VARIABLE, DEFAULT_DIRECTORY)


@lru_cache(maxsize=None)
def _digest(path, size, mtime_ns):
    sha = hashlib.sha256()
    with open(path, "rb") as handle:
        for block in iter(lambda: handle.read(1 << 20), b""):
            sha.update(block)
    return sha.hexdigest()


def sha256(path):
    """SHA-256 of the file a binary path resolves to ('' when there is none), read once per file version."""
    real = os.path.realpath(path) if path else ""
    try:
        stat = os.stat(real)
    except OSError:
        return ""
    if not os.path.isfile(real):
        return ""
    return _digest(real, stat.st_size, stat.st_mtime_ns)


def found(engine):
    """(binary, origin) of every build of `engine` here: its default, then each prefix `<directory>/<engine>-*` (once:
    a default that is a prefix's own binary is not listed again)."""
    out = []
    default = which(engine.binary())
    if default:
        out.append((default, engine.default_origin()))
    for prefix, binary in prefix_binaries(engine):
        if binary not in (path for path, _ in out):
            out.append((binary, f"prefix {prefix}"))
    return out


def prefix_binaries(engine):
    """(prefix, executable) of every prefix `<directory>/<engine>-*` that holds the engine's executable, in order."""
    root, out = directory(), []
    try:
        names = os.listdir(root)
    except OSError:
        return out
    for name in sorted(fnmatch.filter(names, f"{engine.code}-*")):
        prefix = os.path.join(root, name)
        binary = engine.prefix_binary(prefix)
        if binary and os.access(binary, os.X_OK):
            out.append((prefix, binary))
    return out


def builds(engine):
    """Every build of `engine` as its own Engine, in release order (harness.infra.releases)."""
    every = [engine.at(binary, origin) for binary, origin in found(engine)]
    return sorted(every, key=lambda build: release_key(build.version()))


def select(engine, selector):
    """The builds of `engine` a selector names: all of them, the one at a path, or the one version that starts with
    the selector; a UserError naming what was found otherwise."""
    if selector == ALL:
        chosen = builds(engine)
        if not chosen:
            raise EngineMissing(f"no build of {engine.NAME} found ({engine.missing_reason()})")
        return chosen
    if os.sep in selector:
        if not (os.path.isfile(selector) and os.access(selector, os.X_OK)):
            raise UserError(f"{engine.NAME}@{selector}: not an executable file")
        return [engine.at(os.path.abspath(selector), "path given")]
    every = builds(engine)
    matching = [build for build in every if build.version() == selector or build.version().startswith(selector + ".")]
    if len({build.version() for build in matching}) == 1:
        return matching[:1]
    versions = ", ".join(build.version() for build in every) or "none"
    what = "more than one" if matching else "no"
    refusal = UserError if matching else EngineMissing
    raise refusal(f"{what} build of {engine.NAME} has version {selector} (found: {versions}; `harness engines` "
                  f"lists them)")
