"""Run an engine as a subprocess in its own directory and process group, with a timeout, its log streamed to disk
and only its tail read; killed with harness (SIGKILL on the parent's death), listening on no network interface;
every program found by its absolute path (harness.infra.programs), and the engine's PATH without relative entries."""
import os
import shutil
import signal
import subprocess
import threading
import time
from dataclasses import dataclass
from functools import lru_cache

from ..infra.programs import search_path, which

LOG_TAIL_LINES = 40
LOG_TAIL_BYTES = 64 * 1024
# OpenMPI (LIGGGHTS' runtime) as a singleton with no daemon, shared memory only: no TCP listener on any interface,
# and its session directory under the run's own directory (TMPDIR), removed with it
ISOLATED = {"OMPI_MCA_ess_singleton_isolated": "1", "OMPI_MCA_btl": "self,vader",
            "OMPI_MCA_btl_tcp_if_include": "lo", "OMPI_MCA_oob_tcp_if_include": "lo", "OMP_NUM_THREADS": "1"}
PARENT_DEATH = ["setpriv", "--pdeathsig", "KILL", "--"]     # the engine dies with harness, even by SIGKILL
LIVE = set()                # engine processes running now, whichever thread started them
_live_lock = threading.Lock()
STOPPED = threading.Event()  # set by kill_all: no engine process starts until allow() clears it


class EngineFailure(Exception):
    """An engine run that produced no usable result; `log_tail` goes into the report."""

    def __init__(self, message, log_tail="", timed_out=False):
        super().__init__(message)
        self.log_tail = log_tail
        self.timed_out = timed_out


@dataclass(frozen=True)
class Completed:
    """A finished engine run: wall time and the tail of its combined output."""
    wall_s: float
    log_tail: str


def tail(text, lines=LOG_TAIL_LINES):
    return "\n".join(text.splitlines()[-lines:])


def launcher():
    path = which(PARENT_DEATH[0])
    return [path, *PARENT_DEATH[1:]] if path else []


PRIVATE_TMP = "private-tmp"     # the directory of a run that the engine sees as /tmp (its_own_tmp)
# /tmp becomes PRIVATE_TMP; a working directory under /tmp, hidden by that, is bound again at its own path inside
BIND_TMP = (f'W=$(pwd -P) && mount --bind {PRIVATE_TMP} /tmp && case "$W" in /tmp/*) mkdir -p "$W" && '
            'mount --no-canonicalize --bind /proc/self/cwd "$W" && cd "$W";; esac && exec "$@"')


@lru_cache(maxsize=None)
def its_own_tmp():
    """The argv prefix that runs a command in a mount namespace of its own where /tmp is PRIVATE_TMP of its working
    directory (for an engine that writes to /tmp whatever TMPDIR says, as YADE does); [] where the system allows no
    such namespace (no unshare, user namespaces disabled), tried once."""
    unshare, shell = which("unshare"), which("sh")
    if unshare is None or shell is None:
        return []
    user = [] if os.geteuid() == 0 else ["--user", "--map-root-user"]
    prefix = [unshare, "--mount", "--propagation", "private", *user, "--", shell, "-c", BIND_TMP, "sh"]
    with scratch("probe") as probe:
        os.mkdir(os.path.join(probe, PRIVATE_TMP))
        try:
            tried = subprocess.run([*prefix, "true"], cwd=probe, stdin=subprocess.DEVNULL, capture_output=True,
                                   timeout=30, env={**os.environ, "PATH": search_path()})
        except (OSError, subprocess.TimeoutExpired):
            return []
    return prefix if tried.returncode == 0 else []


def run_engine(argv, workdir, timeout_s, env=None, log_name="engine.log", private_tmp=False):
    """Run argv in workdir (own process group); EngineFailure on a missing binary, a crash or a timeout. With
    `private_tmp`, what the engine writes to /tmp goes to workdir/PRIVATE_TMP, and is removed with workdir."""
    log_path = os.path.join(workdir, log_name)
    start = time.perf_counter()
    if STOPPED.is_set():
        raise EngineFailure("not started: harness is stopping")
    program = which(argv[0])
    if program is None:
        raise EngineFailure(f"{argv[0]} not found")
    argv = [program, *argv[1:]]
    env = {**(os.environ if env is None else env), **ISOLATED, "TMPDIR": workdir}
    env["PATH"] = search_path(env.get("PATH", os.defpath))
    prefix = its_own_tmp() if private_tmp else []
    if prefix:
        os.makedirs(os.path.join(workdir, PRIVATE_TMP), exist_ok=True)
    try:
        with open(log_path, "wb") as log:
            proc = subprocess.Popen(launcher() + prefix + argv, cwd=workdir, stdout=log, stderr=subprocess.STDOUT,
                                    stdin=subprocess.DEVNULL, env=env, start_new_session=True)
            with _live_lock:
                LIVE.add(proc)
                stopping = STOPPED.is_set()
            try:
                if stopping:                     # kill_all ran while this one was starting
                    raise EngineFailure("stopped: harness is stopping")
                code = proc.wait(timeout=timeout_s)
                kill(proc)                       # whatever it left in its group (an MPI daemon) ends with it
            except subprocess.TimeoutExpired:
                kill(proc)
                raise EngineFailure(f"{os.path.basename(argv[0])} did not finish within {timeout_s:g} s (killed)",
                                    read_tail(log_path), timed_out=True) from None
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
    """The last LOG_TAIL_LINES lines of a log, reading at most its last LOG_TAIL_BYTES."""
    try:
        with open(path, "rb") as handle:
            handle.seek(max(0, os.path.getsize(path) - LOG_TAIL_BYTES))
            return tail(handle.read().decode("utf-8", "replace"))
    except OSError:
        return ""


ENGINE_TMPDIR = "yade_tmpdir.txt"     # an engine that makes its own directory outside ours names it here


def remove_engine_tmpdir(workdir):
    """Remove the directory an engine made outside `workdir` and named in it (YADE's /tmp/yade-XXXXXX, which it
    removes itself only when it exits normally); nothing when the engine's /tmp was workdir's own (its_own_tmp)."""
    import re
    if os.path.isdir(os.path.join(workdir, PRIVATE_TMP)):
        return
    try:
        with open(os.path.join(workdir, ENGINE_TMPDIR)) as handle:
            path = handle.read().strip()
    except OSError:
        return
    if re.fullmatch(r"/tmp/yade-[A-Za-z0-9]{6}", path) and os.path.isdir(path) and not os.path.islink(path):
        shutil.rmtree(path, ignore_errors=True)


def scratch(what):
    """A temporary directory for one engine run, named after this process (harness-PID-what-XXXX), so that one
    left by a killed harness is recognised and removed by the next (sweep_stale)."""
    import tempfile
    return tempfile.TemporaryDirectory(prefix=f"harness-{os.getpid()}-{what}-")


def sweep_stale(root=None):
    """Remove the scratch directories of harness processes that no longer run (killed before they could clean up);
    returns how many."""
    import re
    import tempfile
    root = root or tempfile.gettempdir()
    removed = 0
    for name in os.listdir(root):
        match = re.fullmatch(r"harness-(\d+)-.+", name)
        path = os.path.join(root, name)
        if not match or int(match.group(1)) == os.getpid() or not os.path.isdir(path) or os.path.islink(path):
            continue
        try:
            os.kill(int(match.group(1)), 0)
            continue                                   # its process is alive
        except ProcessLookupError:
            pass
        except PermissionError:
            continue                                   # alive, another user's
        for inner, _, files in os.walk(path):
            if ENGINE_TMPDIR in files:
                remove_engine_tmpdir(inner)
        shutil.rmtree(path, ignore_errors=True)
        removed += 1
    return removed


def ended_lines(path, engine, what):
    """The lines of an engine's output file before its closing END line; an EngineFailure naming `what` when the
    file is missing or has no END line (a run cut short)."""
    try:
        with open(path) as handle:
            lines = handle.read().splitlines()
    except OSError:
        raise EngineFailure(f"{engine} wrote no {what}") from None
    if not lines or lines[-1] != "END":
        raise EngineFailure(f"{engine} {what} is truncated (no END line)")
    return lines[:-1]
