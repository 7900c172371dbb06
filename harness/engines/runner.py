"""Run an engine as a subprocess in its own directory, with a timeout, keeping the tail of its log."""
import os
import signal
import subprocess
import time
from dataclasses import dataclass

LOG_TAIL_LINES = 40


class EngineFailure(Exception):
    """An engine run that produced no usable result; `log_tail` goes into the report."""

    def __init__(self, message, log_tail=""):
        super().__init__(message)
        self.log_tail = log_tail


@dataclass(frozen=True)
class Completed:
    """A finished engine run: wall time and the tail of its combined output."""
    wall_s: float
    log_tail: str


def tail(text, lines=LOG_TAIL_LINES):
    return "\n".join(text.splitlines()[-lines:])


def run_engine(argv, workdir, timeout_s, env=None, log_name="engine.log"):
    """Run argv in workdir (own process group); EngineFailure on a missing binary, a crash or a timeout."""
    log_path = os.path.join(workdir, log_name)
    start = time.perf_counter()
    try:
        with open(log_path, "wb") as log:
            proc = subprocess.Popen(argv, cwd=workdir, stdout=log, stderr=subprocess.STDOUT,
                                    stdin=subprocess.DEVNULL, env=env, start_new_session=True)
            try:
                code = proc.wait(timeout=timeout_s)
            except subprocess.TimeoutExpired:
                os.killpg(proc.pid, signal.SIGKILL)
                proc.wait()
                raise EngineFailure(f"{os.path.basename(argv[0])} did not finish within {timeout_s:g} s (killed)",
                                    read_tail(log_path)) from None
            except BaseException:
                os.killpg(proc.pid, signal.SIGKILL)
                proc.wait()
                raise
    except FileNotFoundError:
        raise EngineFailure(f"{argv[0]} not found") from None
    log_tail = read_tail(log_path)
    if code != 0:
        how = f"killed by signal {-code}" if code < 0 else f"exit code {code}"
        raise EngineFailure(f"{os.path.basename(argv[0])} failed ({how})", log_tail)
    return Completed(time.perf_counter() - start, log_tail)


def read_tail(path):
    try:
        with open(path, "rb") as handle:
            return tail(handle.read().decode("utf-8", "replace"))
    except OSError:
        return ""
