"""Compares stopped by SIGTERM at random moments while both cores are busy end in time and leave nothing behind
(tools/signals_under_load.py; four runs here, 50 when run by hand: docs/testing.md)."""
import subprocess
import sys
from pathlib import Path

from conftest import needs

TOOL = Path(__file__).resolve().parent.parent / "tools" / "signals_under_load.py"


@needs("yade")
@needs("liggghts")
def test_compares_stopped_at_random_moments_under_load_end_and_leave_nothing():
    done = subprocess.run([sys.executable, str(TOOL), "--runs", "4"], capture_output=True, text=True, timeout=900)
    assert done.returncode == 0, done.stdout + done.stderr
    assert "4 of 4 runs passed" in done.stdout
