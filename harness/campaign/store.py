"""The campaign store: a directory of Parquet files that pandas.read_parquet(STORE) reads as one tidy table (the
results columns, the task key, the failed task's log tail). Each task is written as its own fragment, whole or not
at all (a temporary name, then a rename); compaction merges the finished fragments into one file. A task is keyed
by a hash of everything that determines its result (harness.plan.Run.key), so a rerun computes only missing keys."""
import os
import uuid

import numpy as np
import pandas as pd
import pyarrow as pa
import pyarrow.parquet as pq

from ..keys import run_key
from ..results import COLUMNS

KEY, LOG_TAIL = "task_key", "log_tail"
STRINGS = ("model", "dialect", "engine", "engine_version", "status", "message", KEY, LOG_TAIL)


def tidy(frame, key, log_tail=""):
    """A task's rows in the store's schema: every results column (floats as float64, words as strings), its key,
    and the log tail of a failed task."""
    out = frame.reindex(columns=list(COLUMNS)).assign(**{KEY: key, LOG_TAIL: log_tail})
    for column in out.columns:
        if column in STRINGS:
            out[column] = out[column].fillna("").astype(str)
        else:
            out[column] = pd.to_numeric(out[column], errors="coerce").astype(np.float64)
    return out.reset_index(drop=True)


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
    files data-<id>.parquet, in one directory."""

    def __init__(self, path):
        self.path = os.fspath(path)
        os.makedirs(self.path, exist_ok=True)

    def _write(self, name, frame):
        tmp = os.path.join(self.path, f".{name}.{uuid.uuid4().hex}.tmp")      # dot files: no reader sees them
        pq.write_table(pa.Table.from_pandas(frame, preserve_index=False), tmp)
        os.replace(tmp, os.path.join(self.path, name))

    def put(self, key, frame, log_tail=""):
        """Store one task's rows (status 'failed' rows with the log tail for a task that failed)."""
        failed = (frame.status == "failed").any()
        self._write(f"{'failed' if failed else 'part'}-{key}.parquet", tidy(frame, key, log_tail))
        if not failed:
            self._remove(f"failed-{key}.parquet")

    def _remove(self, name):
        try:
            os.remove(os.path.join(self.path, name))
        except FileNotFoundError:
            pass

    def files(self, prefix=""):
        return sorted(n for n in os.listdir(self.path) if n.endswith(".parquet") and n.startswith(prefix))

    def finished(self):
        """Keys of every task stored with results (failed tasks are not: a rerun retries them)."""
        names = [n for n in self.files() if not n.startswith("failed-")]
        keys = set()
        for name in names:
            keys.update(pq.read_table(os.path.join(self.path, name), columns=[KEY]).column(KEY).to_pylist())
        return keys

    def compact(self):
        """Merge the finished fragments into one file; returns how many it merged."""
        parts = self.files("part-")
        if len(parts) < 2:
            return 0
        frame = pd.concat([pd.read_parquet(os.path.join(self.path, n)) for n in parts], ignore_index=True)
        self._write(f"data-{uuid.uuid4().hex[:12]}.parquet", frame)
        for name in parts:
            self._remove(name)
        return len(parts)

    def get(self, run):
        """The results table of `run` if the store holds it (a run cache for compare and check), else None."""
        key = run_key(run)
        for name in (f"part-{key}.parquet",) + tuple(self.files("data-")):
            path = os.path.join(self.path, name)
            if os.path.exists(path):
                rows = pd.read_parquet(path, filters=[(KEY, "==", key)])
                if len(rows):
                    return rows.drop(columns=[KEY, LOG_TAIL]).reset_index(drop=True)
        return None

    def put_run(self, run, frame):
        self.put(run_key(run), frame)

    def table(self):
        """The whole store as one table (a task's rows once, even if a crash left it in two files)."""
        names = self.files()
        if not names:
            return tidy(pd.DataFrame(columns=list(COLUMNS)), "").iloc[:0]
        frame = pd.concat([pd.read_parquet(os.path.join(self.path, n)).assign(_file=i) for i, n in enumerate(names)],
                          ignore_index=True)
        first = frame.groupby(KEY)["_file"].transform("min")
        return frame[frame._file == first].drop(columns="_file").reset_index(drop=True)
