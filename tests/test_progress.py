"""Progress on stderr: plain lines with done/total and what finished when stderr is not a terminal (a CI log),
none for a quick command or with --quiet, never on stdout."""
import io

import harness.views.progress as progress_module
from harness.views.progress import Progress


class Log(io.StringIO):
    def isatty(self):
        return False


def test_plain_lines_count_the_steps_and_say_what_finished(monkeypatch):
    monkeypatch.setattr(progress_module, "QUIET_START_S", 0.0)
    log = Log()
    with Progress("compare", stream=log) as progress:
        progress.expect(3)
        for what in ("liggghts e_n 0.5", "yade e_n 0.5", "report"):
            progress.advance(what)
    lines = log.getvalue().splitlines()
    assert [line.split("]")[0] for line in lines] == ["harness: compare [1/3", "harness: compare [2/3",
                                                      "harness: compare [3/3"]
    assert lines[-1].endswith("about 0 s left: report")


def test_a_quick_command_and_a_quiet_one_print_nothing():
    for quiet in (False, True):
        log = Log()
        with Progress("run", quiet=quiet, stream=log) as progress:
            progress.expect(2)
            progress.advance("e_n 0.5")
            progress.advance("e_n 0.9")
        assert log.getvalue() == ""


def test_compare_progress_goes_to_stderr_not_stdout(tmp_path, capfd, monkeypatch):
    from harness.commands import main
    monkeypatch.setattr(progress_module, "QUIET_START_S", 0.0)
    main(["compare", "--model", "thornton", "--engines", "reference", "--en", "0.5", "--angles", "10", "-o",
          str(tmp_path), "--quiet"])
    out, err = capfd.readouterr()
    assert out == "agreement: not checked: the reference alone was asked for\n" and "harness: compare" not in err
    main(["compare", "--model", "thornton", "--engines", "reference", "--en", "0.5", "--angles", "10", "-o",
          str(tmp_path)])
    out, err = capfd.readouterr()
    assert "harness: compare thornton [" in err and "harness: compare" not in out
    assert "report" in err.splitlines()[-1]
