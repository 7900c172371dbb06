"""Where a campaign's tasks run: in this process, or on Dask (a LocalCluster of worker processes here, an existing
scheduler, or SLURM: clusters.py and slurm.py here). Every executor calls on_done(i, frame, log tail) as each
task finishes, in whatever order they finish, with a bounded number of tasks in flight."""
import contextlib
import errno
import logging
import os
import time

from ...engines import ENGINES
from ...infra.errors import UserError
from .clusters import Unavailable, address_in, connect, local_cluster, remove, scratch_directory
from .limits import max_workers
from .slurm import accepted, failure, forget_credentials, slurm_cluster, stop_submissions

log = logging.getLogger("harness")
POLL_S = 0.1            # how often the wait for finished tasks looks whether the cluster can start no worker


def run_task(run):
    """One task (an engine batch or a block of reference impacts): (results frame, log tail if it failed)."""
    frame, failure = ENGINES[run.engine].run([run])[0]
    return frame, failure.log_tail if failure is not None else ""


class InProcess:
    """Tasks one after another in this process."""
    name = "in-process"
    workers = 1

    def map(self, runs, keys, on_done):
        for i, run in enumerate(runs):
            on_done(i, *run_task(run))

    def close(self):
        pass


class OnDask:
    """Tasks on a Dask client; at most `in_flight` submitted and not yet finished."""
    name = "dask"

    def __init__(self, client, cluster=None, cleanups=()):
        """`client`, the `cluster` it owns (closed with it) and what removes the files harness made for the
        cluster (called last). Dask's garbage-collection diagnosis runs as a gc callback in this process, and Python
        discards an exception raised inside one: a Ctrl-C landing during a collection would be lost and the
        campaign run on. It is switched off here."""
        from distributed.gc import disable_gc_diagnosis
        disable_gc_diagnosis(force=True)
        self.client, self.cluster, self.cleanups = client, cluster, tuple(cleanups)
        self.closed = False

    @property
    def workers(self):
        return max(1, len(self.client.scheduler_info().get("workers", {})))

    def map(self, runs, keys, on_done):
        from distributed import as_completed
        pending = iter(range(len(runs)))
        window = as_completed(loop=self.client.loop)
        index = {}

        def submit(count):
            for i in [i for _, i in zip(range(count), pending)]:
                future = self.client.submit(run_task, runs[i], key=f"harness-task-{keys[i]}", pure=False)
                index[future.key] = i
                window.add(future)
        submit(max(2, 2 * self.workers))
        try:
            for future in self.finished(window):
                frame, log_tail = future.result()
                on_done(index.pop(future.key), frame, log_tail)
                future.release()
                submit(1)
        except BaseException:
            for future in list(window.futures):
                future.cancel()
            raise

    def finished(self, window):
        """The futures of `window` as each finishes; Unavailable as soon as a job SLURM did not take leaves the
        cluster without a worker, rather than a wait for workers that never come."""
        while not window.is_empty():
            while not window.has_ready():
                reason = failure(self.cluster)
                if reason and not self.client.scheduler_info().get("workers"):
                    raise Unavailable(reason)
                time.sleep(POLL_S)
            yield next(window)

    def close(self):
        """Close the client, then the cluster, then remove what harness made for them; a failure to close (a
        cluster that cannot cancel its jobs) is said in one line and does not hide what stopped the campaign; a
        second call does nothing."""
        if self.closed:
            return
        self.closed = True
        stop_submissions(self.cluster)
        for what, close in (("client", self.client.close), ("cluster", getattr(self.cluster, "close", None))):
            if close is None:
                continue
            try:
                close()
            except Exception as exc:
                log.warning(f"could not close the Dask {what}: {str(exc).splitlines()[0] if str(exc) else exc!r}")
        for cleanup in self.cleanups:
            cleanup()


def workers_for(workers):
    """The LocalCluster's worker processes: `workers`, or one per core this process may use, within the limit."""
    if workers is None:
        return len(os.sched_getaffinity(0))
    if not 1 <= workers <= max_workers():
        raise UserError(f"--workers must be from 1 to {max_workers()} (four per core here), got {workers}")
    return workers


def executor(kind, workers=None, scheduler=None, scheduler_file=None, slurm=None, shared=None):
    """The executor a command asks for: 'local' (in this process) or 'dask' (an address or scheduler file, SLURM
    with the workers' credentials under `shared`, else a LocalCluster)."""
    if kind == "local":
        return InProcess()
    if kind != "dask":
        raise UserError(f"--executor must be local or dask, got {kind!r}")
    from distributed import Client
    if scheduler or scheduler_file:
        return OnDask(connect(scheduler or address_in(scheduler_file)))
    scratch = scratch_directory("dask")
    cluster = None
    try:
        if slurm is not None:
            cluster = slurm_cluster(slurm, shared, scratch)
            accepted(cluster, scratch)
            cluster.adapt(minimum_jobs=0, maximum_jobs=slurm.get("jobs", 4))
        else:
            cluster = started(lambda: local_cluster(workers_for(workers), scratch), scratch)
        return OnDask(Client(cluster, set_as_default=False), cluster, cleanups(cluster, scratch))
    except BaseException:
        if cluster is not None:
            stop_submissions(cluster)
            with contextlib.suppress(Exception):
                cluster.close()
        for cleanup in cleanups(cluster, scratch):
            cleanup()
        raise


def started(start, scratch):
    """A cluster `start` returns; one that fails for want of room in its scratch (a full TMPDIR, a quota) is
    Unavailable in one line, not Dask's traceback."""
    spec = logging.getLogger("distributed.deploy.spec")
    level = spec.level
    spec.setLevel(logging.ERROR)                     # its "closed without starting up" would be a second line
    try:
        return start()
    except Exception as exc:
        cause = exc
        while cause is not None and not isinstance(cause, OSError):
            cause = cause.__cause__ or cause.__context__
        if cause is None or cause.errno not in (errno.ENOSPC, errno.EDQUOT):
            raise
        room = "no space left on the device" if cause.errno == errno.ENOSPC else "disk quota exceeded"
        raise Unavailable(f"the Dask cluster could not start: {room} of its scratch directory "
                          f"{os.path.dirname(scratch)} (TMPDIR); free some or point TMPDIR elsewhere") from None
    finally:
        spec.setLevel(level)


def cleanups(cluster, scratch):
    """What removes the files harness made for a cluster: the workers' credentials (SLURM), then its scratch."""
    credentials = [lambda: forget_credentials(cluster)] if hasattr(cluster, "harness_credentials") else []
    return credentials + [lambda: remove(scratch)]
