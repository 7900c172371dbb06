"""The campaign store: a directory of Parquet files that pandas.read_parquet(STORE) reads as one tidy table (the
results columns, the task key, the failed task's log tail). Each task is written as its own fragment, whole or not
at all (a temporary name, then a rename); compaction merges the finished fragments into one file. A task is keyed
by a hash of everything that determines its result (harness.runs.keys.run_key), so a rerun computes only missing keys.
Every fragment is checked when the store is opened: a damaged one is named, or dropped when asked to."""
import os
import shutil
import stat
import sys
import uuid
from contextlib import suppress

import numpy as np
import pandas as pd
import pyarrow as pa
import pyarrow.parquet as pq

from ...infra.errors import UserError
from ...runs.keys import run_key
from ...data.results import COLUMNS, TEXT
from .drop import DROP
from .fragments import KEY, LOG_TAIL, Damaged, is_fragment, keys_of
from .reading import kind_of

SCENE = ("material", "wall", "target", "speed")   # what a task's scene adds to its rows (the swept parameters
#                                                 the results columns leave out)
STRINGS = TEXT + (KEY, LOG_TAIL, "material", "wall", "target")


class DamagedStore(UserError):
    """A store with a fragment that cannot be read: which one and why, and how to drop it."""


def scene_columns(scene):
    """The columns SCENE of a task's scene: the preset its material starts from (a table's values are in radius,
    E, nu, rho, mu), its wall, its target (wall or sphere) and its impact speed as given [m/s] (resultant, or
    normal with normal_speeds)."""
    if scene is None:
        return {}
    return {"material": scene.material, "wall": scene.wall, "target": "sphere" if scene.spheres else "wall",
            "speed": scene.speed}


def tidy(frame, key, log_tail="", scene=None):
    """A task's rows in the store's schema: every results column (floats as float64, words as strings), its key,
    the log tail of a failed task, and the columns SCENE of its scene (blank when not given)."""
    out = frame.reindex(columns=list(COLUMNS)).assign(**{KEY: key, LOG_TAIL: log_tail})
    out = out.assign(material="", wall="", target="", speed=np.nan).assign(**scene_columns(scene))
    for column in out.columns:
        if column in STRINGS:
            out[column] = out[column].fillna("").astype(str)
        else:
            out[column] = pd.to_numeric(out[column], errors="coerce").astype(np.float64)
    return out.reset_index(drop=True)


def rank(name):
    """The order in which copies of one task are taken: compacted files, then single tasks, then any other
    fragment, failed tasks last (a task that also finished is read from where it finished)."""
    for i, prefix in enumerate(("data-", "part-")):
        if name.startswith(prefix):
            return i, name
    return (3 if name.startswith("failed-") else 2), name


class RunCache:
    """A Store seen as a run cache (get(run), put(run, frame)), as compare's partial runs are."""

    def __init__(self, store):
        self.store = store

    def get(self, run):
        return self.store.get(run)

    def put(self, run, frame):
        self.store.put_run(run, frame)


class Store:
    """Fragments part-<key>.parquet (a failed task's: failed-<key>.parquet, retried by the next run) and compacted
    files data-<id>.parquet, in one directory; `held` maps each fragment to the task keys it holds."""

    def __init__(self, path, create=True, drop_damaged=False):
        """Open the store at `path` (made when `create` and missing); every fragment is checked, and a damaged one
        is refused in one line (DamagedStore) or, with `drop_damaged`, removed so that its tasks rerun."""
        self.path = os.fspath(path)
        if not self.path:
            raise UserError("the store path is empty")
        try:
            mode = os.stat(self.path).st_mode
        except FileNotFoundError:
            if not create:
                raise UserError(f"no campaign store at {self.path}") from None
            os.makedirs(self.path)
            mode = os.stat(self.path).st_mode
        except OSError as exc:
            raise UserError(f"cannot use store {self.path}: {exc.strerror}") from None
        if not stat.S_ISDIR(mode):
            raise UserError(f"store {self.path} is {kind_of(mode)}, not a directory")
        self.held = self._scan(drop_damaged)

    def _scan(self, drop_damaged):
        held, damaged = {}, []
        try:
            names = sorted(n for n in os.listdir(self.path) if is_fragment(n))
        except OSError as exc:
            raise UserError(f"cannot read store {self.path}: {exc.strerror}") from None
        for name in names:
            try:
                held[name] = keys_of(os.path.join(self.path, name))
            except Damaged as why:
                damaged.append((name, str(why)))
        if damaged and drop_damaged:
            for name, why in damaged:
                self._drop(name)
                print(f"harness: dropped damaged fragment {os.path.join(self.path, name)} ({why}); its tasks rerun",
                      file=sys.stderr)
        elif damaged:
            name, why = damaged[0]
            more = f" (and {len(damaged) - 1} more damaged)" if len(damaged) > 1 else ""
            raise DamagedStore(f"store {self.path}: fragment {name} is damaged: {why}{more}; rerun with {DROP} to "
                               "remove it (its tasks then rerun)")
        return held

    def _drop(self, name):
        path = os.path.join(self.path, name)
        if os.path.isdir(path) and not os.path.islink(path):
            shutil.rmtree(path)
        else:
            os.unlink(path)

    def read(self, name, **options):
        """The rows of one fragment (never following a link, never blocking on a FIFO swapped in)."""
        fd = os.open(os.path.join(self.path, name), os.O_RDONLY | os.O_NONBLOCK | os.O_NOFOLLOW | os.O_CLOEXEC)
        with os.fdopen(fd, "rb") as handle:
            return pd.read_parquet(handle, **options)

    def _write(self, name, frame):
        tmp = os.path.join(self.path, f".{name}.{uuid.uuid4().hex}.tmp")      # dot files: no reader sees them
        try:
            pq.write_table(pa.Table.from_pandas(frame, preserve_index=False), tmp)
            os.replace(tmp, os.path.join(self.path, name))
        except BaseException:
            with suppress(FileNotFoundError):      # an interrupt mid-write leaves no half fragment behind
                os.unlink(tmp)
            raise
        self.held[name] = frozenset(frame[KEY].unique())

    def put(self, key, frame, log_tail="", scene=None):
        """Store one task's rows (status 'failed' rows with the log tail for a task that failed), with its scene's
        columns."""
        failed = (frame.status == "failed").any()
        self._write(f"{'failed' if failed else 'part'}-{key}.parquet", tidy(frame, key, log_tail, scene))
        if not failed:
            self._remove(f"failed-{key}.parquet")

    def _remove(self, name):
        self.held.pop(name, None)
        try:
            os.remove(os.path.join(self.path, name))
        except FileNotFoundError:
            pass

    def files(self, prefix=""):
        return sorted(n for n in self.held if n.startswith(prefix))

    def finished(self):
        """Keys of every task stored with results (failed tasks are not: a rerun retries them)."""
        return set().union(*(keys for name, keys in self.held.items() if not name.startswith("failed-")))

    def copies(self):
        """{fragment: the task keys to read from it}: each task once, from the first fragment holding it (rank)."""
        taken, out = set(), {}
        for name in sorted(self.held, key=rank):
            out[name] = self.held[name] - taken
            taken |= out[name]
        return out

    def compact(self):
        """Merge the finished fragments into one file, and remove compacted files it holds whole (a crash between
        writing and removing, or a rerun with --no-cache, leaves such copies); returns how many parts it merged."""
        parts = self.files("part-")
        if len(parts) < 2:
            return 0
        frame = pd.concat([self.read(n) for n in parts], ignore_index=True)
        merged = f"data-{uuid.uuid4().hex[:12]}.parquet"
        self._write(merged, frame)
        for name in parts:
            self._remove(name)
        for name in self.files("data-"):
            if name != merged and self.held[name] <= self.held[merged]:
                self._remove(name)
        return len(parts)

    def get(self, run):
        """The results table of `run` if the store holds it finished (a run cache for compare and check), else
        None."""
        key = run_key(run)
        for name in sorted(self.held, key=rank):
            if key in self.held[name] and not name.startswith("failed-"):
                rows = self.read(name, filters=[(KEY, "==", key)])
                return rows.drop(columns=[KEY, LOG_TAIL, *SCENE], errors="ignore").reset_index(drop=True)
        return None

    def put_run(self, run, frame):
        self.put(run_key(run), frame, scene=run.scene)

    def table(self):
        """The whole store as one table, each task's rows once."""
        frames = []
        for name, keys in self.copies().items():
            if keys:
                frame = self.read(name)
                frames.append(frame if keys == self.held[name] else frame[frame[KEY].isin(keys)])
        if not frames:
            return tidy(pd.DataFrame(columns=list(COLUMNS)), "").iloc[:0]
        return pd.concat(frames, ignore_index=True)
