"""Workers on SLURM through dask-jobqueue: the --slurm values, each checked before it reaches the job script (a
newline would add a directive of its own), the cluster itself (TLS, the workers' credentials in a private directory
only the user can read, on the store's file system, which the compute nodes share), the checks that SLURM is
there and takes the job script before anything is submitted, and each submission held to a deadline and to a job
id: a job SLURM does not take is recorded for the campaign to stop on, never retried for ever."""
import asyncio
import contextlib
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile

from ...engines.runner import launcher
from ...infra.errors import UserError
from ...infra.programs import which
from .clusters import NO_HTTP, SCHEDULER, Unavailable, dask_settings
from .limits import CONNECT_TIMEOUT_S, MAX_SLURM_CORES, MAX_SLURM_JOBS

NAME = re.compile(r"[A-Za-z0-9_.+-]{1,100}(,[A-Za-z0-9_.+-]{1,100}){0,20}")
MEMORY = re.compile(r"[0-9]{1,9}(\.[0-9]{1,6})? ?([KMGTP]i?B|[KMGTP]|B)?", re.IGNORECASE)
WALLTIME = re.compile(r"([0-9]{1,4}-)?[0-9]{1,6}(:[0-9]{2}){0,2}")
DIRECTIVE = re.compile(r"--?[A-Za-z][A-Za-z0-9-]*([= ][\x20-\x7e]{1,200})?")
SHELL_SAFE = re.compile(r"[A-Za-z0-9._/@%+=:,-]+")     # a path that goes into the job script's command line
COUNTS = {"cores": MAX_SLURM_CORES, "processes": MAX_SLURM_CORES, "jobs": MAX_SLURM_JOBS}
FORMS = {"queue": (NAME, "partition names (letters, digits, _ . + -, comma-separated)"),
         "account": (NAME, "an account name (letters, digits, _ . + -)"),
         "memory": (MEMORY, "a size such as 16GB"),
         "walltime": (WALLTIME, "a time such as 02:00:00 or 1-00:00:00"),
         "job_extra": (DIRECTIVE, "one sbatch option such as --constraint=haswell")}
SLURM_KEYS = set(COUNTS) | set(FORMS)
CORES = 2                                             # per job, unless --slurm cores says
SCRATCH = ['harness_scratch="$(mktemp -d "${TMPDIR:-/tmp}/harness-dask-XXXXXX")"',
           "trap 'rm -rf \"$harness_scratch\"' EXIT"]     # each job's worker scratch, removed when the job ends


def slurm_options(pairs):
    """{key: value} of --slurm KEY=VALUE, every value checked: counts are whole numbers within their limits,
    words match their form, and nothing may hold a line break or a control character."""
    options = {}
    for pair in pairs or ():
        key, _, value = pair.partition("=")
        if key not in SLURM_KEYS or not value:
            raise UserError(f"--slurm takes KEY=VALUE with KEY one of {', '.join(sorted(SLURM_KEYS))}, got {pair!r}")
        if key in options:
            raise UserError(f"--slurm {key}=... given twice")
        if key in COUNTS:
            if not value.isdigit() or not 1 <= int(value) <= COUNTS[key]:
                raise UserError(f"--slurm {key} must be a whole number from 1 to {COUNTS[key]}, got {value!r}")
            options[key] = int(value)
        else:
            form, words = FORMS[key]
            if not form.fullmatch(value):
                raise UserError(f"--slurm {key} must be {words}, got {value!r}")
            options[key] = value
    cores = options.get("cores", CORES)
    if options.get("processes", cores) > cores:
        raise UserError(f"--slurm processes ({options['processes']}) must not exceed cores ({cores})")
    return options


def shell_safe(path, what):
    """`path` unless it holds a character the job script's shell would read (a space, a quote, $, a newline...)."""
    if not SHELL_SAFE.fullmatch(path):
        raise UserError(f"--slurm puts the {what} into the job script, which takes only letters, digits and "
                        f"._/@%+=:,- in a path; got {path!r}")
    return path


def preflight():
    """Unavailable unless this machine can submit and cancel SLURM jobs."""
    missing = [command for command in ("sbatch", "scancel") if which(command) is None]
    if missing:
        raise Unavailable(f"--slurm needs SLURM's {' and '.join(missing)}, not found on PATH: run the campaign on "
                          "a SLURM login node")


def slurm_cluster(options, shared, scratch):
    """A SLURMCluster whose jobs run this Python with the options given; TLS with credentials made for this run,
    the workers' copies in a private directory under `shared` (a file system the compute nodes see); no HTTP."""
    import dask
    from distributed import Security
    SLURMCluster, SLURMJob = slurm_cluster_class()
    failures, submitting = [], set()
    shell_safe(sys.executable, "Python of this installation")
    credentials = tempfile.mkdtemp(prefix=f".harness-{os.getpid()}-credentials-", dir=shell_safe(
        os.path.abspath(shared), "store directory (where the workers' credentials go)"))
    cores = options.get("cores", CORES)
    try:
        with dask.config.set(dask_settings(scratch)):
            cluster = SLURMCluster(
                queue=options.get("queue"), account=options.get("account"), cores=cores,
                processes=options.get("processes", cores), memory=options.get("memory", "4GB"),
                walltime=options.get("walltime", "01:00:00"), python=sys.executable,
                job_extra_directives=[options["job_extra"]] if "job_extra" in options else [],
                security=Security.temporary(), protocol="tls://", shared_temp_directory=credentials,
                job_cls=job_class(SLURMJob, failures, submitting),
                scheduler_options=SCHEDULER,
                worker_extra_args=["--preload", NO_HTTP], job_script_prologue=SCRATCH,
                local_directory="$harness_scratch")
    except BaseException:
        shutil.rmtree(credentials, ignore_errors=True)
        raise
    cluster.harness_credentials = credentials
    cluster.harness_failures, cluster.harness_submitting = failures, submitting
    return cluster


def slurm_cluster_class():
    """dask-jobqueue's SLURMCluster and SLURMJob, imported without the SIGINT handler its runner module sets on
    import (Ctrl-C would then exit quietly with status 0, and outside the main thread the import fails)."""
    real = signal.signal
    signal.signal = lambda signum, handler: signal.getsignal(signum)
    try:
        from dask_jobqueue import SLURMCluster
        from dask_jobqueue.slurm import SLURMJob
    finally:
        signal.signal = real
    return SLURMCluster, SLURMJob


class NotSubmitted(Exception):
    """SLURM did not take a job: sbatch failed, printed no job id or did not answer."""


def job_class(base, failures, submitting):
    """A SLURMJob submitted and cancelled by sbatch and scancel at their absolute paths, each submission within
    CONNECT_TIMEOUT_S (its process id in `submitting` meanwhile); a job SLURM does not take is appended to
    `failures` (sbatch's words) and left as started without a job, so that dask-jobqueue neither logs a traceback
    nor submits it again."""
    from distributed.core import Status

    class Job(base):
        submit_command = which("sbatch") or "sbatch"       # found by preflight before anything is submitted
        cancel_command = which("scancel") or "scancel"

        async def _submit_job(self, script_filename):
            return await submitted([self.submit_command, script_filename], self.job_id_regexp, submitting)

        async def start(self):
            try:
                await super().start()
            except NotSubmitted as exc:
                failures.append(str(exc))
                self.job_id = None
                self.status = Status.running         # nothing to cancel, nothing to start again
    return Job


async def submitted(argv, job_id, running):
    """What sbatch printed on submitting a job (it holds a job id matching `job_id`); NotSubmitted otherwise. Its
    process id is in the set `running` while it runs."""
    try:
        proc = await asyncio.create_subprocess_exec(*launcher(), *argv, stdin=subprocess.DEVNULL,
                                                    stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                                                    start_new_session=True)
    except OSError as exc:
        raise NotSubmitted(f"sbatch could not run: {exc.strerror}") from None
    running.add(proc.pid)
    try:
        out, err = await asyncio.wait_for(proc.communicate(), CONNECT_TIMEOUT_S)
    except asyncio.TimeoutError:
        raise NotSubmitted(f"sbatch did not answer within {CONNECT_TIMEOUT_S:g} s: is SLURM's controller up?") \
            from None
    finally:
        running.discard(proc.pid)
        with contextlib.suppress(ProcessLookupError):
            os.killpg(proc.pid, signal.SIGKILL)           # whatever it left running, and itself if it hangs
        if proc.returncode is None:
            await proc.wait()
    out, err = out.decode(errors="replace"), err.decode(errors="replace")
    if proc.returncode != 0:
        raise NotSubmitted(f"SLURM did not take a job: {last_line(err or out) or f'sbatch exit {proc.returncode}'}")
    if not re.search(job_id, out):
        said = last_line(out + "\n" + err)
        raise NotSubmitted(f"sbatch printed no job id ({f'its last line: {said!r}' if said else 'it printed nothing'}"
                           "; SLURM's sbatch prints 'Submitted batch job N')")
    return out


def last_line(text, width=200):
    """The last line of `text` that is not blank, cut to `width` characters ('' when there is none)."""
    lines = [line.strip() for line in text.splitlines() if line.strip()]
    return lines[-1][:width] if lines else ""


def stop_submissions(cluster):
    """Kill every sbatch of the cluster still running, so that closing it waits for none (a stop is prompt even
    while SLURM does not answer)."""
    for pid in list(getattr(cluster, "harness_submitting", ())):
        with contextlib.suppress(ProcessLookupError):
            os.killpg(pid, signal.SIGKILL)


def failure(cluster):
    """Why SLURM took none of the cluster's jobs, in sbatch's words, or None."""
    found = getattr(cluster, "harness_failures", None)
    return found[0] if found else None


def forget_credentials(cluster):
    """Delete the workers' copies of the credentials: the files dask-jobqueue keeps open for the cluster's life,
    then their directory."""
    for name, value in list(vars(cluster).items()):
        if name.startswith("_job_") and hasattr(value, "close"):
            with contextlib.suppress(OSError):
                value.close()
    shutil.rmtree(cluster.harness_credentials, ignore_errors=True)


def accepted(cluster, scratch):
    """Unavailable unless SLURM accepts the cluster's job script (sbatch --test-only: checked, not submitted)."""
    path = os.path.join(scratch, "job.sh")
    with open(path, "w") as handle:
        handle.write(cluster.job_script())
    try:
        done = subprocess.run([which("sbatch") or "sbatch", "--test-only", path], capture_output=True, text=True,
                              errors="replace", timeout=CONNECT_TIMEOUT_S, stdin=subprocess.DEVNULL)
    except subprocess.TimeoutExpired:
        raise Unavailable(f"sbatch did not answer within {CONNECT_TIMEOUT_S:g} s: is SLURM's controller up?") from None
    except OSError as exc:
        raise Unavailable(f"sbatch could not run: {exc.strerror}") from None
    if done.returncode != 0:
        raise Unavailable(f"SLURM refused the job script: "
                          f"{last_line(done.stderr or done.stdout) or f'sbatch exit {done.returncode}'}")
