"""`harness report DIR`: rebuild DIR/report.html from the files of a compare or cost directory, simulating nothing."""
from ..runs.outputs import REPORT
from ..views.figure_files import FIGURES
from ..views.html import rebuild
from .options import EXIT_OK, check_entries


def main(args):
    check_entries(args.directory, (REPORT,), (FIGURES,))
    print(f"wrote {rebuild(args.directory)}")
    return EXIT_OK
