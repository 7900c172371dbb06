"""What a scene's run hands back: the SceneRun (series and closed-form checks, per engine), a row of checks.csv and
the series of one case (scene_files.py writes and reads them)."""
import math
from dataclasses import dataclass, field

import numpy as np
import pandas as pd

CHECK_COLUMNS = ("check", "engine", "case", "quantity", "value", "expected", "error", "tolerance", "passed", "note")
SERIES_COLUMNS = ("engine", "case", "t", "body", "x", "z", "vx", "vz", "w")


@dataclass(frozen=True)
class SceneRun:
    """A scene's run: its `series` (one row per engine, case, recorded time and body) and its `checks`
    (CHECK_COLUMNS: the closed-form checks of the reference and of each engine, and each engine's agreement with
    its dialect), the checks that do not apply to the law with the reason (`skipped`, {check: reason}) and the
    engines asked for that did not run it, with the reason or the failure and its log tail (`unavailable`); the
    law's name, the kind's parameter values and the spheres' radius describe it."""
    scene: str
    series: pd.DataFrame
    checks: pd.DataFrame
    skipped: dict
    unavailable: dict = field(default_factory=dict)
    law: str = ""
    values: dict = field(default_factory=dict)
    radius: float = math.nan

    def __repr__(self):
        passed = int(self.checks.passed.sum())
        return (f"SceneRun({self.scene}: {passed} of {len(self.checks)} checks passed; "
                f".series {len(self.series)} rows, .checks)")


def check_row(check, engine, case, value, arguments, note):
    """One row of checks.csv: the measured value against the check's closed form at `arguments`."""
    expected = check.closed_form(**arguments)
    error = abs(value - expected) / abs(expected) if check.relative and expected else abs(value - expected)
    passed = bool(np.isfinite(error) and error <= check.tolerance)
    return dict(check=check.name, engine=engine, case=case, quantity=check.quantity, value=value, expected=expected,
                error=error, tolerance=check.tolerance, passed=passed, note=note)


def series_rows(engine, case, grid, trace):
    """The series of one case on `engine`: each recorded time and body with x, z, vx, vz, w."""
    n_times, n_bodies, _ = trace.shape
    frame = pd.DataFrame(trace.reshape(n_times * n_bodies, -1), columns=["x", "z", "vx", "vz", "w"])
    frame.insert(0, "body", np.tile(np.arange(n_bodies), n_times))
    frame.insert(0, "t", np.repeat(grid, n_bodies))
    frame.insert(0, "case", case)
    frame.insert(0, "engine", engine)
    return frame

