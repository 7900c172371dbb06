"""`harness paper`: the paper's figure set on its scene: an HTML page and four CSVs."""
import os
import sys

from ..infra.lock import LOCK, exclusive
from ..studies.paper import checked, figure_set
from ..data.results import write_csv
from ..views.paper_html import FILES, NORMAL, OBLIQUE, PUBLISHED, SLIDING, write_paper_report
from ..views.progress import Progress
from ..studies.sliding_search import PSI_MAX
from ..views.terminal import published_summary, sliding_summary
from ..views.figure_files import FIGURES
from .options import EXIT_OK, check_entries, check_output_directory


def main(args):
    """The paper's figure set: paper.csv, paper-normal.csv, paper-sliding.csv, paper-published.csv and paper.html
    in DIR."""
    laws = None if args.laws is None else tuple(n.strip() for n in args.laws.split(",") if n.strip())
    laws = checked(laws, args.steps_per_contact, args.laws)
    check_output_directory(args.output)
    check_entries(args.output, FILES + (LOCK,), (FIGURES,))
    with Progress("paper", quiet=args.quiet) as progress:
        oblique, normal, sliding, published = figure_set(laws, args.steps_per_contact, progress=progress)
    with exclusive(args.output):
        write_csv(oblique, os.path.join(args.output, OBLIQUE))
        for table, name in ((normal, NORMAL), (sliding, SLIDING), (published, PUBLISHED)):
            write_csv(table, os.path.join(args.output, name))
        path = write_paper_report(args.output, oblique, normal, sliding, "harness " + " ".join(sys.argv[1:]),
                                  published)
    if not args.quiet:
        print(sliding_summary(sliding, PSI_MAX))
        if not published.empty:
            print(published_summary(published))
    print(f"wrote {path}")
    return EXIT_OK

