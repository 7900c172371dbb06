"""The command line: one thin module per command; bad input ends in one line on stderr and exit code 2."""
import argparse
import sys

from ..errors import UserError
from ..version import __version__
from .options import EXIT_CODES, EXIT_INTERNAL, EXIT_INTERRUPTED, EXIT_USAGE, Parser


def describe(sub, name, summary, example):
    """A sub-command whose --help carries its summary, an example and the exit codes."""
    return sub.add_parser(name, help=summary, description=summary[0].upper() + summary[1:] + ".",
                          epilog=f"example:\n  {example}\n\n{EXIT_CODES}",
                          formatter_class=argparse.RawDescriptionHelpFormatter)


def build_parser():
    from . import check, compare, cost, models, paper, render, report, run
    parser = Parser(prog="harness", formatter_class=argparse.RawDescriptionHelpFormatter,
                    description="Cross-validate DEM contact force models against the literature (Thornton, Cummins "
                                "& Cleary 2013) and against LIGGGHTS and YADE.",
                    epilog=f"example:\n  harness compare --model hertz-mindlin\n\n{EXIT_CODES}")
    parser.add_argument("--version", action="version", version=f"harness {__version__}")
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND", parser_class=Parser)
    for module in (models, run, compare, cost, paper, render, report, check):
        module.add(sub, describe)
    return parser


def show_log(quiet):
    """harness' log (what it is doing that takes time, e.g. compiling) as `harness: ...` lines on stderr."""
    import logging
    log = logging.getLogger("harness")
    if not log.handlers:
        handler = logging.StreamHandler(sys.stderr)
        handler.setFormatter(logging.Formatter("harness: %(message)s"))
        log.addHandler(handler)
        log.propagate = False
    log.setLevel(logging.WARNING if quiet else logging.INFO)


def main(argv=None):
    """Parse, run one command, return its exit code; a user's mistake is one line and 2, Ctrl-C is 130."""
    try:
        args = build_parser().parse_args(argv)
        show_log(quiet=getattr(args, "quiet", False))
        return args.func(args)
    except UserError as exc:
        print(f"harness: error: {exc}", file=sys.stderr)
        return EXIT_USAGE
    except KeyboardInterrupt:
        print("harness: interrupted; finished results were kept", file=sys.stderr)
        return EXIT_INTERRUPTED
    except Exception:                                   # a bug of harness: never exit 1, which means disagreement
        import traceback
        traceback.print_exc()
        print(f"harness: internal error (exit {EXIT_INTERNAL}); please report it with the traceback above",
              file=sys.stderr)
        return EXIT_INTERNAL
