"""Files written whole or not at all: a temporary file beside the target, renamed over it, so that an interrupted or
killed process never leaves half a file."""
import errno
import os
import stat
import tempfile
from contextlib import suppress

from .errors import UserError


def refuse_unless_regular(path):
    """Only a regular file (not a link, a device, a FIFO, a socket or a directory) may be replaced."""
    try:
        mode = os.lstat(path).st_mode
    except FileNotFoundError:
        return
    if not stat.S_ISREG(mode):
        kind = ("a symbolic link" if stat.S_ISLNK(mode) else "a directory" if stat.S_ISDIR(mode) else
                "a device, FIFO or socket")
        raise UserError(f"will not write {path}: it is {kind}, not a regular file")


def refuse_to_read_unless_regular(path, what):
    """Only a regular file (or a link to one) is read: a FIFO would block the reader for good and a device may never
    end. Checked on the file opened without blocking, so that opening a FIFO does not wait for a writer."""
    try:
        fd = os.open(path, os.O_RDONLY | os.O_NONBLOCK)
    except OSError as exc:
        raise UserError(f"cannot read {what} {path}: {exc.strerror}") from None
    try:
        mode = os.fstat(fd).st_mode
    finally:
        os.close(fd)
    if not stat.S_ISREG(mode):
        kind = "a directory" if stat.S_ISDIR(mode) else "a device, FIFO or socket"
        raise UserError(f"will not read {what} {path}: it is {kind}, not a regular file")


def discard(path):
    """Remove a regular file if there is one (a file an unfinished command must not leave standing, such as the
    report of an earlier run beside new results); anything else at the path is left alone."""
    with suppress(FileNotFoundError):
        if stat.S_ISREG(os.lstat(path).st_mode):
            os.unlink(path)


def write_text(path, text):
    """Write `text` to `path` atomically, with the permissions a plain open() would give; only a new path or a
    regular file is written."""
    return _write(path, text, {"mode": "w", "encoding": "utf-8", "newline": ""})


def write_bytes(path, data):
    """Write `data` (bytes) to `path` as write_text writes text."""
    return _write(path, data, {"mode": "wb"})


def _write(path, data, how):
    path = os.fspath(path)
    refuse_unless_regular(path)
    directory = os.path.dirname(os.path.abspath(path))
    fd, tmp = tempfile.mkstemp(prefix=f".{os.path.basename(path)}-", suffix=".tmp", dir=directory)
    try:
        with os.fdopen(fd, **how) as handle:
            handle.write(data)
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(tmp, 0o666 & ~umask)
        os.replace(tmp, path)
    except BaseException as exc:
        with suppress(FileNotFoundError):      # an interrupt just after the rename: the file is whole, tmp gone
            os.unlink(tmp)
        if isinstance(exc, OSError) and exc.errno in (errno.ENOSPC, errno.EDQUOT) and exc.filename is None:
            raise OSError(exc.errno, exc.strerror, path) from None      # a full disk: say which file it refused
        raise
    return path
