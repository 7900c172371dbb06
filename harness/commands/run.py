"""`harness run`: one law over a scene on the reference solver; a results CSV."""
from ..api import run_request
from ..request import Request
from ..results import write_csv
from .options import EXIT_OK, add_scene_options, check_output_file, keywords

EXAMPLE = "harness run --model thornton --en 0.9,0.5,0.1 --angles 0:80:10 -o results.csv"


def add(sub, describe):
    p = describe(sub, "run", "simulate one law over a scene with the reference solver, write a results CSV", EXAMPLE)
    p.add_argument("--model", required=True, help="law name (see `harness models`)")
    add_scene_options(p)
    p.add_argument("-o", "--output", required=True, help="results CSV to write")
    p.add_argument("--quiet", action="store_true", help="print nothing on success")
    p.set_defaults(func=main)


def main(args):
    request = Request.from_keywords(args.model, **keywords(args))
    check_output_file(args.output)
    frame = run_request(request)
    write_csv(frame, args.output)
    if not args.quiet:
        bad = int((frame.status != "ok").sum())
        print(f"{request.law.name}: {len(frame)} impacts -> {args.output}" + (f" ({bad} not ok)" if bad else ""))
    return EXIT_OK
