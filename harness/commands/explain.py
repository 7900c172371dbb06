"""`harness explain ENGINE TEXT`: what a user's own engine input computes (studies/explain.py), printed."""
from ..studies.explain import explain
from ..views.explain_terminal import print_explanation
from .options import EXIT_OK


def main(args):
    keywords = {name: value for name, value in (("angles", args.angles), ("material", args.material),
                                                ("radius", args.radius), ("rho", args.rho), ("speed", args.speed))
                if value is not None}
    print_explanation(explain(args.engine, args.text, run=args.run, **keywords), quiet=args.quiet)
    return EXIT_OK
