"""Test configuration: make tests/oracles.py importable as `oracles`."""
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))


def fake_executable(directory, body, name="fake-engine"):
    """A small shell script standing in for an engine that crashes, hangs or writes a truncated result."""
    import stat
    path = directory / name
    path.write_text("#!/bin/sh\n" + body + "\n")
    path.chmod(path.stat().st_mode | stat.S_IEXEC)
    return str(path)
