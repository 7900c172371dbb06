"""Run an engine as a subprocess in its own directory, with a timeout, keeping the tail of its log."""
import os
import signal
import subprocess
import threading
import time
from dataclasses import dataclass

LOG_TAIL_LINES = 40
LIVE = set()                # engine processes running now, whichever thread started them
_live_lock = threading.Lock()
STOPPED = threading.Event()  # set by kill_all: no engine process starts until allow() clears it


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
    if STOPPED.is_set():
        raise EngineFailure("not started: harness is stopping")
    try:
        with open(log_path, "wb") as log:
            proc = subprocess.Popen(argv, cwd=workdir, stdout=log, stderr=subprocess.STDOUT,
                                    stdin=subprocess.DEVNULL, env=env, start_new_session=True)
            with _live_lock:
                LIVE.add(proc)
                stopping = STOPPED.is_set()
            try:
                if stopping:                     # kill_all ran while this one was starting
                    raise EngineFailure("stopped: harness is stopping")
                code = proc.wait(timeout=timeout_s)
            except subprocess.TimeoutExpired:
                kill(proc)
                raise EngineFailure(f"{os.path.basename(argv[0])} did not finish within {timeout_s:g} s (killed)",
                                    read_tail(log_path)) from None
            except BaseException:
                kill(proc)
                raise
            finally:
                with _live_lock:
                    LIVE.discard(proc)
    except FileNotFoundError:
        raise EngineFailure(f"{argv[0]} not found") from None
    log_tail = read_tail(log_path)
    if code != 0:
        how = f"killed by signal {-code}" if code < 0 else f"exit code {code}"
        raise EngineFailure(f"{os.path.basename(argv[0])} failed ({how})", log_tail)
    return Completed(time.perf_counter() - start, log_tail)


def kill(proc):
    """Kill an engine's whole process group and reap it (nothing to do if it has ended already)."""
    try:
        os.killpg(proc.pid, signal.SIGKILL)
    except ProcessLookupError:
        pass
    proc.wait()


def allow():
    """Engine processes may start (again)."""
    STOPPED.clear()


def kill_all():
    """Kill every engine process still running and start no other (an interrupted harness leaves none behind)."""
    with _live_lock:
        STOPPED.set()
        procs = list(LIVE)
    for proc in procs:
        kill(proc)


def read_tail(path):
    try:
        with open(path, "rb") as handle:
            return tail(handle.read().decode("utf-8", "replace"))
    except OSError:
        return ""
