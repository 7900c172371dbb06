"""`harness benchmark chung-ooi`: Chung & Ooi (2011)'s eight tests on the reference and the engines; a CSV and a page."""
import json
import os
import sys

from ..engines import ENGINES
from ..errors import UserError
from ..lock import exclusive
from ..results import write_csv
from ..verification.chung_ooi import run_suite, verdict
from ..views.chung_ooi_html import CSV, summary, write_chung_ooi_report
from ..views.progress import Progress
from ..views.terminal import text_table
from .options import EXIT_DISAGREE, EXIT_ENGINE, EXIT_OK, add_output_options, check_output_directory

EXAMPLE = "harness benchmark chung-ooi --engines reference,liggghts -o chung-ooi/"
SUITES = ("chung-ooi",)


def add(sub, describe):
    p = describe(sub, "benchmark", "a published verification suite (Chung & Ooi 2011's eight tests) on the reference "
                                   "and the engines: every quantity against its closed form", EXAMPLE)
    p.add_argument("suite", choices=SUITES, help="the suite: chung-ooi")
    p.add_argument("--engines", default=None, metavar="LIST",
                   help=f"comma-separated engines of {', '.join(ENGINES)} (default: every one; those missing are "
                        "reported as not run)")
    p.add_argument("-o", "--output", default="harness-chung-ooi", metavar="DIR",
                   help="output directory (default %(default)s)")
    add_output_options(p, json=True)
    p.set_defaults(func=main)


def main(args):
    """chung-ooi.csv and chung-ooi.html in DIR; exit 0 when every applicable check passes, 1 when one fails, 3 when
    an engine named in --engines could not run a test it supports or is missing."""
    named = args.engines is not None
    engines = tuple(ENGINES) if not named else tuple(n.strip() for n in args.engines.split(",") if n.strip())
    unknown = [n for n in engines if n not in ENGINES]
    if unknown or not engines:
        raise UserError(f"unknown engine(s) {', '.join(unknown) or args.engines!r}; known: {', '.join(ENGINES)}")
    check_output_directory(args.output)
    with Progress("benchmark chung-ooi", quiet=args.quiet or args.json) as progress:
        table = run_suite(engines, progress=progress)
    with exclusive(args.output):
        write_csv(table, os.path.join(args.output, CSV))
        path = write_chung_ooi_report(args.output, table, "harness " + " ".join(sys.argv[1:]))
    ok, passed, checked = verdict(table)
    missing = [e for e in engines if ENGINES[e].status("hertz-mindlin").available is False] if named else []
    failed = sorted(set(table[table.quantity == "failed"].engine))
    code = EXIT_DISAGREE if not ok else EXIT_ENGINE if missing or failed else EXIT_OK
    if args.json:
        print(json.dumps({"ok": ok, "exit_code": code, "passed": passed, "checked": checked,
                          "could_not_run": missing + failed, "engines": summary(table).to_dict("records"),
                          "csv": os.path.join(args.output, CSV), "report": path}, indent=1, default=str))
        return code
    if not args.quiet:
        print(text_table(summary(table), ["engine", "passed", "checked", "not run", "why not"], {}))
    print(f"chung-ooi: {passed} of {checked} checks pass -> {path}"
          + (f"; could not run: {', '.join(missing + failed)}" if missing or failed else ""))
    return code
