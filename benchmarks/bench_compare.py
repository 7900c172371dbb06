"""The quick start's comparison (hertz-mindlin, the paper's scene, every engine) two ways, side by side in one run:
serial (one engine process per e_n batch, one after another, the measurements after the runs, the report's figures
one after another) and as `harness compare` runs it (each engine's batches in one process, engines side by side,
the measurements beside the runs, the figures drawn in parallel). Goal: at least 3x faster. Both warm (compiled).

    .venv/bin/python benchmarks/bench_compare.py [--smoke]
"""
import os
import sys
import tempfile
import time

from harness.analyses.precision import precision_gap
from harness.api import compare_request, measurements, statuses
from harness.comparison import Comparison
from harness.engines import ENGINES
from harness.outputs import save_comparison
from harness.plan import compare_plan
from harness.request import Request
from harness.results import write_csv
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
    attributions, sliding, histories = measurements(law, scene, engines, request.resolution)
    precision = None
    for engine, options in engines.items():
        if hasattr(engine, "precision_runs") and options.get("precision", "double") == "double":
            checks = [engine.run([run])[0][0] for run in engine.precision_runs(law, scene)]
            precision = precision_gap(*checks, engine.NAME, "mpfr150") if checks else None
    import pandas as pd
    comparison = Comparison(law, scene, pd.concat(frames, ignore_index=True), failures=failures,
                            attribution=attributions, sliding=sliding, histories=histories, precision=precision)
    threads, drawing.THREADS = drawing.THREADS, 1
    try:
        write_report(comparison, out_dir)
    finally:
        drawing.THREADS = threads
    return comparison


def write_report(comparison, out_dir):
    write_csv(comparison.results, os.path.join(out_dir, "results.csv"))
    save_comparison(out_dir, comparison)
    rebuild(out_dir)


def side_by_side(request, out_dir):
    comparison = compare_request(request)
    write_report(comparison, out_dir)
    return comparison


def main(smoke=False):
    keywords = dict(en=(0.5,), angles=(10.0, 40.0)) if smoke else {}
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
