"""`harness compare`: the paper law, each engine's dialect and each engine on one scene; tables, CSVs, report."""
import datetime
import os
import shlex
import sys

import pandas as pd

from ..analyses.physics import DEVIATES, MARGINAL
from ..analyses.verdict import DISAGREE, NOT_COMPARED, verdict
from ..api.requests import compare_request
from ..studies.campaign.store import RunCache, Store
from ..runs.comparison import Comparison, shown_rows
from ..infra.files import discard
from ..infra.lock import exclusive
from ..runs.outputs import save_comparison, start_comparison
from ..runs.partial import PartialRuns
from ..runs.request import Request
from ..data.results import write_csv
from ..views.html import rebuild
from ..views.progress import Progress
from ..views.terminal import print_comparison, print_summary, verdict_line
from ..infra import strict_json
from ..infra.errors import UserError
from .options import EXIT_DISAGREE, EXIT_ENGINE, EXIT_OK, check_results_directory, check_store, keywords


def main(args):
    """Write DIR/results.csv (after every batch), the other tables and report.html; the exit code is the verdict."""
    if args.scene != "impact" or args.scene_params:
        refuse_scene(args)
    request = Request.from_keywords(args.model, tolerances=args.tolerances, **keywords(args))
    check_results_directory(args.output)
    check_store(args.store)
    results_path, report_path = os.path.join(args.output, "results.csv"), os.path.join(args.output, "report.html")
    frames = []

    def keep(frame):                       # results.csv holds every finished run, whatever stops the compare, in the
                                           # order every view shows (not the order the runs finished in)
        if not frames:                     # the first result replaces an earlier compare in DIR, never refused input;
            discard(report_path)           # its report goes first, so that none stands beside the new results
            start_comparison(args.output, Comparison(request.law, request.scene, pd.DataFrame(),
                                                     overrides=dict(request.overrides), requested=request.engines,
                                                     engine_options=request.engine_options, command=command_line(),
                                                     tolerances=request.tolerances))
        frames.append(frame)
        write_csv(shown_rows(pd.concat(frames, ignore_index=True), request.engines), results_path)

    with exclusive(args.output), Progress(f"compare {request.model}", quiet=args.quiet or args.json) as progress:
        partial = (RunCache(Store(args.store, drop_damaged=args.drop_damaged)) if args.store else
                   PartialRuns(args.output))
        try:
            comparison = compare_request(request, on_frame=keep, progress=progress, partial=partial)
        except KeyboardInterrupt:
            if frames:                     # what finished, as a report marked partial
                rebuild(args.output)
            raise
        progress.expect(1)
        comparison.command = command_line()
        comparison.date = datetime.datetime.now().isoformat(timespec="minutes")
        save_comparison(args.output, comparison)
        report = rebuild(args.output)
        if not args.store:
            partial.clear()
        progress.advance("report")
    record = verdict(comparison)
    reference_only = request.engines is not None and set(request.engines) == {"reference"}
    code = exit_code(record, reference_only, args.require)
    states_path = os.path.join(args.output, "states.csv") if comparison.states is not None else None
    if args.json:
        states = {"states": comparison.states.to_dict("records")} if states_path else {}
        files = {"results": results_path, "report": report, **({"states": states_path} if states_path else {})}
        print(strict_json.dumps({**record, **states, "exit_code": code, "files": files}, indent=1, default=str))
        return code
    written = [results_path, *([states_path] if states_path else []), report]
    if args.verbose:
        print_comparison(comparison, written)
    elif not args.quiet:
        print_summary(record, comparison, written)
    print(verdict_line(record, reference_only))
    return code


def refuse_scene(args):
    """compare runs the impact scene alone: a scene kind other than impact is one line saying what runs it."""
    from ..api.scene_requests import runnable_kind
    if args.scene == "impact":
        raise UserError("scene impact takes its own options (--target, --en, --angles, ...), not --scene-param")
    runnable_kind(args.scene)
    raise UserError(f"compare runs the impact scene: `harness run --scene {args.scene} --engines ...` runs it on the "
                    "reference solver and the engines")


def command_line():
    """This command as typed (for the report)."""
    return "harness " + shlex.join(sys.argv[1:])


def exit_code(record, reference_only, require=None):
    """1 when an engine disagrees (or, with require="paper", misses the paper law: deviates or marginal, the
    tolerances being the bound); 3 when an engine asked for did not run, a run failed, or nothing was compared
    (unless the reference alone was asked for); else 0."""
    if record["verdict"] == DISAGREE or (require == "paper" and record["physics"] in (DEVIATES, MARGINAL)):
        return EXIT_DISAGREE
    if record["unavailable"] or record["failed"] or (record["verdict"] == NOT_COMPARED and not reference_only):
        return EXIT_ENGINE
    return EXIT_OK
