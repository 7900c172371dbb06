"""One fragment of a campaign store, checked before anything reads it: a regular file (never opened if it is a
FIFO, a link or a directory), a Parquet file whose footer reads, with the store's key column, and the task keys it
holds. A fragment that fails is damaged, with the reason in words."""
import os
import re
import stat

import pyarrow as pa
import pyarrow.parquet as pq

from .reading import kind_of

KEY, LOG_TAIL = "task_key", "log_tail"
REQUIRED = (KEY, "engine", "status")            # what makes a Parquet file a store fragment
SINGLE = re.compile(r"(?:part|failed)-([0-9a-f]+)\.parquet")   # a fragment of one task, named by its key


class Damaged(Exception):
    """A fragment that cannot be read as the store's; str() says why."""


def is_fragment(name):
    """Every visible Parquet name is a fragment (pandas.read_parquet(STORE) reads them all); dot names are not."""
    return name.endswith(".parquet") and not name.startswith(".")


def keys_of(path):
    """The task keys a fragment holds; Damaged when it is not a readable store fragment."""
    try:
        fd = os.open(path, os.O_RDONLY | os.O_NONBLOCK | os.O_NOFOLLOW | os.O_CLOEXEC)
    except OSError as exc:
        mode = _mode(path)
        raise Damaged(f"it is {kind_of(mode)}" if mode is not None and not stat.S_ISREG(mode)
                      else f"it cannot be opened: {exc.strerror}") from None
    info = os.fstat(fd)
    if not stat.S_ISREG(info.st_mode) or info.st_size == 0:
        os.close(fd)
        raise Damaged("it is empty" if stat.S_ISREG(info.st_mode) else f"it is {kind_of(info.st_mode)}")
    with os.fdopen(fd, "rb") as handle:
        try:
            parquet = pq.ParquetFile(handle)
            names = parquet.schema_arrow.names
            missing = [column for column in REQUIRED if column not in names]
            if missing:
                raise Damaged(f"it is a Parquet file but not a store fragment: it has no {missing[0]} column")
            keys = parquet.read(columns=[KEY]).column(KEY)
        except (OSError, pa.ArrowException) as exc:
            raise Damaged(f"it is not a whole Parquet file ({str(exc).splitlines()[0][:120]})") from None
    if not pa.types.is_string(keys.type) and not pa.types.is_large_string(keys.type):
        raise Damaged(f"its {KEY} column holds {keys.type}, not text")
    found = set(keys.to_pylist())
    single = SINGLE.fullmatch(os.path.basename(path))
    if single and found != {single.group(1)}:
        raise Damaged(f"it does not hold the one task its name says ({single.group(1)})")
    return frozenset(found)


def _mode(path):
    try:
        return os.lstat(path).st_mode
    except OSError:
        return None
