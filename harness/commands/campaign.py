"""`harness campaign FILE`: a matrix of comparisons from a TOML file, run in-process or on Dask into a
content-addressed Parquet store that a rerun resumes; `--dry-run` says what it would run and what is cached."""
import json
import os

from ..campaign.driver import dry_run, run_campaign
from ..campaign.executors import executor, slurm_cluster, slurm_options
from ..campaign.spec import load
from ..campaign.store import DROP, DROP_HELP, Store
from ..errors import UserError
from ..lock import exclusive
from ..views.campaign_html import write_campaign_report
from ..views.progress import Progress
from .options import EXIT_ENGINE, EXIT_OK, add_output_options, check_output_directory


def add(sub, describe):
    p = describe(sub, "campaign", "run a matrix of comparisons from a TOML file into a Parquet store that resumes",
                 "harness campaign examples/campaign.toml -o campaign-store --executor dask")
    p.add_argument("file", metavar="FILE", help="the campaign (TOML; examples/campaign.toml)")
    p.add_argument("-o", "--output", default="campaign-store", metavar="STORE",
                   help="the store directory (default %(default)s); its report is STORE.html")
    p.add_argument("--executor", choices=("local", "dask"), default="local",
                   help="local: in this process; dask: a LocalCluster here unless --scheduler, --scheduler-file or "
                        "--slurm says where")
    p.add_argument("--workers", type=int, default=None, help="LocalCluster worker processes (default: the cores)")
    where = p.add_mutually_exclusive_group()
    where.add_argument("--scheduler", metavar="ADDRESS", help="an existing Dask scheduler, e.g. tcp://host:8786")
    where.add_argument("--scheduler-file", metavar="F", help="an existing Dask scheduler's file")
    where.add_argument("--slurm", metavar="KEY=VALUE", action="append",
                       help="run on SLURM through dask-jobqueue: queue, account, cores, memory, walltime, jobs, "
                            "processes, job_extra (repeat the option)")
    p.add_argument("--slurm-script", action="store_true", help="print the SLURM job script --slurm would submit")
    p.add_argument("--dry-run", action="store_true", help="print the tasks, what is cached and an estimate; run nothing")
    p.add_argument("--no-cache", action="store_true", help="rerun every task, even those the store holds")
    p.add_argument(DROP, action="store_true", help=DROP_HELP)
    add_output_options(p, json=True)
    p.set_defaults(func=main)


def main(args):
    campaign = load(args.file)
    slurm = slurm_options(args.slurm) if args.slurm else None
    if args.slurm_script:
        cluster = slurm_cluster(slurm or {})
        try:
            print(cluster.job_script())
        finally:
            cluster.close()
        return EXIT_OK
    if args.workers is not None and args.workers < 1:
        raise UserError(f"--workers must be at least 1, got {args.workers}")
    check_output_directory(args.output)
    store = Store(args.output, create=False, drop_damaged=args.drop_damaged) if os.path.isdir(args.output) else None
    if args.dry_run:
        return report(args, dry_run(campaign, store, args.no_cache), None, dry=True)
    with exclusive(args.output), Progress(f"campaign {os.path.basename(args.file)}",
                                          quiet=args.quiet or args.json) as progress:
        where = executor(args.executor, args.workers, args.scheduler, args.scheduler_file, slurm)
        try:
            summary = run_campaign(campaign, args.output, where, args.no_cache, progress)
        finally:
            where.close()
        page = write_campaign_report(Store(args.output).table(), args.output.rstrip("/") + ".html", campaign.name)
    return report(args, summary, page)


def report(args, summary, page, dry=False):
    """Print the summary (or one JSON object); exit 3 when a task failed or an engine asked for was skipped."""
    code = EXIT_ENGINE if summary.failed or summary.skipped else EXIT_OK
    if args.json:
        print(json.dumps({**summary.as_dict(), "store": args.output, "report": page, "dry_run": dry,
                          "exit_code": code}, indent=1))
        return code
    if not args.quiet:
        for engine, entry in summary.per_engine.items():
            print(f"  {engine:10s} " + (f"{entry['tasks']} tasks, {entry['cached']} cached, about "
                                        f"{entry['estimated_s']:.0f} s to run" if dry else f"{entry} tasks run"))
        for engine, reason in summary.skipped:
            print(f"skipped {engine}: {reason}")
    verb = "would run" if dry else "ran"
    print(f"campaign: {summary.tasks} tasks, {verb} {summary.tasks - summary.cached if dry else summary.ran}, "
          f"{summary.cached} cached, {summary.failed} failed; store {args.output}"
          + (f", report {page}" if page else ""))
    return code
