"""Files written whole or not at all: a temporary file beside the target, renamed over it, so that an interrupted or
killed process never leaves half a file."""
import os
import tempfile


def write_text(path, text):
    """Write `text` to `path` atomically, with the permissions a plain open() would give."""
    path = os.fspath(path)
    directory = os.path.dirname(os.path.abspath(path))
    fd, tmp = tempfile.mkstemp(prefix=f".{os.path.basename(path)}-", suffix=".tmp", dir=directory)
    try:
        with os.fdopen(fd, "w", encoding="utf-8", newline="") as handle:
            handle.write(text)
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(tmp, 0o666 & ~umask)
        os.replace(tmp, path)
    except BaseException:
        os.unlink(tmp)
        raise
    return path
