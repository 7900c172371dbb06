"""The Python API (harness.run, harness.compare, ...: notebook.py, its results in notebook_results.py) and what it
shares with the commands (requests.py)."""
