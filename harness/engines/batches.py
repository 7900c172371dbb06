"""One run of the plan through an external engine as result rows (a failed batch keeps its log); an engine learns
what to run from the run's spec (RunSpec)."""
import os
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass

import numpy as np

from ..data.results import impact_frame
from ..data.states import attach, states_frame
from ..solver.threads import THREADS
from .runner import EngineFailure, read_tail, run_engine, scratch

TIMEOUT_FLOOR_S = 120.0
SECONDS_PER_ATOM_STEP = 2e-6        # generous: 30x what LIGGGHTS needs here


@dataclass
class FailedRun:
    """One engine batch that produced nothing usable, with the log tail for the report."""
    engine: str
    e_n: float
    message: str
    log_tail: str


OBSERVED = ("t_contact", "f_n_max", "overlap_max")


def stepping_s(spec):
    return SECONDS_PER_ATOM_STEP * spec.impacts * spec.step_cap


def identity_of(engine, build, run):
    """The identity columns of a run's rows: its law and dialect, the engine build that ran it (Engine.build)."""
    spec = run.spec
    return dict(model=run.law.name, dialect=run.dialect.dialect, engine=engine, engine_version=build["version"],
                engine_binary=build["binary"], engine_sha256=build["sha256"], dt=spec.dt,
                steps_per_contact=spec.steps_per_contact)


def failed_rows(engine, build, run, failure):
    """'failed' rows of a run that produced nothing, carrying its one-line message, and its FailedRun."""
    spec = run.spec
    nan = np.full(spec.impacts, np.nan)
    frame = impact_frame(run.scene, spec, **identity_of(engine, build, run), v_n1=nan, v_t1=nan, omega1=nan,
                         wall_s=np.nan, status="failed", message=str(failure))
    return frame, FailedRun(engine, spec.e_n, str(failure), failure.log_tail)


def result_rows(engine, build, run, final, wall):
    """The rows of a run that finished: each impact's rebound, whether it separated, its share of the wall time; an
    impact whose state is not a number is `non-finite`, with the reason where its dialect predicts it."""
    spec = run.spec
    observed = {name: final[name] for name in OBSERVED if run.observe}
    finite = final.get("finite", np.ones(spec.impacts, dtype=bool))
    reason = run.dialect.undefined(run.scene.contact, spec.e_n, run.scene.speed) if not finite.all() else ""
    why = (f"non-finite, as its formulas predict: {reason}" if reason else
           "non-finite: the engine returned values that are not numbers, which its formulas do not predict")
    frame = impact_frame(run.scene, spec, **identity_of(engine, build, run), v_n1=final["v_n1"],
                         v_t1=final["v_t1"], omega1=final["omega1"], wall_s=wall / spec.impacts,
                         status=np.where(~finite, "non-finite", np.where(final["separated"], "ok", "no-separation")),
                         message=np.where(finite, "", why), **observed)
    return attach(frame, states_frame(frame, final["states"]) if run.scene.at_times and "states" in final else None)


def run_grouped(engine, build, runs, input_name, render, group_of, run_inputs, read, deadline=None):
    """Each run as (results frame, FailedRun or None). The runs of one group (group_of(run): e.g. the flavour) share
    engine processes, one per core at most, each batch in its own directory batch<k> of the process's temporary
    directory with its input in `input_name`; the processes run side by side. render(run) -> its input text (an
    EngineFailure refuses that run alone); run_inputs(group, n, timeout, workdir) runs the n inputs and returns each
    batch's wall seconds (an EngineFailure fails the process: its batches are then run one per process, so that each
    failure is its own); read(run, directory) -> its final state; each learns what it runs from run.spec. The engine's
    deadline: after its first timeout, its batches not yet finished are skipped with the reason (a hung engine costs
    one timeout, not one per batch)."""
    out, groups = [None] * len(runs), {}
    deadline = deadline if deadline is not None else []         # the first timeout of this engine, once it happens
    for i, run in enumerate(runs):
        try:
            text = render(run)
        except EngineFailure as exc:
            out[i] = failed_rows(engine, build, run, exc)
            continue
        groups.setdefault(group_of(run), []).append((i, run, text))
    shares = [(group, items[k::processes]) for group, items in groups.items()
              for processes in [min(THREADS, len(items))] for k in range(processes)]

    def skipped(items):
        for i, run, _ in items:
            out[i] = failed_rows(engine, build, run, EngineFailure(
                f"skipped: an earlier {engine} run timed out ({deadline[0]})", deadline[0].log_tail))

    def one_process(group, items):
        if deadline:
            return skipped(items)
        with scratch(engine) as workdir:
            for k, (_, _, text) in enumerate(items):
                os.makedirs(os.path.join(workdir, f"batch{k}"))
                with open(os.path.join(workdir, f"batch{k}", input_name), "w") as handle:
                    handle.write(text)
            timeout = TIMEOUT_FLOOR_S + sum(stepping_s(run.spec) for _, run, _ in items)
            try:
                walls = run_inputs(group, len(items), timeout, workdir)
            except EngineFailure as exc:
                if exc.timed_out:            # every batch of this process shares the timeout; later ones skip
                    deadline.append(exc)
                    for i, run, _ in items:
                        out[i] = failed_rows(engine, build, run, exc)
                    return
                if len(items) > 1:           # one process per batch, so that the failure names its batch
                    for i, run, _ in items:
                        out[i] = run_grouped(engine, build, [run], input_name, render, group_of, run_inputs,
                                             read, deadline)[0]
                    return
                walls = [exc]
            for k, ((i, run, _), wall) in enumerate(zip(items, walls)):
                try:
                    if isinstance(wall, EngineFailure):
                        raise wall
                    final = read(run, os.path.join(workdir, f"batch{k}"))
                    out[i] = (result_rows(engine, build, run, final, wall), None)
                except EngineFailure as exc:        # every failure carries the log of the process that ran it
                    out[i] = failed_rows(engine, build, run, EngineFailure(
                        str(exc), exc.log_tail or read_tail(os.path.join(workdir, "engine.log"))))
    if len(shares) == 1:
        one_process(*shares[0])
    elif shares:
        with ThreadPoolExecutor(max_workers=len(shares)) as pool:
            for future in [pool.submit(one_process, group, items) for group, items in shares]:
                future.result()
    return out


def in_one_process(argv, input_name, count, timeout_s, workdir, env=None):
    """The inputs batch<k>/input_name (k < count) of workdir in one process of an engine that reads `-in in.driver`
    (argv): one start-up, `clear` between them, each writing into its own directory; each batch's share of the
    wall seconds."""
    lines = []
    for k in range(count):
        lines += [f"shell cd batch{k}", f"include {input_name}", "clear", "shell cd .."]
    with open(os.path.join(workdir, "in.driver"), "w") as handle:
        handle.write("\n".join(lines) + "\n")
    done = run_engine(argv[:1] + ["-in", "in.driver"] + argv[1:], workdir, timeout_s, env=env)
    return [done.wall_s / count] * count
