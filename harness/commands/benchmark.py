"""`harness benchmark chung-ooi`: Chung & Ooi (2011)'s eight tests on the reference and the engines; a CSV and a page."""
import os
import sys

from ..engines import ENGINES
from ..lock import LOCK, exclusive
from ..results import write_csv
from ..verification.chung_ooi import LAW, known_engines, run_suite, verdict
from ..views.chung_ooi_html import CSV, PAGE, summary, write_chung_ooi_report
from ..views.figure_files import FIGURES
from ..views.progress import Progress
from ..views.terminal import text_table
from ..views import strict_json
from .options import (EXIT_DISAGREE, EXIT_ENGINE, EXIT_OK, add_output_options, check_entries,
                      check_output_directory)

EXAMPLE = "harness benchmark chung-ooi --engines reference,liggghts -o chung-ooi/"
SUITES = ("chung-ooi",)
EXIT_CODES = """exit codes:
  0  done; every check made passes at the suite's published values, and every engine asked for by name ran
  1  a check fails: a quantity off its published value by more than its tolerance (the CSV and the page say
     which, and what caused it)
  2  bad input (one line on stderr says which); nothing was run
  3  no check failed, but an engine could not run (missing, crashed, timed out: what and why is printed) while it
     was asked for by name or had runs that failed, or no check was made
  4  an internal error of harness (a bug: the traceback is printed)
  130 interrupted (Ctrl-C), 143 terminated (SIGTERM), 129 hung up (SIGHUP): engines stopped, temporary files
     removed"""


def add(sub, describe):
    p = describe(sub, "benchmark", EXAMPLE, EXIT_CODES)
    p.add_argument("suite", choices=SUITES, help="the suite: chung-ooi")
    p.add_argument("--engines", default=None, metavar="LIST",
                   help=f"comma-separated engines of {', '.join(ENGINES)} (default: every one; those missing are "
                        "reported as not run)")
    p.add_argument("-o", "--output", default="harness-chung-ooi", metavar="DIR",
                   help="output directory (default %(default)s)")
    add_output_options(p, json=True)
    p.set_defaults(func=main)


def exit_code(ok, checked, could_not_run):
    """EXIT_CODES: 1 when a check fails; 3 when none fails but an engine could not run or nothing was checked; 0."""
    if checked and not ok:
        return EXIT_DISAGREE
    if could_not_run or not checked:
        return EXIT_ENGINE
    return EXIT_OK


def main(args):
    """chung-ooi.csv and chung-ooi.html in DIR; the exit code of EXIT_CODES."""
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
    print(f"chung-ooi: {passed} of {checked} checks pass, {checked - passed} fail -> {path}"
          + (f"; could not run: {', '.join(missing + failed)}" if missing or failed else ""))
    return code
