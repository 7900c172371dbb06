"""`harness render`: an engine's input deck or script for every e_n of the scene, without running it."""
import os

from ..runs.availability import options_for
from ..studies.calibration.files import read, rendered
from ..engines import get_engine
from ..infra.errors import UserError
from ..infra.files import write_text
from ..runs.plan import engine_runs
from ..runs.request import Request
from ..infra.wording import counted
from .options import EXIT_OK, check_entries, check_output_directory, keywords


def main(args):
    if args.calibration:
        return from_calibration(args)
    if not (args.model and args.engine):
        raise UserError("render needs --model and --engine, or --calibration FILE")
    engine = get_engine(args.engine)
    request = Request.from_keywords(args.model, engines=[args.engine], engine_options=args.engine_options,
                                    **keywords(args))
    if not engine.supports(request.law.name):
        raise UserError(f"{args.engine} has no counterpart of {request.law.name}")
    check_output_directory(args.output)
    texts = [engine.render(run) for run in engine_runs(engine, request.law, request.scene, request.resolution,
                                                       options_for(request, engine.NAME))]
    return write_inputs(args, texts, engine.NAME)


def write_inputs(args, texts, engine):
    """Write each (name, text) into -o DIR, every entry checked before any is written."""
    check_entries(args.output, [name for name, _ in texts])
    os.makedirs(args.output, exist_ok=True)
    for name, text in texts:
        write_text(os.path.join(args.output, name), text)
    if not args.quiet:
        print("\n".join(os.path.join(args.output, name) for name, _ in texts))
    print(f"wrote {counted(len(texts), engine + ' input')} to {args.output}")
    return EXIT_OK


def from_calibration(args):
    """The engine's inputs at the values a calibration found (harness.studies.calibration.files.rendered)."""
    if args.model or args.engine:
        raise UserError("--calibration takes its law and engine from the file: give neither --model nor --engine")
    record = read(args.calibration)
    engine = get_engine(str(record["engine"]))
    check_output_directory(args.output)
    texts = rendered(record, engine)
    return write_inputs(args, texts, engine.code)
