"""`harness run`: one law over a scene on the reference solver; a results CSV."""
from ..infra.wording import counted
from .options import EXIT_OK, check_output_file, keywords


def main(args):
    from ..api.requests import run_request
    from ..runs.request import Request
    from ..data.results import write_csv
    from ..views.progress import Progress
    request = Request.from_keywords(args.model, **keywords(args))
    check_output_file(args.output)
    with Progress(f"run {request.model}", quiet=args.quiet) as progress:
        frame = run_request(request, progress=progress)
    write_csv(frame, args.output)
    bad = int((frame.status != "ok").sum())
    print(f"{request.law.name}: {counted(len(frame), 'impact')} -> {args.output}" + (f" ({bad} not ok)" if bad else ""))
    return EXIT_OK
