"""A scene's closed-form checks in the terminal (one line each) and as JSON."""
import math

from ..infra import strict_json


def check_lines(run):
    """One line per check row: passed or failed, the case, the value, the expected value and the error; then each
    check that does not apply to the law, with why."""
    for row in run.checks.itertuples():
        outcome = "passed" if row.passed else "FAILED"
        error = "no value" if math.isnan(row.value) else f"error {row.error:.3g} (tolerance {row.tolerance:g})"
        where = row.case if row.engine == "reference" else f"{row.engine}, {row.case}"
        yield (f"{outcome} {row.check} [{where}]: {row.value:.9g}, expected {row.expected:.9g}, {error}")
    for check, reason in run.skipped.items():
        yield f"not applicable {check}: {reason}"


def checks_json(run):
    """The checks' rows and the checks not applicable, as one JSON document."""
    return strict_json.dumps({"scene": run.scene, "checks": run.checks.to_dict(orient="records"),
                              "not_applicable": run.skipped, "engines_not_run": run.unavailable}, indent=1, default=str)
