"""`harness run`: one law over a scene on the reference solver; a results CSV."""
from .options import EXIT_OK, add_output_options, add_scene_options, check_output_file, keywords

EXAMPLE = "harness run --model thornton --en 0.9,0.5,0.1 --angles 0:80:10 -o results.csv"


def add(sub, describe):
    p = describe(sub, "run", EXAMPLE)
    p.add_argument("--model", required=True, help="law name (see `harness models`)")
    add_scene_options(p)
    p.add_argument("-o", "--output", required=True, help="results CSV to write")
    add_output_options(p)
    p.set_defaults(func=main)


def main(args):
    from ..laws import get_law
    get_law(args.model)             # an unknown law is refused before the solver loads
    from ..api import run_request
    from ..request import Request
    from ..results import write_csv
    from ..views.progress import Progress
    request = Request.from_keywords(args.model, **keywords(args))
    check_output_file(args.output)
    with Progress(f"run {request.model}", quiet=args.quiet) as progress:
        frame = run_request(request, progress=progress)
    write_csv(frame, args.output)
    bad = int((frame.status != "ok").sum())
    print(f"{request.law.name}: {len(frame)} impacts -> {args.output}" + (f" ({bad} not ok)" if bad else ""))
    return EXIT_OK
