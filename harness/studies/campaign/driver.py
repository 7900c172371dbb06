"""Running a campaign: expand it into tasks, leave out what the store already holds, run the rest on an executor,
store each task as it finishes, compact the store; and the dry run's counts and estimates."""
import os
from collections import Counter
from dataclasses import dataclass, field

from ...engines import ENGINES
from ...engines.runner import sweep_stale
from ...runs.keys import run_key
from .spec import tasks
from .store import Store


@dataclass
class Summary:
    """What a campaign run did: tasks in the matrix, run now, taken from the store, failed; engines skipped."""
    tasks: int
    ran: int = 0
    cached: int = 0
    failed: int = 0
    skipped: list = field(default_factory=list)
    per_engine: dict = field(default_factory=dict)

    def as_dict(self):
        return {"tasks": self.tasks, "ran": self.ran, "cached": self.cached, "failed": self.failed,
                "skipped": [{"engine": e, "reason": r} for e, r in self.skipped], "per_engine": self.per_engine}


def keyed(campaign):
    """({key: run} of the campaign's distinct tasks, skipped engines)."""
    runs, skipped = tasks(campaign)
    out = {}
    for run in runs:
        out.setdefault(run_key(run), run)
    return out, skipped


def estimate_s(run):
    """Rough wall seconds of one task (the dry run's estimate)."""
    spec = run.spec if run.resolution != "converged" else None
    impacts = spec.impacts if spec is not None else 1
    steps = (spec.step_cap if run.engine != "reference" else 1.2 * spec.steps_per_contact) if spec else 5e3
    return ENGINES[run.engine].campaign_seconds(impacts, steps)


def opened(store):
    """A Store, or the store at a path (made if missing)."""
    return store if isinstance(store, Store) else Store(store)


def dry_run(campaign, store, no_cache=False):
    """Summary of what a run would do, with per engine its tasks, cached tasks and estimated seconds; `store` is
    a Store, a path (read, never made) or None."""
    runs, skipped = keyed(campaign)
    if store is not None and not isinstance(store, Store):
        store = Store(store, create=False) if os.path.isdir(store) else None
    done = set() if no_cache or store is None else store.finished()
    per = {}
    for key, run in runs.items():
        entry = per.setdefault(run.engine, {"tasks": 0, "cached": 0, "estimated_s": 0.0})
        entry["tasks"] += 1
        if key in done:
            entry["cached"] += 1
        else:
            entry["estimated_s"] += estimate_s(run)
    cached = sum(e["cached"] for e in per.values())
    return Summary(len(runs), 0, cached, 0, skipped, per)


def run_campaign(campaign, store, executor, no_cache=False, progress=None):
    """Run the tasks the store (a Store or a path) lacks on `executor`, storing each as it finishes; compact the
    store at the end."""
    runs, skipped = keyed(campaign)
    store = opened(store)
    done = set() if no_cache else store.finished()
    todo = [(key, run) for key, run in runs.items() if key not in done]
    summary = Summary(len(runs), len(todo), len(runs) - len(todo), 0, skipped,
                      dict(Counter(run.engine for _, run in todo)))
    if progress:
        progress.expect(len(todo))

    def on_done(i, frame, log_tail):
        key, run = todo[i]
        store.put(key, frame, log_tail, run.scene)
        if (frame.status == "failed").any():
            summary.failed += 1
        if progress:
            progress.advance(f"{run.engine} {run.law.name} ({run.dialect.dialect} formulas) e_n {run.e_n:g}")
    try:
        executor.map([run for _, run in todo], [key for key, _ in todo], on_done)
    finally:
        sweep_stale()                    # a worker killed mid-task leaves its engine's directories: remove them
    store.compact()
    return summary
