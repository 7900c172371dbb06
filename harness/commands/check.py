"""`harness check` and `harness baseline --update`: the regression check against the committed baseline."""
from ..baseline import DEFAULT_BASELINE, check, update
from ..errors import UserError
from ..views.terminal import text_table
from .options import EXIT_DISAGREE, EXIT_OK


def add(sub, describe):
    p = describe(sub, "check", "recompute the baseline matrix; exit 1 listing every metric outside tolerance",
                 "harness check")
    p.add_argument("--baseline", default=DEFAULT_BASELINE, metavar="DIR",
                   help="baseline directory (default: the committed one, shipped with harness)")
    p.set_defaults(func=main)
    p = describe(sub, "baseline", "rewrite the committed baseline matrix on purpose",
                 "harness baseline --update --baseline baselines")
    p.add_argument("--update", action="store_true", help="required: rewriting expectations is deliberate")
    p.add_argument("--baseline", default=DEFAULT_BASELINE, metavar="DIR", help="baseline directory")
    p.set_defaults(func=main_update)


def main(args):
    failures, skipped = check(args.baseline)
    for line in skipped:
        print(f"skipped {line}")
    if failures.empty:
        print("check: every metric within tolerance")
        return EXIT_OK
    print(f"check: {len(failures)} metric(s) outside tolerance")
    print(text_table(failures, list(failures.columns), {"baseline": "{:.10g}", "now": "{:.10g}",
                                                        "rel_diff": "{:.2e}", "tolerance": "{:.0e}"}))
    return EXIT_DISAGREE


def main_update(args):
    if not args.update:
        raise UserError("baseline rewrites the committed expectations only with --update")
    frame, skipped = update(args.baseline)
    for line in skipped:
        print(f"skipped {line}")
    print(f"wrote {len(frame)} rows to {args.baseline}")
    return EXIT_OK
