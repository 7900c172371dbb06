"""The quick start's comparison (hertz-mindlin, the paper's scene, every engine) two ways, side by side in one run:
serial, as issue 15 found it (one engine process per e_n batch, one after another, the measurements after the runs,
YADE's precision checked on three impacts of the first e_n at the comparison's own resolution, in double and at 150
bits, the report's figures one after another) and as
`harness compare` runs it (each engine's batches in one process, engines side by side, the measurements beside the
runs, the precision checked on two impacts at a coarse step, the figures drawn in parallel). Goal: at least 3x
faster. Both warm (compiled).

    .venv/bin/python benchmarks/bench_compare.py [--smoke]

--smoke: one e_n and two angles, LIGGGHTS and YADE alone (YADE for its precision check).
"""
import os
import sys
import tempfile
import time
from dataclasses import replace

import numpy as np
import pandas as pd

from harness.analyses.precision import precision_gap
from harness.api.requests import compare_request, measurements
from harness.runs.availability import statuses
from harness.runs.comparison import Comparison
from harness.engines import ENGINES
from harness.engines.yade.dialect import dialect as yade_dialect
from harness.engines.yade.precision import HIGH, available
from harness.engines.run import Run
from harness.runs.outputs import save_comparison
from harness.runs.plan import compare_plan
from harness.runs.request import Request
from harness.data.results import write_csv
from harness.views import drawing
from harness.views.html import rebuild


def serial(request, out_dir):
    """Every batch in its own engine process, one after another; then the measurements; then the report."""
    law, scene = request.law, request.scene
    engines = {ENGINES[s.name]: request.engine_options.get(s.name, {}) for s in statuses(request) if s.available}
    frames, failures = [], []
    for run in compare_plan(law, scene, request.resolution, engines, request.resolution):
        frame, failure = ENGINES[run.engine].run([run])[0]
        frames.append(frame)
        failures += [failure] if failure else []
    attributions, rows, sliding, histories = measurements(law, scene, engines, request.resolution, request.tolerances)
    precision = None
    yade = ENGINES["yade"]
    if yade in engines and engines[yade].get("precision", "double") == "double" and available(HIGH):
        precision = issue_precision_check(law, scene, request.resolution)
    comparison = Comparison(law, scene, pd.concat(frames, ignore_index=True), failures=failures,
                            attribution=attributions, attribution_rows=rows, sliding=sliding, histories=histories,
                            precision=precision, tolerances=request.tolerances)
    threads, drawing.CORES = drawing.CORES, 1
    try:
        write_report(comparison, out_dir)
    finally:
        drawing.CORES = threads
    return comparison


def issue_precision_check(law, scene, resolution, samples=3):
    """YADE's precision check as the issue found it: `samples` impacts spread over the first e_n's angles, at the
    comparison's resolution, in double and at 150 bits."""
    angles = np.asarray(scene.impacts(scene.e_n[0])[3])
    picked = tuple(float(a) for a in np.unique(angles[np.linspace(0, len(angles) - 1, samples).round().astype(int)]))
    held = "normal" if scene.angles_deg is None else scene.speed_is
    sample = replace(scene, e_n=scene.e_n[:1], angles_deg=picked, psi1_star=None, v_t=None, speed_is=held)
    frames = [ENGINES["yade"].run([Run("yade", law, yade_dialect(law.name, {"precision": flavour}), sample, resolution,
                                       (("precision", flavour),))])[0][0] for flavour in ("double", HIGH)]
    return precision_gap(*frames, "yade", HIGH)


def write_report(comparison, out_dir):
    write_csv(comparison.results, os.path.join(out_dir, "results.csv"))
    save_comparison(out_dir, comparison)
    rebuild(out_dir)


def side_by_side(request, out_dir):
    comparison = compare_request(request)
    write_report(comparison, out_dir)
    return comparison


def main(smoke=False):
    keywords = dict(en=(0.5,), angles=(10.0, 40.0), engines=["liggghts", "yade"]) if smoke else {}
    request = Request.from_keywords("hertz-mindlin", **keywords)
    with tempfile.TemporaryDirectory(prefix="harness-bench-") as warm:
        side_by_side(request, warm)                   # compile, load the engines' files into the page cache
    times = {}
    for name, path in (("serial", serial), ("harness compare", side_by_side)):
        with tempfile.TemporaryDirectory(prefix="harness-bench-") as out_dir:
            start = time.perf_counter()
            comparison = path(request, out_dir)
            times[name] = time.perf_counter() - start
        engines = ", ".join(e for e in comparison.results.engine.unique() if e != "reference") or "no engine"
        print(f"{name:16s} {times[name]:7.2f} s  ({len(comparison.results)} rows; engines: {engines})")
    print(f"RATIO serial / harness compare: {times['serial'] / times['harness compare']:.2f} (goal >= 3)")


if __name__ == "__main__":
    main("--smoke" in sys.argv[1:])
