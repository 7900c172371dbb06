"""Test configuration: make tests/oracles.py importable as `oracles`."""
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
