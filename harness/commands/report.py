"""`harness report DIR`: rebuild DIR/report.html from the files of a compare or cost directory, simulating nothing."""
from ..outputs import REPORT
from ..views.figure_files import FIGURES
from ..views.html import rebuild
from .options import EXIT_OK, add_output_options, check_entries


def add(sub, describe):
    p = describe(sub, "report", "harness report harness-out")
    p.add_argument("directory", metavar="DIR")
    add_output_options(p)
    p.set_defaults(func=main)


def main(args):
    check_entries(args.directory, (REPORT,), (FIGURES,))
    print(f"wrote {rebuild(args.directory)}")
    return EXIT_OK
