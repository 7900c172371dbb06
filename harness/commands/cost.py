"""`harness cost`: the accuracy-against-cost ladder; its tables, DIR/cost.csv and the report."""
import json
import os

import pandas as pd

from ..analyses.cost import COLUMNS, LADDER, convergence_orders, recommendations
from ..api import options_for, statuses
from ..campaign.store import DROP, DROP_HELP, RunCache, Store
from ..cost_plan import TIMING_REPEATS, cost_table
from ..engines import ENGINES
from ..errors import UserError
from ..files import discard
from ..lock import exclusive
from ..outputs import COST, save_cost
from ..request import Request
from ..results import write_csv
from ..solver.batch import MAX_STEPS_PER_CONTACT
from ..views.html import rebuild
from ..views.progress import Progress
from ..views.terminal import print_cost
from .options import (EXIT_ENGINE, EXIT_OK, add_engine_options, add_output_options, add_scene_options,
                      check_results_directory, check_store, keywords)

EXAMPLE = "harness cost --model hertz-mindlin --en 0.9,0.3 --angles 0:80:20 -o cost/"


def add(sub, describe):
    p = describe(sub, "cost", EXAMPLE)
    p.add_argument("--model", required=True, help="law name (see `harness models`)")
    add_engine_options(p)
    add_scene_options(p, resolution=False)
    p.add_argument("--ladder", default=None, metavar="LIST",
                   help="steps per contact to try (default 5,10,20,50,100,200,500,1000,5000)")
    p.add_argument("-o", "--output", default="harness-out", metavar="DIR", help="output directory (default %(default)s)")
    p.add_argument("--store", metavar="STORE", help="a campaign store: the converged truths' runs are taken from it "
                                                    "or added to it (timed runs never are)")
    p.add_argument(DROP, action="store_true", help=DROP_HELP)
    add_output_options(p, json=True)
    p.set_defaults(func=main)


MAX_RUNGS = 30                              # each rung runs every curve at every e_n, timed up to 3 times
MAX_LADDER_STEPS = 2 * MAX_STEPS_PER_CONTACT    # the rungs together: two runs at the finest resolution allowed


def ladder_from_text(text):
    """--ladder '5,10,20': whole steps per contact >= 1, ascending, no repeats; at most MAX_RUNGS rungs, each at most
    MAX_STEPS_PER_CONTACT (every resolution's bound) and MAX_LADDER_STEPS together, so that the study ends."""
    if text is None:
        return LADDER
    try:
        rungs = tuple(int(part) for part in text.split(",") if part.strip())
    except ValueError:
        raise UserError(f"--ladder takes whole numbers of steps per contact, e.g. 5,10,100; got {text!r}") from None
    if not rungs or min(rungs) < 1 or list(rungs) != sorted(set(rungs)):
        raise UserError(f"--ladder needs ascending whole numbers >= 1 without repeats, got {text!r}")
    if len(rungs) > MAX_RUNGS:
        raise UserError(f"--ladder may have at most {MAX_RUNGS} rungs (each runs every curve at every e_n, timed up "
                        f"to {TIMING_REPEATS} times), got {len(rungs)}")
    if rungs[-1] > MAX_STEPS_PER_CONTACT:
        raise UserError(f"--ladder rungs must be at most {MAX_STEPS_PER_CONTACT:.0e} steps per contact (the bound of "
                        f"every resolution), got {rungs[-1]}")
    if sum(rungs) > MAX_LADDER_STEPS:
        raise UserError(f"--ladder rungs may add up to at most {MAX_LADDER_STEPS:.0e} steps per contact (the work of "
                        f"two runs at the finest resolution allowed), got {sum(rungs):.3g}")
    return rungs


def main(args):
    """Run the ladder; 0 when every run succeeded or was refused with its reason, 3 when an engine run failed."""
    request = Request.from_keywords(args.model, **keywords(args, resolution=False))
    law, scene, ladder = request.law, request.scene, ladder_from_text(args.ladder)
    check_results_directory(args.output)
    check_store(args.store)
    found = statuses(request)
    adapters = {s.name: (ENGINES[s.name], options_for(request, s.name)) for s in found if s.available}
    for name, (adapter, options) in adapters.items():
        adapter.dialect(law.name, options)                    # bad options: exit 2 before anything runs
    skipped = [(s.name, s.reason) for s in found if not s.available]
    overrides = dict(request.overrides)
    cache = RunCache(Store(args.store, drop_damaged=args.drop_damaged)) if args.store else None
    with exclusive(args.output):
        discard(os.path.join(args.output, "report.html"))     # an earlier report never stands beside this study
        save_cost(args.output, pd.DataFrame(columns=COLUMNS), {}, law, scene, overrides, skipped, [])
        with Progress(f"cost {law.name}", quiet=args.quiet or args.json) as progress:
            table, failures, uncertainty = cost_table(
                law, scene, adapters, ladder, keep=lambda so_far: write_csv(so_far, os.path.join(args.output, COST)),
                progress=progress, cache=cache)
        save_cost(args.output, table, uncertainty, law, scene, overrides, skipped, failures)
        report = rebuild(args.output)
    asked = set(request.engines or ()) - {"reference"}
    code = EXIT_ENGINE if failures or asked & {name for name, _ in skipped} else EXIT_OK
    if args.json:
        print(json.dumps({"model": law.name, "exit_code": code, "recommendations": recommendations(table).to_dict(
            "records"), "orders": convergence_orders(table).to_dict("records"), "skipped": skipped,
            "failed": [{"engine": f.engine, "e_n": f.e_n, "message": f.message} for f in failures],
            "files": {"cost": os.path.join(args.output, COST), "report": report}}, indent=1, default=str))
        return code
    if not args.quiet:
        print_cost(table, uncertainty, law, scene, ladder, skipped, failures)
        print()
    print(f"wrote {os.path.join(args.output, COST)} and {report}")
    return code
