"""`harness report DIR`: rebuild DIR/report.html from the files of a compare or cost directory, simulating nothing."""
from ..views.html import rebuild
from .options import EXIT_OK, add_output_options


def add(sub, describe):
    p = describe(sub, "report", "harness report harness-out")
    p.add_argument("directory", metavar="DIR")
    add_output_options(p)
    p.set_defaults(func=main)


def main(args):
    print(f"wrote {rebuild(args.directory)}")
    return EXIT_OK
