"""Where a campaign's tasks run: in this process, or on Dask (a LocalCluster of worker processes bound to the
loopback address, an existing scheduler, or SLURM through dask-jobqueue). Every executor calls on_done(i, frame,
log tail) as each task finishes, in whatever order they finish, with a bounded number of tasks in flight."""
import os

from ..engines import ENGINES
from ..errors import UserError

SLURM_KEYS = {"queue", "account", "cores", "memory", "walltime", "jobs", "processes", "job_extra"}


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

    def __init__(self, client, cluster=None):
        """`client` (and the local `cluster` it owns). Dask's garbage-collection diagnosis runs as a gc callback in
        this process, and Python discards an exception raised inside one: a Ctrl-C landing during a collection
        would be lost and the campaign run on. It is switched off here."""
        from distributed.gc import disable_gc_diagnosis
        disable_gc_diagnosis(force=True)
        self.client, self.cluster = client, cluster

    @property
    def workers(self):
        return max(1, len(self.client.scheduler_info().get("workers", {})))

    def map(self, runs, keys, on_done):
        from distributed import as_completed
        pending = iter(range(len(runs)))
        window = as_completed()
        index = {}

        def submit(count):
            for i in [i for _, i in zip(range(count), pending)]:
                future = self.client.submit(run_task, runs[i], key=f"harness-task-{keys[i]}", pure=False)
                index[future.key] = i
                window.add(future)
        submit(max(2, 2 * self.workers))
        try:
            for future in window:
                frame, log_tail = future.result()
                on_done(index.pop(future.key), frame, log_tail)
                future.release()
                submit(1)
        except BaseException:
            for future in list(window.futures):
                future.cancel()
            raise

    def close(self):
        self.client.close()
        if self.cluster is not None:
            self.cluster.close()


def local_cluster(workers=None):
    """Worker processes on this machine, one thread each, listening on the loopback address only, no dashboard."""
    from distributed import LocalCluster
    return LocalCluster(n_workers=workers or len(os.sched_getaffinity(0)), threads_per_worker=1, processes=True,
                        host="127.0.0.1", dashboard_address=None)


def slurm_options(pairs):
    """{key: value} of --slurm KEY=VALUE (queue, account, cores, memory, walltime, jobs, processes, job_extra)."""
    options = {}
    for pair in pairs or ():
        key, _, value = pair.partition("=")
        if key not in SLURM_KEYS or not value:
            raise UserError(f"--slurm takes KEY=VALUE with KEY one of {', '.join(sorted(SLURM_KEYS))}, got {pair!r}")
        options[key] = value
    return options


def slurm_cluster(options):
    """A dask-jobqueue SLURMCluster whose jobs run this Python (the harness installed here) with the options given."""
    import sys

    from dask_jobqueue import SLURMCluster
    cores = int(options.get("cores", 2))
    return SLURMCluster(queue=options.get("queue"), account=options.get("account"), cores=cores,
                        processes=int(options.get("processes", cores)), memory=options.get("memory", "4GB"),
                        walltime=options.get("walltime", "01:00:00"), python=sys.executable,
                        job_extra_directives=[options["job_extra"]] if "job_extra" in options else [],
                        scheduler_options={"dashboard_address": None})


def executor(kind, workers=None, scheduler=None, scheduler_file=None, slurm=None):
    """The executor a command asks for: 'local' (in this process) or 'dask' (an address or scheduler file, SLURM,
    else a LocalCluster)."""
    if kind == "local":
        return InProcess()
    if kind != "dask":
        raise UserError(f"--executor must be local or dask, got {kind!r}")
    from distributed import Client
    if scheduler:
        return OnDask(Client(scheduler))
    if scheduler_file:
        return OnDask(Client(scheduler_file=scheduler_file))
    if slurm is not None:
        cluster = slurm_cluster(slurm)
        cluster.adapt(minimum_jobs=0, maximum_jobs=int(slurm.get("jobs", 4)))
        return OnDask(Client(cluster), cluster)
    cluster = local_cluster(workers)
    return OnDask(Client(cluster), cluster)
