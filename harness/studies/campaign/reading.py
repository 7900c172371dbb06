"""Reading a small file a user names (a campaign, a scheduler file) without ever blocking: only a regular file is
read, checked on the open descriptor (a FIFO opened non-blocking returns at once), and only up to a size limit."""
import os
import stat

from ...infra.errors import UserError


def kind_of(mode):
    """A file type in words."""
    return ("a directory" if stat.S_ISDIR(mode) else "a FIFO" if stat.S_ISFIFO(mode) else
            "a socket" if stat.S_ISSOCK(mode) else "a device" if stat.S_ISCHR(mode) or stat.S_ISBLK(mode) else
            "a symbolic link" if stat.S_ISLNK(mode) else "not a regular file")


def read_regular(path, what, limit):
    """The bytes of the regular file at `path` (links followed); UserError naming `what` for anything else, for a
    file beyond `limit` bytes or one that cannot be read."""
    path = os.fspath(path)
    if not path:
        raise UserError(f"the {what} path is empty")
    try:
        fd = os.open(path, os.O_RDONLY | os.O_NONBLOCK | os.O_CLOEXEC)
    except OSError as exc:
        raise UserError(f"cannot read {what} {path}: {exc.strerror}") from None
    try:
        mode = os.fstat(fd).st_mode
        if not stat.S_ISREG(mode):
            raise UserError(f"{what} {path} is {kind_of(mode)}, not a regular file")
        chunks, size = [], 0
        while size <= limit:
            chunk = os.read(fd, min(1 << 16, limit + 1 - size))
            if not chunk:
                break
            chunks.append(chunk)
            size += len(chunk)
        if size > limit:
            raise UserError(f"{what} {path} is larger than {limit} bytes")
        return b"".join(chunks)
    except OSError as exc:
        raise UserError(f"cannot read {what} {path}: {exc.strerror}") from None
    finally:
        os.close(fd)
