"""A digest of harness' own source files, for keys that must change whenever the code behind a result changes."""
import hashlib
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent      # the package


def source_digest(*folders):
    """sha256 (12 hex digits) of the .py and .j2 files among the given files and folders (of the harness package when
    relative), in path order."""
    paths = [p for name in folders for p in ([ROOT / name] if (ROOT / name).is_file() else (ROOT / name).rglob("*"))]
    digest = hashlib.sha256()
    for path in sorted(p for p in paths if p.suffix in (".py", ".j2")):
        digest.update(path.read_bytes())
    return digest.hexdigest()[:12]
