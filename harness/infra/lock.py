"""One writer per output directory: an advisory lock (flock) on DIR/.harness.infra.lock holding the writer's pid and
command, so that a second run into the same directory is refused in one line that says who holds it."""
import fcntl
import os
import sys
from contextlib import contextmanager

from .errors import UserError

LOCK = ".harness.infra.lock"


@contextmanager
def exclusive(directory):
    """Hold DIR's lock (creating DIR) while the block runs; UserError naming the holder if another run has it. A DIR
    this made and the block left empty (refused input) is removed again."""
    created = not os.path.isdir(directory)
    os.makedirs(directory, exist_ok=True)
    path = os.path.join(directory, LOCK)
    fd = os.open(path, os.O_RDWR | os.O_CREAT | os.O_NOFOLLOW, 0o644)
    try:
        try:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            holder = os.pread(fd, 4096, 0).decode("utf-8", "replace").strip() or "another process"
            raise UserError(f"{directory} is being written by {holder}; wait for it or choose another -o") from None
        os.ftruncate(fd, 0)
        os.pwrite(fd, f"harness pid {os.getpid()} ({' '.join(['harness'] + sys.argv[1:])[:300]})".encode(), 0)
        try:
            yield
        finally:
            os.unlink(path)                 # while still held: the next writer makes a fresh one
    finally:
        os.close(fd)
        if created and not os.listdir(directory):
            os.rmdir(directory)
