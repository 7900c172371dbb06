"""The finished runs of an unfinished compare, kept in DIR/.partial/ as one table per run named by the run's key (a
hash of everything that determines its result: engines/run.py's Run.key), so that the next compare into DIR reruns only
what is missing. A finished compare removes them."""
import os
import shutil

from ..infra.files import write_text
from .keys import run_key
from ..data.results import read_csv

PARTIAL = ".partial"


class PartialRuns:
    """Finished runs of DIR by key: get(run) -> its results table or None; put(run, frame); clear()."""

    def __init__(self, directory):
        self.path = os.path.join(directory, PARTIAL)

    def _file(self, run):
        return os.path.join(self.path, run_key(run) + ".csv")

    def get(self, run):
        path = self._file(run)
        return read_csv(path) if os.path.isfile(path) else None

    def put(self, run, frame):
        os.makedirs(self.path, exist_ok=True)
        write_text(self._file(run), frame.to_csv(index=False, float_format="%.17g"))

    def count(self):
        return len(os.listdir(self.path)) if os.path.isdir(self.path) else 0

    def clear(self):
        shutil.rmtree(self.path, ignore_errors=True)
