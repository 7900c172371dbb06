"""Reading the files a user points harness at: opened only when they are regular files (a FIFO would block for
ever, a device behind a link never end), and a table only when it holds the columns and numbers its reader needs;
anything else is one UserError line naming the file."""
import os
import stat

import pandas as pd

from .errors import UserError


def kind_of(mode):
    """What a file that is not regular is, in words."""
    return ("a directory" if stat.S_ISDIR(mode) else "a FIFO" if stat.S_ISFIFO(mode) else
            "a socket" if stat.S_ISSOCK(mode) else "a device" if stat.S_ISCHR(mode) or stat.S_ISBLK(mode) else
            "not a regular file")


def open_regular(path, binary=False):
    """`path` opened for reading (utf-8 text, or bytes) when it is a regular file, links followed; FileNotFoundError
    for a missing one, UserError for anything else. Opening does not block: a FIFO is opened without waiting for a
    writer, then refused."""
    try:
        fd = os.open(path, os.O_RDONLY | os.O_NONBLOCK | os.O_CLOEXEC)
    except FileNotFoundError:
        raise
    except OSError as exc:
        raise UserError(f"cannot read {path}: {exc.strerror}") from None
    mode = os.fstat(fd).st_mode
    if not stat.S_ISREG(mode):
        os.close(fd)
        raise UserError(f"will not read {path}: it is {kind_of(mode)}, not a regular file")
    os.set_blocking(fd, True)
    return os.fdopen(fd, "rb") if binary else os.fdopen(fd, "r", encoding="utf-8", newline="")


def read_table(path, required=(), numeric=(), what="table", text=()):
    """The CSV table at `path` (a regular file) holding every `required` column, its `numeric` columns (where
    present) as numbers and its `text` columns as strings; an empty file is an empty table. UserError for a
    binary, foreign, cut or mistyped file."""
    try:
        with open_regular(path) as handle:
            frame = pd.read_csv(handle, dtype={c: str for c in text}, keep_default_na=True)
    except pd.errors.EmptyDataError:
        return pd.DataFrame()
    except (UnicodeDecodeError, pd.errors.ParserError, ValueError) as exc:
        if isinstance(exc, UserError):
            raise
        raise UserError(f"cannot read {what} {path}: not a CSV table ({str(exc).splitlines()[0][:80]})") from None
    missing = [c for c in required if c not in frame.columns]
    if missing:
        raise UserError(f"{path} is not a harness {what} (missing {', '.join(missing[:3])}"
                        f"{'...' if len(missing) > 3 else ''})")
    for column in (c for c in numeric if c in frame.columns):
        values = pd.to_numeric(frame[column], errors="coerce")
        wrong = frame[column].notna().to_numpy() & values.isna().to_numpy()
        if wrong.any():
            row = int(wrong.argmax())
            raise UserError(f"{path} is damaged: a value that is not a number in {column} "
                            f"({str(frame[column].iat[row])[:30]!r}, data row {row + 1})")
        frame[column] = values.astype(float)
    return frame
