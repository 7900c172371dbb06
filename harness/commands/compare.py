"""`harness compare`: the paper law, each engine's dialect and each engine on one scene; tables, CSVs, report."""
import os

import pandas as pd

from ..api import compare_request
from ..outputs import save_comparison
from ..request import Request
from ..results import write_csv
from ..views.html import rebuild
from ..views.terminal import print_comparison
from .options import (EXIT_DISAGREE, EXIT_ENGINE, EXIT_OK, add_engine_options, add_scene_options,
                      check_output_directory, keywords)

EXAMPLE = "harness compare --model hertz-mindlin --engines liggghts --en 0.5 -o out/"


def add(sub, describe):
    p = describe(sub, "compare", "the paper law against each engine and its dialect; tables, results.csv, report.html",
                 EXAMPLE)
    p.add_argument("--model", required=True, help="law name (see `harness models`)")
    add_engine_options(p)
    add_scene_options(p)
    p.add_argument("-o", "--output", default="harness-out", metavar="DIR", help="output directory (default %(default)s)")
    p.add_argument("--quiet", action="store_true", help="print only the verdict")
    p.set_defaults(func=main)


def main(args):
    """Write DIR/results.csv (after every batch), the other tables and report.html; the exit code is the verdict."""
    request = Request.from_keywords(args.model, **keywords(args))
    check_output_directory(args.output)
    results_path = os.path.join(args.output, "results.csv")
    frames = []

    def keep(frame):                       # the directory appears with the first results, never for refused input
        frames.append(frame)
        os.makedirs(args.output, exist_ok=True)
        write_csv(pd.concat(frames, ignore_index=True), results_path)

    comparison = compare_request(request, on_frame=keep)
    os.makedirs(args.output, exist_ok=True)
    save_comparison(args.output, comparison)
    report = rebuild(args.output)
    if not args.quiet:
        print_comparison(comparison, [results_path, report])
    if comparison.unavailable:
        print(f"agreement: not checked for {', '.join(comparison.unavailable)}, asked for by name")
        return EXIT_ENGINE
    print("agreement: " + ("no engine compared" if not comparison.compared else "ok" if comparison.ok else "FAILED"))
    return EXIT_OK if comparison.ok else EXIT_DISAGREE
