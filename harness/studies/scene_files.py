"""A scene run's files: series.csv, checks.csv and scene.json written whole, and read back into a SceneRun."""
import json
import os

import pandas as pd

from ..data.results import write_csv
from ..infra.files import write_text
from .scene_rows import SceneRun

SERIES, CHECKS, DESCRIPTION = "series.csv", "checks.csv", "scene.json"


def write_scene(directory, run, command=""):
    """series.csv, checks.csv and scene.json (what the run was, the checks not applicable, the engines asked for that
    did not run it, the command that ran it) in `directory` (created if missing), each written whole or not at all."""
    os.makedirs(directory, exist_ok=True)
    write_csv(run.series, os.path.join(directory, SERIES))
    write_csv(run.checks, os.path.join(directory, CHECKS))
    described = {"scene": run.scene, "law": run.law, "values": run.values, "radius": run.radius,
                 "not_applicable": run.skipped, "not_run": run.unavailable, "command": command}
    write_text(os.path.join(directory, DESCRIPTION), json.dumps(described, indent=1) + "\n")


def load_scene(directory):
    """(the SceneRun, the command) a scene's directory holds (write_scene's files)."""
    with open(os.path.join(directory, DESCRIPTION)) as handle:
        described = json.load(handle)
    series = pd.read_csv(os.path.join(directory, SERIES))
    checks = pd.read_csv(os.path.join(directory, CHECKS), keep_default_na=False, na_values=[""])
    checks["passed"] = checks.passed.astype(str) == "True"
    return SceneRun(described["scene"], series, checks, described["not_applicable"], described["not_run"],
                    described["law"], described["values"], described["radius"]), described["command"]
