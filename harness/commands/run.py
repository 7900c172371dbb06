"""`harness run`: one law over a scene on the reference solver; a results CSV (impact) or a scene's series and
closed-form checks (on the engines asked for too)."""
import os
import sys

from ..infra.errors import UserError
from ..infra.wording import counted
from .options import EXIT_DISAGREE, EXIT_ENGINE, EXIT_OK, check_output_directory, check_output_file, keywords


def main(args):
    if args.scene != "impact":
        return main_scene(args)
    if args.scene_params:
        raise UserError("scene impact takes its own options (--target, --en, --angles, ...), not --scene-param")
    if args.json:
        raise UserError("--json prints a scene's checks: give --scene and a scene other than impact")
    if args.engines is not None or args.engine_options:
        raise UserError("run computes the impact scene on the reference solver: `harness compare --engines ...` runs "
                        "it on engines")
    from ..api.requests import run_request
    from ..runs.request import Request
    from ..data.results import write_csv
    from ..data.states import carried
    from ..infra.files import write_text
    from ..views.terminal import states_text
    from ..views.progress import Progress
    request = Request.from_keywords(args.model, **keywords(args))
    check_output_file(args.output)
    with Progress(f"run {request.model}", quiet=args.quiet) as progress:
        frame = run_request(request, progress=progress)
    states = carried(frame)
    write_csv(frame, args.output)
    written = args.output
    if states is not None:
        written += " and " + write_text(states_path(args.output), states.to_csv(index=False))
        if not args.quiet:
            print(states_text(states, os.path.basename(states_path(args.output))))
    bad = int((frame.status != "ok").sum())
    print(f"{request.law.name}: {counted(len(frame), 'impact')} -> {written}" + (f" ({bad} not ok)" if bad else ""))
    return EXIT_OK


def states_path(output):
    """Where `run -o FILE` writes the states: FILE's name less its .csv, then -states.csv, beside it."""
    root, extension = os.path.splitext(output)
    return (root if extension.lower() == ".csv" else output) + "-states.csv"


def main_scene(args):
    """A scene other than impact: series.csv and checks.csv in the output directory, one line per check."""
    from ..api.scene_requests import parameters_from_text, runnable_kind, scene_request
    from ..studies.scene_files import write_scene
    from ..studies.scenes import run_scene
    from ..views.scene_html import write_scene_report
    from ..views.scene_terminal import check_lines, checks_json
    from .compare import command_line
    kind = runnable_kind(args.scene)
    request, kind, values = scene_request(args.model, args.scene, parameters_from_text(kind, args.scene_params),
                                          **keywords(args))
    check_output_directory(args.output)
    run = run_scene(request.law, kind, values, request.scene, request.resolution, request.engines,
                    request.engine_options, request.overrides)
    write_scene(args.output, run, command_line())
    write_scene_report(args.output, run, command_line())
    failed = int((~run.checks.passed).sum())
    for name, reason in run.unavailable.items():
        print(f"{name} skipped: {reason}", file=sys.stderr)
    if args.json:
        print(checks_json(run))
    else:
        for line in check_lines(run):
            if not args.quiet:
                print(line)
        print(f"{request.law.name} on scene {kind.NAME}: {len(run.checks) - failed} of "
              f"{counted(len(run.checks), 'check')} passed -> {args.output}")
    return EXIT_DISAGREE if failed else EXIT_ENGINE if run.unavailable else EXIT_OK
