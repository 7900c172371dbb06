"""A closed stdout (`harness ... | head`) ends harness quietly, as it ends a Unix tool: exit 141 (128 + SIGPIPE, what
a shell reports for a tool stopped by its closed pipe), no traceback, and whatever the command wrote before it
printed kept."""
import os
import subprocess
import sys

import pytest

COMMANDS = {
    "models": ["models"],
    "help": ["compare", "--help"],
    "compare": ["compare", "--model", "hertz-mindlin", "--en", "0.5", "--angles", "10,40", "--engines", "reference",
                "--verbose", "-o", "{out}"],
    "paper": ["paper", "--laws", "linear-spring-dashpot", "--steps-per-contact", "200", "-o", "{out}"],
}


def with_closed_stdout(argv):
    """(exit code, stderr) of `harness ARGV` writing into a pipe nobody reads (its reader closed before it starts)."""
    reader, writer = os.pipe()
    os.close(reader)
    try:
        done = subprocess.run([sys.executable, "-m", "harness", *argv], stdout=writer, stderr=subprocess.PIPE,
                              text=True, timeout=600)
    finally:
        os.close(writer)
    return done.returncode, done.stderr


@pytest.mark.parametrize("name", list(COMMANDS))
def test_a_closed_stdout_ends_harness_quietly(tmp_path, name):
    out = tmp_path / "out"
    code, err = with_closed_stdout([a.replace("{out}", str(out)) for a in COMMANDS[name]])
    expected = 0 if name == "help" else 141          # argparse drops a help text it cannot write, and exits 0
    assert code == expected and "Traceback" not in err and "error" not in err, (code, err)
    if name == "compare":
        assert (out / "results.csv").is_file() and (out / "report.html").is_file()
    if name == "paper":
        assert (out / "paper.html").is_file()


def test_a_broken_pipe_that_is_not_stdouts_stays_an_internal_error(monkeypatch, capfd):
    """A BrokenPipeError while stdout is open (here raised by the command itself) is a bug, reported as one."""
    from harness.commands import main, models

    def broken(args):
        raise BrokenPipeError(32, "Broken pipe")
    monkeypatch.setattr(models, "main", broken)
    assert main(["models"]) == 4
    assert "Traceback" in capfd.readouterr().err
