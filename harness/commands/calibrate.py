"""`harness calibrate`: the engine inputs that make an engine compute the paper law as nearly as it can on a scene,
confirmed by running the engine; the time step a tolerance needs; tables, the engine's inputs and report.html."""
import os
import sys

from ..api.requests import calibrate_request, check_timestep_tolerance
from ..studies.calibration.files import RECORD, TABLES, save, summary
from ..infra.files import write_text
from ..runs.request import Request
from ..infra import strict_json
from ..views.calibration_html import write_calibration_report
from ..views.calibration_terminal import print_calibration, print_not_run
from ..views.figure_files import FIGURES
from ..infra.wording import counted
from .options import EXIT_ENGINE, EXIT_OK, check_entries, check_output_directory, keywords


def main(args):
    """Refuse what cannot be calibrated (exit 2, nothing written), calibrate, write the files; exit 3 with the reason
    on stderr when the engine did not run or a run of it failed."""
    request = Request.from_keywords(args.model, engines=[args.engine], tolerances=args.tolerances, **keywords(args))
    check_timestep_tolerance(args.timestep_tolerance)
    check_output_directory(args.output)
    check_entries(args.output, [RECORD, "report.html"] + [f"{name}.csv" for name in TABLES], (FIGURES,))
    calibration = calibrate_request(request, timestep_tolerance=args.timestep_tolerance)
    os.makedirs(args.output, exist_ok=True)
    save(calibration, args.output)
    for typed in calibration.typed:
        write_text(os.path.join(args.output, typed.file), typed.text)
    report = write_calibration_report(calibration, args.output, [typed.file for typed in calibration.typed])
    code = EXIT_ENGINE if calibration.skipped or calibration.failures else EXIT_OK
    print_not_run(calibration, file=sys.stderr)
    record_path = os.path.join(args.output, RECORD)
    if args.json:
        files = {"calibration": record_path, "report": report,
                 "inputs": [os.path.join(args.output, typed.file) for typed in calibration.typed],
                 **{name: os.path.join(args.output, f"{name}.csv") for name in TABLES}}
        print(strict_json.dumps(summary(calibration, files, code), indent=1))
        return code
    if not args.quiet:
        print_calibration(calibration)
    inputs = counted(len(calibration.typed), calibration.engine + " input")
    print(f"calibrate: wrote {record_path}, the tables, {inputs} and {report}")
    return code
