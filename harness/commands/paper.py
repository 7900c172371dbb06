"""`harness paper`: the paper's figure set on its scene: an HTML page and four CSVs."""
import os
import sys

from ..errors import UserError
from ..laws import LAWS
from ..lock import LOCK, exclusive
from ..paper import figure_set
from ..results import write_csv
from ..solver.batch import MAX_STEPS_PER_CONTACT
from ..views.paper_html import FILES, NORMAL, OBLIQUE, PUBLISHED, SLIDING, write_paper_report
from ..views.progress import Progress
from ..views.terminal import published_summary, text_table
from ..views.figure_files import FIGURES
from .options import EXIT_OK, add_output_options, check_entries, check_output_directory

EXAMPLE = "harness paper -o paper/"


def add(sub, describe):
    p = describe(sub, "paper", "the paper's figure set: Psi2*, Omega*, e_t against Psi1* per law at its e_n, contact "
                               "duration and peak force against e_n, where each law slides throughout", EXAMPLE)
    p.add_argument("--laws", default=None, metavar="LIST", help="comma-separated laws (default: every law)")
    p.add_argument("--steps-per-contact", type=int, default=2000, metavar="N", help="resolution (default 2000)")
    p.add_argument("-o", "--output", default="harness-paper", metavar="DIR", help="output directory (default %(default)s)")
    add_output_options(p)
    p.set_defaults(func=main)


def main(args):
    """The paper's figure set: paper.csv, paper-normal.csv, paper-sliding.csv, paper-published.csv and paper.html
    in DIR."""
    laws = tuple(LAWS) if args.laws is None else tuple(n.strip() for n in args.laws.split(",") if n.strip())
    unknown = [n for n in laws if n not in LAWS]
    if unknown or not laws:
        raise UserError(f"unknown law(s) {', '.join(unknown) or args.laws!r}; known: {', '.join(LAWS)}")
    if args.steps_per_contact < 100:
        raise UserError(f"--steps-per-contact must be >= 100 for the paper's figures, got {args.steps_per_contact}")
    if args.steps_per_contact > MAX_STEPS_PER_CONTACT:
        raise UserError(f"--steps-per-contact must be at most {MAX_STEPS_PER_CONTACT:.0e} (the bound of every "
                        f"resolution), got {args.steps_per_contact}")
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
        print(text_table(sliding, ["model", "e_n_target", "simulated", "derived", "difference"],
                         {"simulated": "{:.4f}", "derived": "{:.4f}", "difference": "{:+.1e}"}))
        if not published.empty:
            print(published_summary(published))
    print(f"wrote {path}")
    return EXIT_OK

