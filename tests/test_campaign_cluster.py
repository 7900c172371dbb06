"""The campaign's Dask entrance. Security: a client without the campaign's credentials cannot submit work (plain TCP,
TLS without a certificate, TLS with another run's certificate), a LocalCluster listens on the loopback address only
and a SLURM scheduler with TLS only, with no HTTP listener anywhere, and the workers' credentials are readable by the
user alone. Options: every --slurm value is checked before it reaches the job script, contradictions and limits are
refused in one line; a missing sbatch or an unreachable scheduler is one line with exit 3 within a deadline; nothing
a Dask campaign starts outlives it in TMPDIR."""
import gc
import json
import os
import signal
import socket
import stat
import subprocess
import sys
import threading

import psutil
import pytest

from conftest import fake_executable
from harness.studies.campaign import clusters
from harness.studies.campaign.executors import executor
from harness.studies.campaign.limits import max_workers
from harness.studies.campaign.slurm import forget_credentials, slurm_cluster
from harness.commands import main

TOML = 'laws = ["thornton"]\ne_n = [0.5]\nangles = [10, 50]\nsteps_per_contact = [500]\n'
LOOPBACK = {"127.0.0.1", "::1"}


def listeners(pid):
    """(address, port) of every listening TCP socket of a process and its descendants."""
    found = set()
    root = psutil.Process(pid)
    for process in [root] + root.children(recursive=True):
        try:
            found |= {(c.laddr.ip, c.laddr.port) for c in process.net_connections(kind="inet")
                      if c.status == psutil.CONN_LISTEN}
        except psutil.NoSuchProcess:
            pass
    return found


def port(address):
    return int(address.rsplit(":", 1)[1])


def refused(address, **security):
    """True when a Client cannot connect to `address` and submit work within 15 s."""
    from distributed import Client
    try:
        client = Client(address, timeout=15, set_as_default=False, **security)
    except Exception:
        client = None
    if client is None:      # a half-made Client closes itself when collected: here, not inside the next Client's
        gc.collect()        # start, where its close waits on the loop lock that start holds (a deadlock)
        return True
    try:
        client.submit(os.getpid).result(timeout=15)
        return False
    except Exception:
        return True
    finally:
        client.close()


@pytest.fixture
def dashboard_port_taken():
    """Port 8787, where Dask's scheduler opens its HTTP listener by default (warning on stderr when it is taken),
    held by someone else (with SO_REUSEPORT, so that tests running side by side each hold it)."""
    held = socket.socket()
    held.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEPORT, 1)
    try:
        held.bind(("127.0.0.1", 8787))
        held.listen(1)
    except OSError:
        pass
    yield
    held.close()


@pytest.fixture(scope="module")
def cluster():
    """The LocalCluster a campaign with --executor dask --workers 2 starts."""
    on_dask = executor("dask", workers=2)
    yield on_dask
    on_dask.close()


def test_the_campaign_cluster_runs_work_for_its_own_client(cluster):
    pids = cluster.client.run(os.getpid)
    assert len(pids) == 2 and cluster.client.submit(os.getpid, pure=False).result(timeout=60) in pids.values()


def test_a_client_without_the_campaigns_credentials_cannot_submit_work(cluster):
    from distributed import Security
    own = cluster.cluster.security
    address = cluster.cluster.scheduler_address
    assert address.startswith("tls://127.0.0.1:")
    assert not refused(address, security=own)                         # the control: its own credentials work
    assert refused(address.replace("tls://", "tcp://"))               # plain TCP
    assert refused(address, security=Security(tls_ca_file=own.tls_ca_file, require_encryption=True))  # no cert
    assert refused(address, security=Security.temporary())            # TLS with another run's certificate


def test_the_local_cluster_listens_on_loopback_only_and_serves_no_http(cluster):
    info = cluster.client.scheduler_info()
    ports = {port(cluster.cluster.scheduler_address)}
    for address, worker in info["workers"].items():
        ports |= {port(address), port(worker["nanny"])}
    found = listeners(os.getpid())
    assert found and {ip for ip, _ in found} <= LOOPBACK, found
    assert {p for _, p in found} == ports, (found, ports)               # the TLS comms, nothing else (no HTTP)
    for worker in info["workers"].values():                            # its scratch is harness' own directory
        assert f"/harness-{os.getpid()}-dask-" in worker["local_directory"], worker["local_directory"]


def test_a_dask_campaign_leaves_nothing_in_tmpdir(tmp_path, dashboard_port_taken):
    scratch = tmp_path / "tmp"
    scratch.mkdir()
    (tmp_path / "c.toml").write_text(TOML)
    done = subprocess.run([sys.executable, "-m", "harness", "campaign", str(tmp_path / "c.toml"), "-o",
                           str(tmp_path / "store"), "--executor", "dask", "--workers", "1", "--quiet"],
                          capture_output=True, text=True, timeout=300, env={**os.environ, "TMPDIR": str(scratch)})
    assert done.returncode == 0 and done.stderr == "", done.stderr
    assert os.listdir(scratch) == []


@pytest.fixture
def nearly_full_tmpdir(tmp_path):
    """A 64 KiB file system with one 4 KiB block left (root mounts it; a full TMPDIR), unmounted after."""
    where = tmp_path / "full"
    where.mkdir()
    if os.geteuid() != 0 or subprocess.run(["mount", "-t", "tmpfs", "-o", "size=64k", "tmpfs", str(where)],
                                           capture_output=True).returncode != 0:
        pytest.skip("mounting a small file system needs root")
    try:
        room = os.statvfs(where)
        (where / "fill").write_bytes(b"\0" * (room.f_bavail * room.f_frsize - 4096))
        yield where
    finally:
        subprocess.run(["umount", "-l", str(where)], capture_output=True)


def test_a_dask_campaign_with_a_full_tmpdir_is_one_line_and_exit_3(tmp_path, nearly_full_tmpdir):
    (tmp_path / "c.toml").write_text(TOML)
    done = subprocess.run([sys.executable, "-m", "harness", "campaign", str(tmp_path / "c.toml"), "-o",
                           str(tmp_path / "store"), "--executor", "dask", "--workers", "1"],
                          capture_output=True, text=True, timeout=300,
                          env={**os.environ, "TMPDIR": str(nearly_full_tmpdir)})
    assert done.returncode == 3, done.stderr
    assert done.stderr.strip().count("\n") == 0 and "no space left" in done.stderr, done.stderr
    assert sorted(os.listdir(nearly_full_tmpdir)) == ["fill"]


def test_the_slurm_scheduler_speaks_tls_only_with_private_credentials_and_no_http(tmp_path):
    from distributed import Security
    shared, scratch = tmp_path / "shared", tmp_path / "scratch"
    shared.mkdir()
    scratch.mkdir()
    before = listeners(os.getpid())
    cluster = slurm_cluster({"queue": "debug", "cores": 2}, shared, scratch)
    try:
        script = cluster.job_script()
        address = cluster.scheduler_address
        assert address.startswith("tls://") and f"{sys.executable} -m distributed.cli.dask_worker {address}" in script
        paths = [script.split(f"--tls-{what} ")[1].split()[0] for what in ("ca-file", "cert", "key")]
        for path in paths:
            assert stat.S_IMODE(os.stat(path).st_mode) == 0o600
            assert stat.S_IMODE(os.stat(os.path.dirname(path)).st_mode) == 0o700
        assert "--preload harness.studies.campaign.no_http" in script and "--local-directory" in script
        found = listeners(os.getpid()) - before
        assert {p for _, p in found} == {port(address)}, found          # the scheduler's TLS port alone
        from distributed import Client
        Client(address, security=cluster.security, timeout=15, set_as_default=False).close()   # the control
        assert refused(address.replace("tls://", "tcp://")) and refused(address)
        assert refused(address, security=Security(tls_ca_file=cluster.security.tls_ca_file, require_encryption=True))
        assert refused(address, security=Security.temporary())
    finally:
        cluster.close()
        forget_credentials(cluster)
    assert not os.listdir(shared)


BAD_SLURM = [
    ("queue=debug\n#SBATCH --uid=0", "queue must be"),
    ("account=proj\n#SBATCH -A other", "account must be"),
    ("memory=8GB\nrm -rf ~", "memory must be"),
    ("walltime=01:00:00\n#SBATCH -t 99:00:00", "walltime must be"),
    ("job_extra=--qos=low\n#SBATCH --qos=high", "job_extra must be"),
    ("job_extra=--qos=low\r", "job_extra must be"),
    ("job_extra=qos", "job_extra must be"),
    ("queue=de bug", "queue must be"),
    ("queue=$(id)", "queue must be"),
    ("memory=lots", "memory must be"),
    ("walltime=soon", "walltime must be"),
    ("cores=four", "cores must be a whole number"),
    ("cores=0", "cores must be a whole number"),
    ("cores=100000", "cores must be a whole number"),
    ("jobs=-1", "jobs must be a whole number"),
    ("jobs=1e9", "jobs must be a whole number"),
    ("processes=1.5", "processes must be a whole number"),
    ("nodes=3", "KEY one of"),
    ("queue", "KEY one of"),
    ("queue=", "KEY one of"),
]


def campaign_args(tmp_path, *extra):
    (tmp_path / "c.toml").write_text(TOML)
    return ["campaign", str(tmp_path / "c.toml"), "-o", str(tmp_path / "store"), *extra]


def one_line(code, capfd, tmp_path, before, words, exit_code=2):
    out, err = capfd.readouterr()
    lines = err.strip().splitlines()
    assert code == exit_code, (out, err)
    assert len(lines) == 1 and lines[0].startswith("harness: error: ") and words in lines[0], err
    assert "Traceback" not in out + err and sorted(os.listdir(tmp_path)) == before


@pytest.mark.parametrize("value, words", BAD_SLURM, ids=[v for v, _ in BAD_SLURM])
def test_a_bad_slurm_value_is_refused_before_it_reaches_the_script(tmp_path, capfd, value, words):
    args = campaign_args(tmp_path, "--executor", "dask", "--slurm", value)
    before = sorted(os.listdir(tmp_path))
    one_line(main(args), capfd, tmp_path, before, words)
    one_line(main(args + ["--slurm-script"]), capfd, tmp_path, before, words)


CONTRADICTIONS = [
    (["--workers", "100000", "--executor", "dask"], f"from 1 to {max_workers()}"),
    (["--workers", "0", "--executor", "dask"], "from 1 to"),
    (["--workers", "2"], "add --executor dask"),
    (["--workers", "2", "--executor", "dask", "--scheduler", "tcp://127.0.0.1:1"], "the workers are the scheduler"),
    (["--workers", "2", "--executor", "dask", "--slurm", "queue=a"], "--slurm jobs and processes"),
    (["--slurm", "queue=a"], "add --executor dask"),
    (["--scheduler", "tcp://127.0.0.1:1"], "add --executor dask"),
    (["--scheduler-file", "s.json"], "add --executor dask"),
    (["--executor", "dask", "--slurm", "queue=a", "--slurm", "queue=b"], "given twice"),
    (["--executor", "dask", "--slurm", "cores=2", "--slurm", "processes=4"], "must not exceed cores"),
    (["--executor", "dask", "--scheduler", "nonsense"], "--scheduler must be"),
    (["--executor", "dask", "--scheduler", "ucx://127.0.0.1:1"], "--scheduler must be"),
    (["--executor", "dask", "--scheduler", "tcp://127.0.0.1:1\n"], "--scheduler must be"),
    (["--executor", "dask", "--scheduler-file", "missing.json"], "cannot read scheduler file"),
]


@pytest.mark.parametrize("extra, words", CONTRADICTIONS, ids=[" ".join(e) for e, _ in CONTRADICTIONS])
def test_contradictory_or_excessive_options_are_refused_in_one_line(tmp_path, capfd, monkeypatch, extra, words):
    monkeypatch.chdir(tmp_path)
    args = campaign_args(tmp_path, *extra)
    before = sorted(os.listdir(tmp_path))
    one_line(main(args), capfd, tmp_path, before, words)


@pytest.mark.parametrize("content, words", [("not json", "not a Dask scheduler file"),
                                            ('{"address": 1}', "not a Dask scheduler file"),
                                            ("[1, 2]", "not a Dask scheduler file"),
                                            ('{"address": "tcp://127.0.0.1:1 ; x"}', "--scheduler must be")])
def test_a_scheduler_file_that_is_not_one_is_refused(tmp_path, capfd, content, words):
    (tmp_path / "s.json").write_text(content)
    args = campaign_args(tmp_path, "--executor", "dask", "--scheduler-file", str(tmp_path / "s.json"))
    before = sorted(os.listdir(tmp_path))
    one_line(main(args), capfd, tmp_path, before, words)


def within(seconds, function):
    """function()'s value, or a failure if it has not returned after `seconds` (a hang, not a slow answer)."""
    result = {}
    thread = threading.Thread(target=lambda: result.setdefault("value", function()), daemon=True)
    thread.start()
    thread.join(seconds)
    assert not thread.is_alive(), f"still running after {seconds} s"
    return result["value"]


def closed_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def test_an_unreachable_or_silent_scheduler_is_one_line_and_exit_3_within_the_deadline(tmp_path, capfd, monkeypatch):
    monkeypatch.setattr(clusters, "CONNECT_TIMEOUT_S", 3.0)
    silent = socket.socket()
    silent.bind(("127.0.0.1", 0))
    silent.listen(5)                           # accepts, never answers
    (tmp_path / "c.toml").write_text(TOML)
    (tmp_path / "s.json").write_text(json.dumps({"address": f"tcp://127.0.0.1:{closed_port()}"}))
    before = sorted(os.listdir(tmp_path))
    try:
        for where in (["--scheduler", f"tcp://127.0.0.1:{closed_port()}"],
                      ["--scheduler", f"tcp://127.0.0.1:{silent.getsockname()[1]}"],
                      ["--scheduler", f"tls://127.0.0.1:{silent.getsockname()[1]}"],
                      ["--scheduler-file", str(tmp_path / "s.json")]):
            args = ["campaign", str(tmp_path / "c.toml"), "-o", str(tmp_path / "store"), "--executor", "dask", *where]
            code = within(60, lambda: main(args))
            words = "speaks TLS" if where[1].startswith("tls") else "no Dask scheduler answered"
            one_line(code, capfd, tmp_path, before, words, exit_code=2 if "TLS" in words else 3)
    finally:
        silent.close()


@pytest.mark.parametrize("kind", ["fifo", "directory"])
def test_a_scheduler_file_that_is_not_a_regular_file_is_refused_without_blocking(tmp_path, capfd, kind):
    path = tmp_path / "s.json"
    os.mkfifo(path) if kind == "fifo" else path.mkdir()
    args = campaign_args(tmp_path, "--executor", "dask", "--scheduler-file", str(path))
    before = sorted(os.listdir(tmp_path))
    one_line(within(60, lambda: main(args)), capfd, tmp_path, before, "not a regular file")


def test_a_campaign_runs_on_a_scheduler_it_is_given(tmp_path, capfd):
    from distributed import LocalCluster
    (tmp_path / "c.toml").write_text(TOML)
    with LocalCluster(n_workers=1, threads_per_worker=1, host="127.0.0.1", dashboard_address=None) as given:
        args = ["campaign", str(tmp_path / "c.toml"), "-o", str(tmp_path / "store"), "--executor", "dask",
                "--scheduler", given.scheduler_address, "--json"]
        assert main(args) == 0
    summary = json.loads(capfd.readouterr().out)
    assert (summary["tasks"], summary["ran"], summary["failed"]) == (1, 1, 0)


def test_without_sbatch_a_slurm_campaign_is_one_line_exit_3_and_writes_nothing(tmp_path, capfd, monkeypatch):
    monkeypatch.setenv("PATH", str(tmp_path / "nothing-here"))
    args = campaign_args(tmp_path, "--executor", "dask", "--slurm", "queue=debug")
    before = sorted(os.listdir(tmp_path))
    one_line(within(60, lambda: main(args)), capfd, tmp_path, before, "sbatch", exit_code=3)


def test_a_job_script_slurm_refuses_is_one_line_exit_3_and_leaves_nothing(tmp_path, capfd, monkeypatch,
                                                                          dashboard_port_taken, recwarn):
    """A stand-in sbatch that refuses the script (--test-only) as a controller refusing the partition would."""
    bin_dir = tmp_path / "bin"
    bin_dir.mkdir()
    fake_executable(bin_dir, 'echo "sbatch: error: invalid partition specified: nope" >&2; exit 1', "sbatch")
    fake_executable(bin_dir, "exit 0", "scancel")
    monkeypatch.setenv("PATH", f"{bin_dir}:{os.environ['PATH']}")
    args = campaign_args(tmp_path, "--executor", "dask", "--slurm", "queue=nope")
    before, listening = sorted(os.listdir(tmp_path)), listeners(os.getpid())
    one_line(within(120, lambda: main(args)), capfd, tmp_path, before, "invalid partition specified", exit_code=3)
    assert listeners(os.getpid()) <= listening
    assert not [w for w in recwarn if "already in use" in str(w.message)]     # on stderr outside pytest


STAND_IN_SBATCH = """[ "$1" = "--test-only" ] && exit 0
echo "$$" >> "{log}"
{submit}"""


def stand_in_slurm(tmp_path, monkeypatch, submit):
    """A SLURM whose sbatch takes the job script (--test-only) and then submits with `submit` (shell), logging
    each submission's process id (`submit` may log more, to {log}); returns the log's path."""
    bin_dir, log = tmp_path / "bin", tmp_path / "submitted.log"
    bin_dir.mkdir()
    fake_executable(bin_dir, STAND_IN_SBATCH.format(log=log, submit=submit.format(log=log)), "sbatch")
    fake_executable(bin_dir, "exit 0", "scancel")
    monkeypatch.setenv("PATH", f"{bin_dir}:{os.environ['PATH']}")
    return log


@pytest.mark.parametrize("submit, words", [
    ("exit 0", "sbatch printed no job id (it printed nothing"),
    ("echo 'sbatch: job accepted'", "sbatch printed no job id (its last line: 'sbatch: job accepted'"),
    ("echo 'sbatch: error: Batch job submission failed: QOS limit' >&2; exit 1",
     "SLURM did not take a job: sbatch: error: Batch job submission failed: QOS limit"),
])
def test_a_slurm_that_takes_no_job_ends_in_one_line_with_its_words_and_leaves_nothing(
        tmp_path, capfd, monkeypatch, dashboard_port_taken, submit, words):
    """sbatch accepts the script, then prints no job id (or fails): the campaign stops at its first submission, in
    one line with what sbatch said, exit 3, its scheduler closed and nothing left, rather than retrying for ever."""
    log = stand_in_slurm(tmp_path, monkeypatch, submit)
    args = campaign_args(tmp_path, "--executor", "dask", "--slurm", "queue=debug")
    before, listening = sorted(os.listdir(tmp_path)) + ["submitted.log"], listeners(os.getpid())
    one_line(within(120, lambda: main(args)), capfd, tmp_path, before, words, exit_code=3)
    assert len(log.read_text().split()) >= 1                # the premise: a job was submitted
    assert listeners(os.getpid()) <= listening              # the scheduler does not listen any more


def test_sigterm_while_sbatch_does_not_answer_ends_harness_at_once_with_nothing_left(tmp_path, monkeypatch):
    """sbatch hangs on submitting: SIGTERM ends the campaign within seconds (exit 143, one line), sbatch and what it
    started killed, the store directory it made removed."""
    log = stand_in_slurm(tmp_path, monkeypatch, 'sleep 300 & echo "$!" >> "{log}"; wait')
    from conftest import interruptible
    proc = subprocess.Popen([sys.executable, "-m", "harness", *campaign_args(tmp_path, "--executor", "dask",
                                                                           "--slurm", "queue=debug")],
                            cwd=tmp_path, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            preexec_fn=interruptible)
    try:
        waited = 0.0
        while not (log.exists() and len(log.read_text().split()) == 2) and waited < 120 and proc.poll() is None:
            threading.Event().wait(0.2)
            waited += 0.2
        submitted = [int(pid) for pid in log.read_text().split()]      # sbatch, and what it started
        assert all(map(alive, submitted))                  # the premise: sbatch is still submitting
        proc.send_signal(15)
        out, err = proc.communicate(timeout=15)
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.communicate()
    lines = err.strip().splitlines()
    assert proc.returncode == 143 and len(lines) == 1 and lines[0].startswith("harness: terminated"), err
    assert not any(map(alive, submitted))
    assert not (tmp_path / "store").exists()


def alive(pid):
    """A process with this id runs (a zombie has ended)."""
    try:
        return psutil.Process(pid).status() != psutil.STATUS_ZOMBIE
    except psutil.NoSuchProcess:
        return False


def test_a_store_path_with_an_empty_component_is_refused(tmp_path, capfd):
    """-o /scratch/$USER/store with USER unset."""
    (tmp_path / "c.toml").write_text(TOML)
    before = sorted(os.listdir(tmp_path))
    args = ["campaign", str(tmp_path / "c.toml"), "-o", f"{tmp_path}//store"]
    one_line(main(args), capfd, tmp_path, before, "empty component")


def test_the_printed_job_script_leaves_no_credentials_behind(tmp_path, capfd, monkeypatch):
    monkeypatch.setenv("TMPDIR", str(tmp_path))
    import tempfile
    monkeypatch.setattr(tempfile, "tempdir", None)
    (tmp_path / "c.toml").write_text(TOML)
    assert main(["campaign", str(tmp_path / "c.toml"), "--slurm", "queue=debug", "--slurm-script"]) == 0
    script = capfd.readouterr().out
    assert "#SBATCH -p debug" in script and "--tls-key" in script
    assert os.listdir(tmp_path) == ["c.toml"]


def ctrl_c_as_a_terminal_gives_it():
    """SIGINT at its default in the child, as a shell starts harness: a test runner's worker may ignore it, and
    Python started with SIGINT ignored keeps it ignored (whatever harness does)."""
    signal.signal(signal.SIGINT, signal.SIG_DFL)


def test_dask_jobqueue_leaves_ctrl_c_to_harness():
    """dask-jobqueue's runner sets SIGINT to sys.exit() on import: Ctrl-C would end a campaign with status 0 and no
    word. Imported by harness, from a thread first (where setting a handler fails), the handler is Python's."""
    code = ("import signal, threading\n"
            "from harness.studies.campaign.slurm import slurm_cluster_class\n"
            "thread = threading.Thread(target=slurm_cluster_class)\n"
            "thread.start(); thread.join()\n"
            "slurm_cluster_class()\n"
            "assert signal.getsignal(signal.SIGINT) is signal.default_int_handler, signal.getsignal(signal.SIGINT)\n"
            "print('kept')")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120,
                          preexec_fn=ctrl_c_as_a_terminal_gives_it)
    assert done.returncode == 0 and done.stdout.strip() == "kept" and "Traceback" not in done.stderr, done.stderr
