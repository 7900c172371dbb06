"""Campaign throughput, side by side in one run: a campaign of engine batches (LIGGGHTS and YADE decks and scripts
of a hertz-mindlin sweep) in this process, then on a Dask LocalCluster of 1 and 2 worker processes (goal: 2 workers
at least 1.7x the in-process executor on 2 cores); its cached rerun against the first run (goal: at least 50x); and
the reference alone through the campaign path, IMPACTS impacts at 1000 steps per contact (goal: 10^6 in under 3
minutes), with the peak memory of this process and its workers.

    .venv/bin/python benchmarks/bench_campaign.py [--smoke] [--impacts N]
"""
import resource
import sys
import tempfile
import time

from harness.studies.campaign.driver import run_campaign
from harness.studies.campaign.executors import InProcess, executor
from harness.studies.campaign.spec import from_dict
from harness.engines import ENGINES


def engine_campaign(smoke):
    engines = [name for name in ("liggghts", "yade") if ENGINES[name].available()]
    return from_dict({"laws": ["hertz-mindlin"], "engines": engines, "e_n": [0.3, 0.5, 0.7, 0.9][:2 if smoke else 4],
                      "angles": list(range(5, 90, 20 if smoke else 5)), "spins": [0.0] if smoke else [0.0, -20.0],
                      "steps_per_contact": [200 if smoke else 1000]}), engines


def timed(campaign, executor, store):
    start = time.perf_counter()
    summary = run_campaign(campaign, store, executor)
    return time.perf_counter() - start, summary


def main(smoke=False, impacts=None):
    campaign, engines = engine_campaign(smoke)
    if not engines:
        print("neither LIGGGHTS nor YADE is installed: no engine batches to measure")
    with tempfile.TemporaryDirectory(prefix="harness-bench-campaign-") as root:
        walls = {}
        walls["in-process"], summary = timed(campaign, InProcess(), f"{root}/a")
        for workers in (1, 2):
            on_dask = executor("dask", workers)                              # the cluster a campaign starts
            try:
                on_dask.client.run(lambda: __import__("harness.solver.kernel"))   # workers start warm
                walls[f"dask, {workers} worker(s)"], _ = timed(campaign, on_dask, f"{root}/w{workers}")
            finally:
                on_dask.close()
        cached, again = timed(campaign, InProcess(), f"{root}/a")
        print(f"campaign of {summary.tasks} tasks ({', '.join(f'{n} {e}' for e, n in summary.per_engine.items())})")
        for name, wall in walls.items():
            print(f"{name:22s} {wall:8.2f} s   RATIO in-process/this {walls['in-process'] / wall:5.2f}")
        print(f"cached rerun           {cached:8.3f} s   ran {again.ran} of {again.tasks}; RATIO first/cached "
              f"{walls['in-process'] / cached:6.1f} (goal >= 50)")

        count = impacts or (2000 if smoke else 1000000)
        angles = [90.0 * (i + 0.5) / count for i in range(count)]
        reference = from_dict({"laws": ["hertz-mindlin"], "engines": ["reference"], "e_n": [0.5], "angles": angles,
                               "steps_per_contact": [1000]})
        wall, done = timed(reference, InProcess(), f"{root}/r")
        peak = max(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss,
                   resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss) / 1024
        print(f"reference through the campaign path: {count} impacts at 1000 steps/contact in {wall:.1f} s "
              f"({done.tasks} tasks) = {wall * 1e6 / count / 60:.2f} min per 10^6 impacts (goal < 3); "
              f"peak memory {peak:.0f} MB")


if __name__ == "__main__":
    arguments = sys.argv[1:]
    size = int(arguments[arguments.index("--impacts") + 1]) if "--impacts" in arguments else None
    main("--smoke" in arguments, size)
