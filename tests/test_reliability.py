"""Nothing leaked and nothing lost: engine processes and temporary directories end with harness, whatever stops it
(Ctrl-C, SIGTERM, SIGHUP, SIGKILL); a hung engine costs one timeout; logs are read from their tail; a LIGGGHTS run
listens on no network interface."""
import json
import os
import signal
import subprocess
import sys
import threading
import time
from pathlib import Path

import numpy as np
import pytest

from conftest import fake_executable, interruptible, needs
from harness.engines import liggghts
from harness.engines.executable import BANNER_TIMEOUT_S as VERSION_TIMEOUT_S
from harness.engines.runner import read_tail, run_engine, sweep_stale

# --- sockets -------------------------------------------------------------------------------------------------------


def descendants(root):
    """Pids of every process below `root` (from /proc's parent links)."""
    children = {}
    for name in os.listdir("/proc"):
        if name.isdigit():
            try:
                with open(f"/proc/{name}/stat") as handle:
                    ppid = int(handle.read().rsplit(")", 1)[1].split()[1])
            except (OSError, IndexError, ValueError):
                continue
            children.setdefault(ppid, []).append(int(name))
    found, todo = [], [root]
    while todo:
        for child in children.get(todo.pop(), []):
            found.append(child)
            todo.append(child)
    return found


def external_listeners(pids):
    """(address, port) of every TCP socket in LISTEN state, on an address other than loopback, held by `pids`."""
    inodes = set()
    for pid in pids:
        try:
            for fd in os.listdir(f"/proc/{pid}/fd"):
                target = os.readlink(f"/proc/{pid}/fd/{fd}")
                if target.startswith("socket:["):
                    inodes.add(target[8:-1])
        except OSError:
            continue
    found = []
    for table, loopback in (("/proc/net/tcp", {"0100007F"}), ("/proc/net/tcp6", {"00000000000000000000000001000000"})):
        with open(table) as handle:
            for line in handle.readlines()[1:]:
                fields = line.split()
                address, port = fields[1].split(":")
                if fields[3] == "0A" and fields[9] in inodes and address not in loopback:
                    found.append((address, int(port, 16)))
    return found


def listeners_while(start, seconds):
    """Every external listener seen below this process while start() runs (polled for `seconds` at most)."""
    seen, worker = set(), threading.Thread(target=start, daemon=True)
    worker.start()
    deadline = time.time() + seconds
    while worker.is_alive() and time.time() < deadline:
        seen.update(external_listeners(descendants(os.getpid())))
        time.sleep(0.05)
    worker.join(seconds)
    return seen


def test_the_poller_sees_a_listener():
    """Positive control: a child listening on every interface is found."""
    code = "import socket,time; s=socket.socket(); s.bind(('0.0.0.0', 0)); s.listen(); time.sleep(1.5)"
    seen = listeners_while(lambda: subprocess.run([sys.executable, "-c", code]), 5)
    assert any(address == "00000000" for address, _ in seen)


@needs("liggghts")
def test_a_liggghts_run_listens_on_no_network_interface(tmp_path):
    """LIGGGHTS with its OpenMPI runtime, as harness runs it (the banner, then a deck that waits 2 s)."""
    (tmp_path / "in.wait").write_text('print "waiting"\nshell sleep 2\n')
    done = {}

    def start():
        done["run"] = run_engine([liggghts.ENGINE.binary(), "-in", "in.wait"], str(tmp_path), 60)
    seen = listeners_while(start, 30)
    assert "waiting" in done["run"].log_tail
    assert seen == set()
    assert not [name for name in os.listdir("/tmp") if name.startswith("ompi.")]    # its session dir was TMPDIR


# --- signals -------------------------------------------------------------------------------------------------------

HANG = 'echo $$ > "{pidfile}"; exec sleep 60'


def cmdline(pid):
    try:
        with open(f"/proc/{pid}/cmdline") as handle:
            return handle.read()
    except OSError:
        return ""


def alive(pid):
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    with open(f"/proc/{pid}/stat") as handle:            # a zombie has ended
        return handle.read().rsplit(")", 1)[1].split()[0] != "Z"


def start_hung_compare(tmp_path):
    """harness compare with a LIGGGHTS that hangs; returns (process, engine pid, its TMPDIR) once the engine runs."""
    pidfile, scratch = tmp_path / "engine.pid", tmp_path / "tmp"
    scratch.mkdir()
    fake = fake_executable(tmp_path, HANG.format(pidfile=pidfile))
    env = {**os.environ, liggghts.BINARY_VARIABLE: fake, "TMPDIR": str(scratch)}
    proc = subprocess.Popen([sys.executable, "-m", "harness", "compare", "--model", "hertz-mindlin", "--en", "0.5",
                             "--angles", "10", "--engines", "liggghts", "-o", str(tmp_path / "out")], env=env,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            preexec_fn=interruptible)
    deadline = time.time() + 120
    while not (pidfile.exists() and pidfile.read_text().strip()):
        assert time.time() < deadline and proc.poll() is None, proc.communicate()
        time.sleep(0.1)
    return proc, int(pidfile.read_text()), scratch


def wait_gone(pid, seconds=10):
    deadline = time.time() + seconds
    while alive(pid) and time.time() < deadline:
        time.sleep(0.05)
    return not alive(pid)


@pytest.mark.parametrize("signum, code", [(signal.SIGINT, 130), (signal.SIGTERM, 143), (signal.SIGHUP, 129)])
def test_a_stopped_harness_leaves_no_engine_and_no_temporary_directory(tmp_path, signum, code):
    proc, engine, scratch = start_hung_compare(tmp_path)
    proc.send_signal(signum)
    out, err = proc.communicate(timeout=30)
    assert proc.returncode == code, err
    assert "Traceback" not in err and "engines stopped" in err
    assert wait_gone(engine)
    assert os.listdir(scratch) == []


def test_a_killed_harness_takes_its_engine_along_and_the_next_run_sweeps_its_directory(tmp_path):
    proc, engine, scratch = start_hung_compare(tmp_path)
    proc.kill()
    proc.communicate(timeout=30)
    assert wait_gone(engine)                                  # the parent-death signal
    assert [name for name in os.listdir(scratch) if name.startswith(f"harness-{proc.pid}-")]
    assert sweep_stale(str(scratch)) == 1 and os.listdir(scratch) == []


def test_sweeping_spares_the_directories_of_running_processes(tmp_path):
    mine = tmp_path / f"harness-{os.getpid()}-liggghts-x"
    parent = tmp_path / f"harness-{os.getppid()}-yade-y"
    other = tmp_path / "harness-notapid-z"
    for directory in (mine, parent, other):
        directory.mkdir()
    assert sweep_stale(str(tmp_path)) == 0
    assert mine.exists() and parent.exists() and other.exists()


# --- a hung engine, a huge log ---------------------------------------------------------------------------------------

def test_a_hung_engine_costs_one_timeout_not_one_per_batch(tmp_path, monkeypatch):
    """Three e_n batches of a LIGGGHTS that hangs: each process times out once, and its batches are not rerun one
    by one (which cost one more timeout each)."""
    from harness.engines import ENGINES, batches
    from harness.runs.execute import execute
    from harness.laws import compose
    from harness.runs.plan import engine_runs
    from harness.scenes.scene import Scene
    monkeypatch.setattr(batches, "TIMEOUT_FLOOR_S", 2.0)
    monkeypatch.setenv(liggghts.BINARY_VARIABLE, fake_executable(tmp_path, "echo started; exec sleep 60"))
    runs = engine_runs(ENGINES["liggghts"], compose("hertz-mindlin"), Scene(e_n=(0.9, 0.5, 0.25), angles_deg=(10.0,)),
                       100)
    start = time.perf_counter()
    rows, failures = execute(runs)
    seconds = time.perf_counter() - start
    assert len(rows) == 3 and set(rows.status) == {"failed"}
    assert rows.message.str.contains("did not finish within").all()
    assert seconds < VERSION_TIMEOUT_S + 2.0 + 2.0, seconds     # the version probe's timeout, then the
                                                    # processes side by side, each timed out once; never 2 + 3 x 2
    assert len(failures) == 3 and all("started" in f.log_tail for f in failures)


def test_only_the_tail_of_a_huge_log_is_read(tmp_path):
    """A 4 GB log (sparse, so the test stays cheap): its tail comes back at once, without reading the rest."""
    log = tmp_path / "engine.log"
    with open(log, "wb") as handle:
        handle.truncate(4 * 1024 ** 3)
        handle.seek(0, 2)
        handle.write(b"".join(b"line %d\n" % i for i in range(100)))
    start = time.perf_counter()
    text = read_tail(str(log))
    assert time.perf_counter() - start < 1.0
    assert text.splitlines()[-1] == "line 99" and len(text.splitlines()) == 40


# --- output paths ----------------------------------------------------------------------------------------------------

def harness_main(capfd, *argv):
    """(exit code, stdout, stderr) of one command run in this process."""
    from harness.commands import main
    code = main(list(argv))
    out, err = capfd.readouterr()
    return code, out, err


def refused_in_one_line(code, err):
    lines = err.strip().splitlines()
    return code == 2 and len(lines) == 1 and lines[0].startswith("harness: error:") and "Traceback" not in err


RUN = ["run", "--model", "thornton", "--en", "0.5", "--angles", "10", "-o"]


def odd_targets(tmp_path):
    """name -> (path, what must still be there afterwards)."""
    fifo, link, target, directory = tmp_path / "fifo", tmp_path / "link.csv", tmp_path / "target", tmp_path / "dir"
    os.mkfifo(fifo)
    target.write_text("precious\n")
    os.symlink(target, link)
    directory.mkdir()
    return {"fifo": (str(fifo), lambda: stat_kind(fifo) == "fifo"),
            "symlink": (str(link), lambda: os.path.islink(link) and target.read_text() == "precious\n"),
            "directory": (str(directory), lambda: directory.is_dir()),
            "empty": ("", lambda: True),
            "missing directory": (str(tmp_path / "newdir") + "/", lambda: not (tmp_path / "newdir").exists()),
            "proc": ("/proc/harness-test.csv", lambda: not os.path.exists("/proc/harness-test.csv"))}


def stat_kind(path):
    import stat
    mode = os.lstat(path).st_mode
    return "fifo" if stat.S_ISFIFO(mode) else "link" if stat.S_ISLNK(mode) else "other"


@pytest.mark.parametrize("name", ["fifo", "symlink", "directory", "empty", "missing directory", "proc"])
def test_run_writes_only_regular_files_or_new_paths(tmp_path, capfd, name):
    path, intact = odd_targets(tmp_path)[name]
    code, out, err = harness_main(capfd, *RUN, path)
    assert refused_in_one_line(code, err), (code, err)
    assert intact()


def test_run_replaces_a_regular_file(tmp_path, capfd):
    path = tmp_path / "old.csv"
    path.write_text("old\n")
    code, out, err = harness_main(capfd, *RUN, str(path))
    assert code == 0 and path.read_text().startswith("model,")


@pytest.mark.parametrize("path", ["", "/proc/harness-test-dir", "FILE"])
def test_compare_refuses_an_output_directory_it_cannot_use(tmp_path, capfd, path):
    if path == "FILE":
        path = str(tmp_path / "a-file")
        (tmp_path / "a-file").write_text("keep\n")
    code, out, err = harness_main(capfd, "compare", "--model", "thornton", "--engines", "reference", "--en", "0.5",
                                  "--angles", "10", "-o", path)
    assert refused_in_one_line(code, err), (code, err)
    assert not os.path.exists("/proc/harness-test-dir")


def test_a_second_writer_is_refused_and_told_who_holds_the_directory(tmp_path, capfd):
    from harness.infra.lock import LOCK, exclusive
    with exclusive(str(tmp_path)):
        code, out, err = harness_main(capfd, "compare", "--model", "thornton", "--engines", "reference", "--en",
                                      "0.5", "--angles", "10", "-o", str(tmp_path))
        assert refused_in_one_line(code, err) and f"harness pid {os.getpid()}" in err
        assert not (tmp_path / "results.csv").exists()
    assert not (tmp_path / LOCK).exists()
    code, out, err = harness_main(capfd, "compare", "--model", "thornton", "--engines", "reference", "--en", "0.5",
                                  "--angles", "10", "-o", str(tmp_path))
    assert code == 0 and (tmp_path / "results.csv").exists() and not (tmp_path / LOCK).exists()


# --- the Coulomb impulse bound ----------------------------------------------------------------------------------------

SPIN = dict(en=[0.5], vt=[0.0, 0.05, 0.1, 0.2], normal_speed=0.2, radius=0.1, mu=0.4, material="example-5mm")


@pytest.mark.parametrize("omega0", [5.0, 21.0, -21.0])
def test_every_paper_law_keeps_the_coulomb_impulse_bound(omega0):
    """|F_t| <= mu F_n at every instant, so m |v_t1 - v_t0| <= mu m (v_n0 + v_n1) (no gravity): Chung & Ooi's spin
    scene and a whole angle sweep, every law."""
    import harness
    from harness.laws import LAWS
    for law in LAWS:
        for frame in (harness.run(law, omega0=omega0, **SPIN),
                      harness.run(law, en=[0.9, 0.1], angles=list(range(0, 90, 4)), omega0=omega0 / 10)):
            slack = frame.mu * (frame.v_n0 + frame.v_n1) - (frame.v_t1 - frame.v_t0).abs()
            assert (slack >= -1e-9 * frame.mu * (frame.v_n0 + frame.v_n1)).all(), (law, slack.min())


def test_an_impulse_beyond_the_bound_is_an_invariant_break():
    import pandas as pd
    from harness.analyses.invariants import invariant_breaks
    import harness
    frame = harness.run("hertz-mindlin", omega0=21.0, **SPIN)
    assert "Coulomb bound" not in set(invariant_breaks(frame).kind)
    pushed = frame.copy()
    pushed.loc[1, "v_t1"] = pushed.v_t0[1] + 1.01 * pushed.mu[1] * (pushed.v_n0[1] + pushed.v_n1[1])
    found = invariant_breaks(pd.DataFrame(pushed))
    assert found[found.kind == "Coulomb bound"].row.tolist() == [1]


@needs("liggghts")
@needs("yade")
def test_both_engines_break_the_coulomb_bound_on_chung_and_oois_spin_case():
    """Chung & Ooi's spin scene (R 0.1 m, V_n 0.2 m/s, omega0 21 rad/s, e 0.5, mu 0.4): both engines end with v_t1
    about 0.14 m/s where |J_t| <= mu J_n allows 0.12; the finding says so, and their formulas reproduce it."""
    import harness
    comparison = harness.compare("hertz-mindlin", engines=["liggghts", "yade"], omega0=21.0, **SPIN)
    found = comparison.findings[comparison.findings.kind == "Coulomb bound"]
    assert {(e, d) for e, d in zip(found.engine, found.dialect)} >= {("liggghts", "liggghts"), ("yade", "yade"),
                                                                      ("reference", "liggghts"), ("reference", "yade")}
    rows = comparison.results[(comparison.results.engine != "reference") & (comparison.results.v_t0 == 0.0)]
    allowed = (rows.mu * (rows.v_n0 + rows.v_n1)).to_numpy()
    assert (rows.v_t1.abs().to_numpy() > 1.1 * allowed).all() and np.allclose(rows.v_t1.abs(), 0.14, atol=0.005)
    assert not (comparison.findings.dialect == "paper").any()


# --- an interrupted compare: kept, shown as partial, resumed ---------------------------------------------------------

def test_an_interrupted_compare_is_shown_as_partial_and_the_rerun_runs_only_what_is_missing(tmp_path, monkeypatch,
                                                                                          capfd):
    import json
    proc, engine, _ = start_hung_compare(tmp_path)
    out = tmp_path / "out"
    deadline = time.time() + 60                       # the reference's two runs finish while LIGGGHTS hangs
    while not (out / ".partial").is_dir() or len(os.listdir(out / ".partial")) < 2:
        assert time.time() < deadline
        time.sleep(0.1)
    proc.send_signal(signal.SIGINT)
    proc.communicate(timeout=30)
    assert proc.returncode == 130 and wait_gone(engine)
    assert json.loads((out / "run.json").read_text())["partial"] is True
    assert "PARTIAL: this compare was interrupted" in (out / "report.html").read_text()
    assert len(os.listdir(out / ".partial")) == 2

    executed = []
    from harness.engines import ENGINES
    for name in ("reference", "liggghts"):
        def counting(runs, run=ENGINES[name].run):
            executed.extend((r.engine, r.dialect.dialect) for r in runs)
            return run(runs)
        monkeypatch.setattr(ENGINES[name], "run", counting)
    monkeypatch.setenv(liggghts.BINARY_VARIABLE, fake_executable(tmp_path, 'echo "ERROR: gone"; exit 1', "crash"))
    code = main_in_process("compare", "--model", "hertz-mindlin", "--en", "0.5", "--angles", "10", "--engines",
                           "liggghts", "-o", str(out), "--quiet")
    err = capfd.readouterr().err
    assert code == 3, err                                          # LIGGGHTS failed this time
    assert executed == [("liggghts", "liggghts")]                  # the reference's two runs came from the first
    frame = __import__("pandas").read_csv(out / "results.csv")
    assert sorted(frame.dialect[frame.engine == "reference"]) == ["liggghts", "paper"]
    assert json.loads((out / "run.json").read_text())["partial"] is False and not (out / ".partial").exists()


def main_in_process(*argv):
    from harness.commands import main
    return main(list(argv))


@needs("liggghts")
@pytest.mark.parametrize("signum, code", [(signal.SIGINT, 130), (signal.SIGTERM, 143)])
def test_a_real_liggghts_run_ends_with_harness(tmp_path, signum, code):
    """The real binary at 1e6 steps per contact: harness stopped while LIGGGHTS runs leaves no process of its tree
    and no temporary directory."""
    scratch = tmp_path / "tmp"
    scratch.mkdir()
    proc = subprocess.Popen([sys.executable, "-m", "harness", "compare", "--model", "hertz-mindlin", "--en", "0.5",
                             "--angles", "10", "--engines", "liggghts", "--steps-per-contact", "1000000", "-o",
                             str(tmp_path / "out")], env={**os.environ, "TMPDIR": str(scratch)},
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            preexec_fn=interruptible)
    deadline, engines = time.time() + 120, []
    while not engines:
        assert time.time() < deadline and proc.poll() is None, proc.communicate()
        engines = [pid for pid in descendants(proc.pid) if "liggghts" in cmdline(pid)]
        time.sleep(0.1)
    tree = descendants(proc.pid)
    proc.send_signal(signum)
    out, err = proc.communicate(timeout=60)
    assert proc.returncode == code and "Traceback" not in err, err
    assert all(wait_gone(pid) for pid in tree)
    assert os.listdir(scratch) == []


def catches_sigint(pid):
    """Whether process `pid` has a handler of its own for SIGINT (bit 2 of SigCgt in /proc/PID/status)."""
    with open(f"/proc/{pid}/status") as handle:
        mask = next(line.split()[1] for line in handle if line.startswith("SigCgt:"))
    return bool(int(mask, 16) & (1 << (signal.SIGINT - 1)))


def test_ctrl_c_inside_the_compiled_kernel_stops_at_once_and_says_nothing_was_written(tmp_path):
    """A run of ~2e8 impact-steps (tens of seconds): interrupted a second into its kernel, harness ends within a few
    seconds instead of when the compiled loop returns, and does not claim results it never wrote."""
    out = tmp_path / "r.csv"
    proc = subprocess.Popen([sys.executable, "-m", "harness", "run", "--model", "hertz-mindlin", "--en", "0.5",
                             "--angles", "0:89:0.5", "--steps-per-contact", "1000000", "-o", str(out)],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            preexec_fn=interruptible)
    deadline = time.time() + 60
    while not catches_sigint(proc.pid):   # Python's own handler installed (a busy machine may take seconds)
        assert time.time() < deadline and proc.poll() is None
        time.sleep(0.05)
    time.sleep(4.0)                       # start-up and the cached kernel's load, then well inside the loop
    assert proc.poll() is None
    stopped = time.perf_counter()
    proc.send_signal(signal.SIGINT)
    _, err = proc.communicate(timeout=60)
    assert time.perf_counter() - stopped < 3.0
    assert proc.returncode == 130 and "nothing had been written yet" in err and not out.exists()


def test_ctrl_c_while_the_measurements_beside_the_engines_run_exits_at_once(tmp_path):
    """What runs beside the engines (attribution, sliding threshold, histories; compiling on a first run) must not
    hold harness after Ctrl-C: made to take ten minutes here, the interrupted compare still ends within a minute
    even under load (a wait for the measurements would take the ten minutes)."""
    code = ("import sys, time, harness.api.requests as api\n"
            "api.measurements = lambda *a: time.sleep(600)\n"
            "from harness.commands import main\n"
            f"sys.exit(main(['compare', '--model', 'hertz-mindlin', '--en', '0.5', '--angles', '10', '--engines', "
            f"'reference', '-o', {str(tmp_path / 'out')!r}]))\n")
    proc = subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            preexec_fn=interruptible)
    deadline = time.time() + 60
    while not (tmp_path / "out" / ".partial").is_dir() or not os.listdir(tmp_path / "out" / ".partial"):
        assert time.time() < deadline and proc.poll() is None, proc.communicate()
        time.sleep(0.1)
    time.sleep(0.5)
    stopped = time.perf_counter()
    proc.send_signal(signal.SIGINT)
    try:
        _, err = proc.communicate(timeout=120)
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.communicate()
    assert time.perf_counter() - stopped < 60.0 and proc.returncode == 130, err      # not the ten minutes


# --- an interrupt at a rename ----------------------------------------------------------------------------------------

class ReplaceThenInterrupt:
    """The os module as harness.infra.files sees it, but Ctrl-C arrives just after results.csv is renamed into place."""

    def __getattr__(self, name):
        return getattr(os, name)

    @staticmethod
    def replace(source, target):
        os.replace(source, target)
        if os.path.basename(target) == "results.csv":
            raise KeyboardInterrupt


def test_ctrl_c_just_after_a_rename_is_an_interruption_and_the_file_is_whole(tmp_path, monkeypatch, capfd):
    import pandas as pd
    import harness.infra.files
    monkeypatch.setattr(harness.infra.files, "os", ReplaceThenInterrupt())
    out = tmp_path / "out"
    code, _, err = harness_main(capfd, "compare", "--model", "hertz-mindlin", "--en", "0.5", "--angles", "10",
                                "--engines", "reference", "-o", str(out), "--quiet")
    assert code == 130 and err.strip().splitlines() == [
        f"harness: interrupted; engines stopped, finished results were kept in {out}"], err
    assert len(pd.read_csv(out / "results.csv")) == 1
    assert not [name for name in os.listdir(out) if name.endswith(".tmp")]


# --- a baseline that is not a regular file ---------------------------------------------------------------------------

@pytest.mark.parametrize("kind", ["fifo", "link to a fifo", "link to /dev/zero", "directory"])
def test_check_refuses_a_baseline_that_is_not_a_regular_file_without_opening_it_for_good(tmp_path, kind):
    """A FIFO would block the reader until a writer came, /dev/zero never ends: refused at once, in one line, and
    left as it was."""
    path, fifo = tmp_path / "baseline.csv", tmp_path / "elsewhere"
    if kind == "fifo":
        os.mkfifo(path)
    elif kind == "link to a fifo":
        os.mkfifo(fifo)
        os.symlink(fifo, path)
    elif kind == "link to /dev/zero":
        os.symlink("/dev/zero", path)
    else:
        path.mkdir()
    done = subprocess.run([sys.executable, "-m", "harness", "check", "--baseline", str(tmp_path)],
                          capture_output=True, text=True, timeout=60)
    lines = done.stderr.strip().splitlines()
    assert done.returncode == 2 and len(lines) == 1 and "not a regular file" in lines[0], done.stderr
    assert os.path.lexists(path) and (kind != "fifo" or stat_kind(path) == "fifo")


# --- no earlier report beside new results ----------------------------------------------------------------------------

def test_a_killed_compare_leaves_no_earlier_report_beside_its_results(tmp_path, capfd):
    """DIR holds an earlier compare (another e_n) and its report; a compare killed once its first results are in
    DIR must not leave that report standing beside them unmarked."""
    out = tmp_path / "out"
    assert main_in_process("compare", "--model", "hertz-mindlin", "--en", "0.9", "--angles", "10", "--engines",
                           "reference", "-o", str(out), "--quiet") == 0
    assert (out / "report.html").exists()
    proc, engine, _ = start_hung_compare(tmp_path)
    deadline = time.time() + 60                       # the reference's runs finish while LIGGGHTS hangs
    while not (out / ".partial").is_dir() or len(os.listdir(out / ".partial")) < 2:
        assert time.time() < deadline
        time.sleep(0.1)
    proc.kill()
    proc.communicate(timeout=30)
    assert wait_gone(engine)
    assert set(__import__("pandas").read_csv(out / "results.csv").e_n_target) == {0.5}
    report = out / "report.html"
    assert not report.exists() or "PARTIAL" in report.read_text()


def test_a_killed_cost_study_leaves_no_earlier_report_standing(tmp_path):
    out = tmp_path / "out"
    assert main_in_process("compare", "--model", "hertz-mindlin", "--en", "0.9", "--angles", "10", "--engines",
                           "reference", "-o", str(out), "--quiet") == 0
    proc = subprocess.Popen([sys.executable, "-m", "harness", "cost", "--model", "hertz-mindlin", "--en", "0.5",
                             "--angles", "10", "--engines", "reference", "-o", str(out)],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    deadline = time.time() + 60
    while not (out / "cost.json").exists():
        assert time.time() < deadline and proc.poll() is None, proc.communicate()
        time.sleep(0.05)
    proc.kill()
    proc.communicate(timeout=30)
    assert not (out / "report.html").exists()


# --- the report's figure workers --------------------------------------------------------------------------------------

def report_while_drawing(tmp_path):
    """`harness report DIR` on a compare of the reference (45 angles, 3 e_n), returned once its forked figure workers
    run: (process, the workers' pids)."""
    out = tmp_path / "out"
    assert main_in_process("compare", "--model", "hertz-mindlin", "--engines", "reference", "-o", str(out),
                           "--quiet") == 0
    proc = subprocess.Popen([sys.executable, "-m", "harness", "report", str(out)], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, preexec_fn=interruptible)
    deadline, workers = time.time() + 60, []
    while len(workers) < 2:
        assert time.time() < deadline and proc.poll() is None, proc.communicate()
        workers = descendants(proc.pid)
        time.sleep(0.01)
    return proc, workers


def test_a_killed_report_takes_its_figure_workers_along(tmp_path):
    proc, workers = report_while_drawing(tmp_path)
    proc.kill()
    proc.communicate(timeout=30)
    assert all(wait_gone(pid, 5) for pid in workers)


@pytest.mark.parametrize("signum, code", [(signal.SIGINT, 130), (signal.SIGTERM, 143)])
def test_a_report_stopped_while_drawing_ends_at_once_with_its_workers(tmp_path, signum, code):
    proc, workers = report_while_drawing(tmp_path)
    stopped = time.perf_counter()
    proc.send_signal(signum)
    _, err = proc.communicate(timeout=30)
    assert proc.returncode == code and "Traceback" not in err, err
    assert time.perf_counter() - stopped < 10.0
    assert all(wait_gone(pid, 1) for pid in workers)


# --- YADE's own temporary directory ----------------------------------------------------------------------------------

YADE_START = r"""
import json, os, signal, subprocess, sys, time
codes = []
KEEP = os.environ.get("KEEP_TOP", "")     # the checkout's top directory in /tmp, when it lives there (bound back)


def private_tmp():                        # every path in this /tmp but the checkout's, relative to it
    for root, dirs, files in os.walk("/tmp"):
        if root == "/tmp":
            dirs[:] = [d for d in dirs if d != KEEP]
        yield from (os.path.relpath(os.path.join(root, name), "/tmp") for name in dirs + files)


for k in range(int(sys.argv[1])):
    proc = subprocess.Popen([sys.executable, "-m", "harness", "compare", "--model", "hertz-mindlin", "--en", "0.5",
                             "--angles", "10", "--engines", "yade", "-o", f"/tmp/out{k}", "--quiet"],
                            stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    made = lambda: {path for path in private_tmp() if os.path.basename(path).startswith("yade-")}
    before, deadline = made(), time.time() + 120
    while not made() - before and time.time() < deadline and proc.poll() is None:
        time.sleep(0.002)
    proc.send_signal(signal.SIGTERM)                   # YADE has made its directory and is still starting
    proc.communicate(timeout=60)
    codes.append(proc.returncode)
left = sorted(path for path in private_tmp() if not path.startswith("out"))
print(json.dumps({"codes": codes, "left": left}))
"""


def namespaces_allowed():
    return subprocess.run(["unshare", "--user", "--map-root-user", "--mount", "true"],
                          capture_output=True).returncode == 0


@needs("yade")
@pytest.mark.skipif(not namespaces_allowed(), reason="no user and mount namespaces here")
def test_harness_stopped_while_yade_starts_leaves_no_yade_directory(tmp_path):
    """YADE makes /tmp/yade-XXXXXX as it starts, whatever TMPDIR says, and removes it only when it exits normally.
    Each compare runs with a /tmp of the test's own (a private mount namespace) and is stopped the moment YADE's
    directory appears: nothing may be left in that /tmp."""
    private = tmp_path / "tmp"
    private.mkdir()
    checkout = Path(__file__).resolve().parents[1]
    inside = checkout.parts[2:] if checkout.parts[:2] == ("/", "tmp") else ()   # a clone under /tmp is bound back
    keep = os.path.join(*inside) if inside else ""
    if keep:
        (private / keep).mkdir(parents=True)
    done = subprocess.run(["unshare", "--user", "--map-root-user", "--mount", "--", "sh", "-c",
                           '{ [ -z "$2" ] || mount --bind "/tmp/$2" "$1/$2"; } && mount --rbind "$1" /tmp && shift 2 '
                           '&& exec "$@"', "sh", str(private), keep, sys.executable, "-c", YADE_START, "4"],
                          capture_output=True, text=True, timeout=900, cwd=os.getcwd(),
                          env={**os.environ, "KEEP_TOP": inside[0] if inside else ""})
    assert done.returncode == 0, done.stderr
    found = json.loads(done.stdout)
    assert found["codes"] == [143] * 4 and found["left"] == [], found


# --- a stop raised where Python ignores exceptions --------------------------------------------------------------------

LOST_STOP = r"""
import os, signal, sys
sent = []

def at_fork():                                  # as logging's fork handler was when SIGTERM came under load
    if not sent:
        sent.append(os.kill(os.getpid(), signal.SIGTERM))
        sum(range(1000))                        # the handler runs here, where Python ignores what it raises

os.register_at_fork(after_in_parent=at_fork)
from harness.commands import main
sys.exit(main(["compare", "--model", "hertz-mindlin", "--engines", "reference", "-o", sys.argv[1], "--quiet"]))
"""


def test_a_stop_raised_where_python_ignores_exceptions_still_stops_harness(tmp_path):
    """SIGTERM handled inside a fork handler (the report's figure workers are forked): Python ignores the exception
    the handler raises there, and harness went on to finish as if never stopped."""
    done = subprocess.run([sys.executable, "-c", LOST_STOP, str(tmp_path / "out")], capture_output=True, text=True,
                          timeout=300)
    assert done.returncode == 143 and "Traceback" not in done.stderr, done.stderr
    assert "terminated" in done.stderr


STOP_IN_AN_EXTENSION = r"""
import os, signal, sys
from harness.commands import main, models

def load_extension(args):                       # as scipy's compiled optimiser did when SIGTERM came as it loaded
    try:
        os.kill(os.getpid(), signal.SIGTERM)
        sum(range(1000))
    except KeyboardInterrupt as exc:
        raise ImportError("initialization failed") from exc

models.main = load_extension
sys.exit(main(["models"]))
"""


def test_a_stop_turned_into_another_error_is_still_a_stop():
    """A compiled extension interrupted while it loads raises ImportError from the stop: still exit 143, one line."""
    done = subprocess.run([sys.executable, "-c", STOP_IN_AN_EXTENSION], capture_output=True, text=True, timeout=120)
    assert done.returncode == 143 and done.stderr.strip().splitlines() == [
        "harness: terminated; engines stopped, nothing had been written yet"], done.stderr


LOST_AT_THE_END = r"""
import os, signal, sys
from harness.commands import main, models

class Finaliser:
    def __del__(self):                          # SIGTERM handled here: Python ignores what its handler raises
        os.kill(os.getpid(), signal.SIGTERM)
        sum(range(1000))

def finish(args):
    Finaliser()                                 # collected at once, in the command's last moment
    return 0

models.main = finish
sys.exit(main(["models"]))
"""


def test_a_stop_lost_in_a_commands_last_moment_still_stops_harness():
    """A stop lost where Python ignores exceptions just before the command returns, sooner than its redelivery
    timer: the command's end raises it, exit 143, rather than exit 0 as if never stopped."""
    done = subprocess.run([sys.executable, "-c", LOST_AT_THE_END], capture_output=True, text=True, timeout=120)
    assert done.returncode == 143 and "Traceback" not in done.stderr, done.stderr
    assert "terminated" in done.stderr
