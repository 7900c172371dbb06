"""`harness explain ENGINE TEXT`: what a user's own engine input computes (studies/explain.py), printed."""
import json

from ..studies.explain import explain
from ..views.explain_terminal import explanation_record, print_explanation
from .options import EXIT_OK


def main(args):
    keywords = {name: value for name, value in (("angles", args.angles), ("material", args.material),
                                                ("radius", args.radius), ("rho", args.rho), ("speed", args.speed))
                if value is not None}
    explanation = explain(args.engine, args.text, run=args.run, **keywords)
    if args.json:
        print(json.dumps(explanation_record(explanation)))
    else:
        print_explanation(explanation, quiet=args.quiet)
    return EXIT_OK
