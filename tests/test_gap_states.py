"""A starting gap and states during contact (issue 42 item 4): the options, the run's key, the reference kernel's
free approach and recorded states against theory."""
import pytest

from harness.commands import main
from harness.engines.run import scene_identity
from harness.runs.request import scene_from


def test_default_gap_and_times_leave_a_runs_identity_as_it_was():
    identity = scene_identity(scene_from(en=(0.5,), angles=(10.0,)))
    assert "gap" not in identity and "at_times" not in identity
    assert scene_identity(scene_from(en=(0.5,), angles=(10.0,), gap=1e-4))["gap"] == 1e-4
    assert scene_identity(scene_from(en=(0.5,), angles=(10.0,), at_times=(1e-5,)))["at_times"] == [1e-5]


@pytest.mark.parametrize("command", ["run", "compare"])
def test_gap_and_times_are_taken_by_run_and_compare(command, tmp_path, capsys):
    out = tmp_path / ("r.csv" if command == "run" else "d")
    extra = ["--engines", "reference"] if command == "compare" else []
    code = main([command, "--model", "linear-spring-dashpot", "--en", "0.5", "--angles", "0", "--gap", "1e-5",
                 "--at-times", "1e-5,2e-5", "--quiet", "-o", str(out), *extra])
    assert code == 0, capsys.readouterr().err
