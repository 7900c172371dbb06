"""`harness cost`: the accuracy-against-cost ladder; its tables, DIR/cost.csv and the report."""
import os
import sys
import time

import pandas as pd

from ..analyses.cost import COLUMNS, LADDER, MEASURE, convergence_orders, step_times
from ..analyses.cost_answer import answers, notes, recommendations, verdict
from ..runs.availability import able_engines
from ..studies.campaign.store import RunCache, Store
from ..studies.cost_estimate import said, study_seconds
from ..studies.cost_plan import check_ladder, cost_table
from ..infra.errors import UserError
from ..infra.files import discard
from ..infra.lock import exclusive
from ..runs.outputs import COST, save_cost
from ..runs.request import Request
from ..data.results import write_csv
from ..views.html import rebuild
from ..views.progress import Progress
from ..views.terminal import print_cost
from ..infra import strict_json
from .options import EXIT_ENGINE, EXIT_OK, check_results_directory, check_store, keywords


def ladder_from_text(text):
    """--ladder '5,10,20' as whole steps per contact, checked (harness.studies.cost_plan.check_ladder)."""
    if text is None:
        return LADDER
    try:
        rungs = tuple(int(part) for part in text.split(",") if part.strip())
    except ValueError:
        raise UserError(f"--ladder takes whole numbers of steps per contact, e.g. 5,10,100; got {text!r}") from None
    return check_ladder(rungs, text)


def main(args):
    """Run the ladder; 0 when every run succeeded or was refused with its reason, 3 when an engine run failed."""
    request = Request.from_keywords(args.model, **keywords(args, resolution=False))
    law, scene, ladder = request.law, request.scene, ladder_from_text(args.ladder)
    check_results_directory(args.output)
    check_store(args.store)
    adapters, skipped = able_engines(request)                # bad options: exit 2 before anything runs
    overrides = dict(request.overrides)
    cache = RunCache(Store(args.store, drop_damaged=args.drop_damaged)) if args.store else None
    parts = study_seconds(law, scene, adapters, ladder)
    estimate = sum(parts.values())
    if not (args.quiet or args.json):
        print(f"harness: cost {law.name}: {said(parts, os.getloadavg()[0], os.cpu_count())}", file=sys.stderr,
              flush=True)
    start = time.perf_counter()
    with exclusive(args.output):
        discard(os.path.join(args.output, "report.html"))     # an earlier report never stands beside this study
        save_cost(args.output, pd.DataFrame(columns=COLUMNS), {}, law, scene, overrides, skipped, [])
        with Progress(f"cost {law.name}", quiet=args.quiet or args.json) as progress:
            table, failures, uncertainty = cost_table(
                law, scene, adapters, ladder, keep=lambda so_far: write_csv(so_far, os.path.join(args.output, COST)),
                progress=progress, cache=cache)
        save_cost(args.output, table, uncertainty, law, scene, overrides, skipped, failures)
        report = rebuild(args.output)
    took = time.perf_counter() - start
    asked = set(request.engines or ()) - {"reference"}
    code = EXIT_ENGINE if failures or asked & {name for name, _ in skipped} else EXIT_OK
    if args.json:
        found = answers(table)
        print(strict_json.dumps({
            "model": law.name, "exit_code": code, "measure": MEASURE,
            "verdict": verdict(table, found).to_dict("records"), "notes": notes(found),
            "step_times": step_times(table).to_dict("records"),
            "recommendations": recommendations(table, found).to_dict("records"),
            "orders": convergence_orders(table).to_dict("records"), "skipped": skipped,
            "failed": [{"engine": f.engine, "e_n": f.e_n, "message": f.message} for f in failures],
            "files": {"cost": os.path.join(args.output, COST), "report": report},
            "seconds": took, "estimated_seconds": estimate}, indent=1, default=str))
        return code
    if not args.quiet:
        print_cost(table, uncertainty, law, scene, ladder, skipped, failures, verbose=args.verbose)
        print(f"took {took / 60:.1f} min (estimated {estimate / 60:.1f} min)")
    print(f"wrote {COST} and {os.path.basename(report)} in {args.output}" + (
        "" if args.verbose or args.quiet else " (every table: --verbose)"))
    return code
