"""`harness calibrate`: the engine inputs that make an engine compute the paper law as nearly as it can on a scene,
confirmed by running the engine; the time step a tolerance needs; tables, the engine's inputs and report.html."""
import os

from ..api import calibrate_request, check_timestep_tolerance
from ..calibration.files import RECORD, TABLES, rendered, save
from ..engines import get_engine
from ..files import write_text
from ..request import Request
from ..views.calibration_html import write_calibration_report
from ..views.terminal import print_calibration
from ..views.figure_files import FIGURES
from ..wording import counted
from .options import EXIT_ENGINE, EXIT_OK, check_entries, check_output_directory, keywords


def main(args):
    request = Request.from_keywords(args.model, engines=[args.engine], tolerances=args.tolerances, **keywords(args))
    engine = get_engine(request.engines[0])
    check_timestep_tolerance(args.timestep_tolerance)
    check_output_directory(args.output)
    check_entries(args.output, [RECORD, "report.html"] + [f"{name}.csv" for name in TABLES], (FIGURES,))
    calibration = calibrate_request(request, engine, timestep_tolerance=args.timestep_tolerance)
    os.makedirs(args.output, exist_ok=True)
    texts = rendered(save(calibration, args.output), engine)
    record_path = os.path.join(args.output, RECORD)
    for name, text in texts:
        write_text(os.path.join(args.output, name), text)
    report = write_calibration_report(calibration, args.output, [name for name, _ in texts])
    if not args.quiet:
        print_calibration(calibration)
    print(f"calibrate: wrote {record_path}, the tables, {counted(len(texts), engine.code + ' input')} and {report}")
    return EXIT_ENGINE if calibration.skipped or calibration.failures else EXIT_OK
