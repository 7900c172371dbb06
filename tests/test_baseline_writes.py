"""The committed baseline is written only where a user names it (issue 40.3)."""
import hashlib
import os

import pytest

from harness.studies.baseline import BASELINE_FILE, DEFAULT_BASELINE
from harness.commands import main


def digest(path):
    with open(path, "rb") as handle:
        return hashlib.sha256(handle.read()).hexdigest()


@pytest.mark.parametrize("args, words", [
    (["baseline", "--update", "--baseline", ""], "--baseline is empty"),
    (["baseline", "--update", "--baseline", "  "], "--baseline is empty"),
    (["baseline", "--update"], "writes only where --baseline names a directory"),
    (["check", "--baseline", ""], "--baseline is empty"),
])
def test_no_baseline_is_written_or_read_unless_named(args, words, tmp_path, monkeypatch, capfd):
    """From any directory: one line, exit 2, the package's own baseline.csv byte for byte as it was, nothing in the
    working directory."""
    committed = os.path.join(DEFAULT_BASELINE, BASELINE_FILE)
    before = digest(committed)
    monkeypatch.chdir(tmp_path)
    assert main(args) == 2
    (line,) = capfd.readouterr().err.strip().splitlines()
    assert words in line
    assert digest(committed) == before
    assert os.listdir(tmp_path) == []
