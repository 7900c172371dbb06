"""`harness check` and `harness baseline --update`: the regression check against the committed baseline."""

from ..studies.baseline import DEFAULT_BASELINE, check, update
from ..runs.request import engines_asked
from ..studies.campaign.store import RunCache, Store
from ..infra.errors import UserError
from ..views.progress import Progress
from ..views.terminal import text_table, wrapped
from ..infra import strict_json
from ..infra.wording import counted
from .options import EXIT_DISAGREE, EXIT_OK, engines_from



def pins(args):
    """The engine builds --engines names (each an external engine's build), or None."""
    names = engines_asked(engines_from(args.engines))
    if names is not None and "reference" in names:
        raise UserError("--engines pins engine builds; the reference always runs")
    return names


def unexplained(failures, engine):
    """Laws whose engine rows moved beyond tolerance while the rows of its dialect in the reference did not."""
    if failures.empty:
        return []
    ran = set(failures[failures.engine == engine].model)
    dialect = set(failures[(failures.engine == "reference") & (failures.dialect == engine)].model)
    return sorted(ran - dialect)


def named_baseline(value):
    """The --baseline directory as given; an empty value is refused rather than read as the working directory."""
    if value is not None and not value.strip():
        raise UserError("--baseline is empty: name a baseline directory")
    return value


def main(args):
    engines, baseline = pins(args), named_baseline(args.baseline) or DEFAULT_BASELINE
    with Progress("check", quiet=args.quiet or args.json) as progress:
        cache = RunCache(Store(args.store, drop_damaged=args.drop_damaged)) if args.store else None
        failures, skipped, releases = check(baseline, progress=progress, cache=cache, engines=engines)
    code = EXIT_OK if failures.empty else EXIT_DISAGREE
    if args.json:
        print(strict_json.dumps({"ok": failures.empty, "exit_code": code, "baseline": baseline, "skipped": skipped,
                          "releases": releases, "outside_tolerance": failures.to_dict("records")}, indent=1,
                         default=str))
        return code
    if not args.quiet:
        for line in skipped:
            print(f"skipped {line}")
        for change in releases:
            print(wrapped(f"{change['engine']}: the baseline is from {change['baseline']}, this check ran "
                          f"{change['now']} ({change['binary']})", indent=2))
            for law, ingredients in change["ingredients"].items():
                print(wrapped(f"  {law}: the releases' dialects differ in {'; '.join(ingredients)}", indent=4))
            for law in unexplained(failures, change["engine"]):
                print(wrapped(f"  {law}: the engine's results moved and its dialect's did not: a change harness' "
                              "reading of the releases does not explain", indent=4))
        if not failures.empty:
            print(text_table(failures, list(failures.columns), {"baseline": "{:.10g}", "now": "{:.10g}",
                                                                "rel_diff": "{:.2e}", "tolerance": "{:.0e}"}))
    print("check: every metric within tolerance" if failures.empty else
          f"check: {counted(len(failures), 'metric')} outside tolerance")
    return code


def main_update(args):
    if not args.update:
        raise UserError("baseline rewrites the committed expectations only with --update")
    baseline = named_baseline(args.baseline)
    if baseline is None:
        raise UserError("baseline --update writes only where --baseline names a directory (the committed one in a "
                        "checkout: --baseline baselines)")
    with Progress("baseline", quiet=args.quiet) as progress:
        frame, skipped = update(baseline, progress=progress, engines=pins(args))
    if not args.quiet:
        for line in skipped:
            print(f"skipped {line}")
    print(f"wrote {counted(len(frame), 'row')} to {baseline}")
    return EXIT_OK
