"""`harness campaign FILE`: a matrix of comparisons from a TOML file, run in-process or on Dask into a
content-addressed Parquet store that a rerun resumes; `--dry-run` says what it would run and what is cached."""
import os
import sys
import tempfile
from contextlib import closing

from ..studies.campaign.clusters import Unavailable, remove
from ..studies.campaign.driver import dry_run, run_campaign
from ..studies.campaign.executors import executor
from ..studies.campaign.limits import max_workers
from ..studies.campaign.page import page_data
from ..studies.campaign.slurm import forget_credentials, preflight, shell_safe, slurm_cluster, slurm_options
from ..studies.campaign.spec import load
from ..studies.campaign.store import Store
from ..infra.errors import UserError
from ..infra.files import refuse_unless_regular
from ..infra.lock import exclusive
from ..views.campaign_html import figures_folder, write_campaign_report
from ..views.progress import Progress
from ..infra import strict_json
from ..infra.wording import counted
from .options import EXIT_ENGINE, EXIT_OK, check_entries, check_output_directory


def main(args):
    campaign = load(args.file)
    slurm = slurm_options(args.slurm) if args.slurm else None
    if args.slurm_script:
        return print_script(slurm or {})
    refuse_contradictions(args)
    report_path = check_store_path(args.output)
    store = Store(args.output, create=False, drop_damaged=args.drop_damaged) if os.path.isdir(args.output) else None
    try:
        if args.dry_run:
            return report(args, dry_run(campaign, store, args.no_cache), None, dry=True)
        if slurm is not None:
            preflight()
            shell_safe(os.path.abspath(args.output), "store directory (where the workers' credentials go)")
        given = args.scheduler or args.scheduler_file      # reached before anything is written
        where = executor(args.executor, scheduler=args.scheduler, scheduler_file=args.scheduler_file) \
            if given else None
        try:
            with exclusive(args.output), Progress(f"campaign {os.path.basename(args.file)}",
                                                  quiet=args.quiet or args.json) as progress:
                store = Store(args.output)              # again, now that this process is its only writer
                where = where or executor(args.executor, args.workers, slurm=slurm, shared=args.output)
                with closing(where):        # before the lock goes: the cluster's files in the store go first
                    summary = run_campaign(campaign, store, where, args.no_cache, progress)
                table = store.table()
                page = write_campaign_report(table, report_path, campaign.name, page_data(store, table),
                                             args.output)
        finally:
            if where is not None:
                where.close()
    except Unavailable as exc:
        print(f"harness: error: {exc}", file=sys.stderr)
        return EXIT_ENGINE
    return report(args, summary, page)


def refuse_contradictions(args):
    """Options that only mean something together: refused in one line rather than silently ignored."""
    dask = args.executor == "dask"
    elsewhere = next((f"--{name}" for name in ("scheduler", "scheduler_file", "slurm") if getattr(args, name)), None)
    if elsewhere and not dask:
        raise UserError(f"{elsewhere.replace('_', '-')} runs the campaign on Dask: add --executor dask")
    if args.workers is not None and not dask:
        raise UserError("--workers sets the Dask LocalCluster's worker processes: add --executor dask")
    if args.workers is not None and elsewhere:
        raise UserError(f"--workers sets a LocalCluster's worker processes; with {elsewhere.replace('_', '-')} the "
                        "workers are the scheduler's" + (" (--slurm jobs and processes)" if args.slurm else ""))
    if args.workers is not None and not 1 <= args.workers <= max_workers():
        raise UserError(f"--workers must be from 1 to {max_workers()} (four per core here), got {args.workers}")


def check_store_path(path):
    """The store directory and its report: writable, no empty path component (`/scratch/$USER/store` with USER
    unset), the report a new path or a regular file, its figures' folder a new path or a directory; returns the
    report's path."""
    check_output_directory(path)
    if "//" in path.rstrip("/"):
        raise UserError(f"store path {path} has an empty component (an unset variable?)")
    report_path = path.rstrip("/") + ".html"
    refuse_unless_regular(report_path)
    check_entries(os.path.dirname(os.path.abspath(report_path)), (), (figures_folder(report_path),))
    return report_path


def print_script(slurm):
    """The job script --slurm would submit (its credential paths are this run's, removed again)."""
    shared = tempfile.mkdtemp(prefix=f"harness-{os.getpid()}-script-")
    try:
        cluster = slurm_cluster(slurm, shared, shared)
        try:
            print(cluster.job_script())
        finally:
            cluster.close()
            forget_credentials(cluster)
    finally:
        remove(shared)
    return EXIT_OK


def report(args, summary, page, dry=False):
    """Print the summary (or one JSON object); exit 3 when a task failed or an engine asked for was skipped."""
    code = EXIT_ENGINE if summary.failed or summary.skipped else EXIT_OK
    if args.json:
        print(strict_json.dumps({**summary.as_dict(), "store": args.output, "report": page, "dry_run": dry,
                          "exit_code": code}, indent=1))
        return code
    if not args.quiet:
        for engine, entry in summary.per_engine.items():
            print(f"  {engine:10s} " + (f"{counted(entry['tasks'], 'task')}, {entry['cached']} cached, about "
                                        f"{entry['estimated_s']:.0f} s to run" if dry
                                        else f"{counted(entry, 'task')} run"))
        for engine, reason in summary.skipped:
            print(f"skipped {engine}: {reason}")
    verb = "would run" if dry else "ran"
    print(f"campaign: {counted(summary.tasks, 'task')}, {verb} "
          f"{summary.tasks - summary.cached if dry else summary.ran}, "
          f"{summary.cached} cached, {summary.failed} failed; store {args.output}"
          + (f", report {page}" if page else ""))
    return code
