"""`harness benchmark chung-ooi`: Chung & Ooi (2011)'s eight tests on the reference and the engines; a CSV and a
page."""
import os
import sys

from ..engines import ENGINES
from ..infra.lock import LOCK, exclusive
from ..data.results import write_csv
from ..studies.verification.chung_ooi import LAW, known_engines, run_suite, verdict
from ..views.chung_ooi_html import CSV, PAGE, summary, write_chung_ooi_report
from ..views.figure_files import FIGURES
from ..views.progress import Progress
from ..views.terminal import text_table
from ..infra import strict_json
from ..infra.wording import counted, verb
from .options import EXIT_DISAGREE, EXIT_ENGINE, EXIT_OK, check_entries, check_output_directory


def exit_code(ok, checked, could_not_run):
    """BENCHMARK_EXIT_CODES (options.py): 1 when a check fails; 3 when none fails but an engine could not run or
    nothing was checked; 0."""
    if checked and not ok:
        return EXIT_DISAGREE
    if could_not_run or not checked:
        return EXIT_ENGINE
    return EXIT_OK


def main(args):
    """chung-ooi.csv and chung-ooi.html in DIR; the exit code of BENCHMARK_EXIT_CODES."""
    named = args.engines is not None
    engines = known_engines(None if not named else tuple(n.strip() for n in args.engines.split(",") if n.strip()),
                            args.engines)
    check_output_directory(args.output)
    check_entries(args.output, (CSV, PAGE, LOCK), (FIGURES,))
    with Progress("benchmark chung-ooi", quiet=args.quiet or args.json) as progress:
        table = run_suite(engines, progress=progress)
    with exclusive(args.output):
        write_csv(table, os.path.join(args.output, CSV))
        path = write_chung_ooi_report(args.output, table, "harness " + " ".join(sys.argv[1:]))
    ok, passed, checked = verdict(table)
    missing = [e for e in engines if ENGINES[e].status(LAW).available is False] if named else []
    failed = sorted(set(table[table.quantity == "failed"].engine))
    code = exit_code(ok, checked, missing + failed)
    if args.json:
        print(strict_json.dumps({"ok": ok, "exit_code": code, "passed": passed, "failed": checked - passed,
                          "checked": checked, "could_not_run": missing + failed,
                          "engines": summary(table).to_dict("records"), "csv": os.path.join(args.output, CSV),
                          "report": path}, indent=1, default=str))
        return code
    if not args.quiet:
        print(text_table(summary(table), ["engine", "passed", "failed", "checked", "not run", "why not"], {}))
    print(f"chung-ooi: {passed} of {counted(checked, 'check')} {verb(passed, 'passes')}, {checked - passed} "
          f"{verb(checked - passed, 'fails')} -> {path}"
          + (f"; could not run: {', '.join(missing + failed)}" if missing or failed else ""))
    return code
