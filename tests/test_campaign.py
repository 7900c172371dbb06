"""Campaigns: the TOML matrix expands into compare's plan; the Parquet store keeps each task once and a rerun runs
only what is missing; Dask worker processes give the in-process results bit for bit, also when a worker is killed
mid-run; an interrupted campaign resumes; the SLURM job script carries the options given."""
import os
import signal
import sys
from pathlib import Path

import pandas as pd
import pytest

from conftest import interruptible, needs
from harness.studies.campaign.driver import dry_run, keyed, run_campaign
from harness.studies.campaign.executors import InProcess, executor
from harness.studies.campaign.slurm import forget_credentials, slurm_cluster
from harness.studies.campaign.spec import from_dict, load
from harness.studies.campaign.store import KEY, Store
from harness.commands import main
from harness.infra.errors import UserError
from harness.runs.plan import compare_plan

SMALL = dict(laws=["hertz-mindlin", "thornton"], e_n=[0.5, 0.9], angles=[10, 50, 85], steps_per_contact=[500])
METRICS = ["v_n1", "v_t1", "omega1", "e_n", "e_t", "omega_star"]


def sorted_rows(table):
    return table.sort_values([KEY, "theta_deg"]).reset_index(drop=True)


def test_a_campaign_expands_into_the_plan_compare_runs():
    campaign = from_dict({**SMALL, "engines": ["reference"], "spins": [0.0, -20.0]})
    runs, skipped = keyed(campaign)
    expected = sum(len(compare_plan(r.law, r.scene, r.resolution, {})) for r in campaign.requests)
    assert len(campaign.requests) == 4 and len(runs) == expected == 8 and skipped == []
    assert {run.engine for run in runs.values()} == {"reference"}


def test_reference_blocks_split_a_long_sweep():
    campaign = from_dict({**SMALL, "laws": ["thornton"], "engines": ["reference"], "angles": list(range(0, 89)),
                          "block": 20})
    runs, _ = keyed(campaign)
    assert len(runs) == 2 * 5                    # 89 angles in blocks of 20, per e_n
    assert sum(len(run.scene.angles_deg) for run in runs.values()) == 2 * 89


@pytest.mark.parametrize("text, message", [("laws = [", "not valid TOML"), ("lawz = ['thornton']", "unknown key"),
                                           ("laws = ['nope']", "unknown law"), ("e_n = [0.5]", "give laws"),
                                           ("laws = ['thornton']\nangles = [10]\npsi = [1]", "one of angles"),
                                           ("laws = ['thornton']\ne_n = [2]", "e_n must lie")])
def test_a_bad_campaign_file_is_one_line(tmp_path, capfd, text, message):
    path = tmp_path / "c.toml"
    path.write_text(text)
    with pytest.raises(UserError, match=message):
        load(path)
    assert main(["campaign", str(path), "-o", str(tmp_path / "store")]) == 2
    assert len(capfd.readouterr().err.strip().splitlines()) == 1 and not (tmp_path / "store").exists()


def test_the_store_reads_as_one_table_and_a_rerun_runs_nothing(tmp_path):
    campaign = from_dict({**SMALL, "engines": ["reference"]})
    first = run_campaign(campaign, tmp_path / "s", InProcess())
    assert (first.tasks, first.ran, first.cached, first.failed) == (4, 4, 0, 0)
    table = pd.read_parquet(tmp_path / "s")                         # pandas alone, as the README says
    assert len(table) == 4 * 3 and table[KEY].nunique() == 4 and set(table.status) == {"ok"}
    again = run_campaign(campaign, tmp_path / "s", InProcess())
    assert (again.ran, again.cached) == (0, 4)
    forced = run_campaign(campaign, tmp_path / "s", InProcess(), no_cache=True)
    assert forced.ran == 4 and len(Store(tmp_path / "s").table()) == 12
    assert dry_run(campaign, tmp_path / "s").cached == 4


class StopAfter:
    """A progress that interrupts the driver after `n` tasks (as Ctrl-C would)."""

    def __init__(self, n):
        self.n = n

    def expect(self, steps):
        pass

    def advance(self, what):
        self.n -= 1
        if self.n == 0:
            raise KeyboardInterrupt


def test_an_interrupted_campaign_resumes_with_only_the_missing_tasks(tmp_path):
    campaign = from_dict({**SMALL, "engines": ["reference"], "spins": [0.0, 10.0]})
    with pytest.raises(KeyboardInterrupt):
        run_campaign(campaign, tmp_path / "s", InProcess(), progress=StopAfter(3))
    assert not [n for n in os.listdir(tmp_path / "s") if n.endswith(".tmp")]       # only whole fragments
    resumed = run_campaign(campaign, tmp_path / "s", InProcess())
    assert (resumed.tasks, resumed.ran, resumed.cached) == (8, 5, 3)
    whole = run_campaign(campaign, tmp_path / "t", InProcess())
    a, b = sorted_rows(Store(tmp_path / "s").table()), sorted_rows(Store(tmp_path / "t").table())
    assert whole.ran == 8 and a[METRICS].equals(b[METRICS])


def test_a_changed_law_or_engine_build_changes_the_key():
    campaign = from_dict({**SMALL, "laws": ["hertz-mindlin"], "engines": ["reference"]})
    other = from_dict({**SMALL, "variants": [{"law": "hertz-mindlin", "with": {"tangential": "mindlin:incremental"}}],
                       "laws": [], "engines": ["reference"]})
    run = next(iter(keyed(campaign)[0].values()))
    assert not set(keyed(campaign)[0]) & set(keyed(other)[0])
    assert run.key("0.1.0") != run.key("0.1.1")


@needs("liggghts")
@needs("yade")
def test_a_variant_replacing_a_sub_model_reaches_the_engine_inputs_or_skips_the_engine():
    campaign = from_dict({**SMALL, "laws": ["hertz-mindlin"], "engines": ["liggghts", "yade"],
                          "variants": [{"law": "hertz-mindlin", "with": {"tangential-damping": "none"}}]})
    runs, skipped = keyed(campaign)
    liggghts = [run for run in runs.values() if run.engine == "liggghts"]
    assert {run.options_dict.get("tangential_damping") for run in liggghts} == {"off", None}
    plain = [run for run in liggghts if "tangential_damping" not in run.options_dict]
    assert len([run for run in runs.values() if run.engine == "yade"]) == len(plain) > 0
    assert skipped == [("yade", "yade cannot follow --with tangential-damping=none: its hertz-mindlin inputs have no "
                                "setting that computes it (docs/yade-dialect.md)")]


def test_the_slurm_job_script_carries_the_options(tmp_path):
    cluster = slurm_cluster({"queue": "debug", "account": "proj", "cores": 4, "memory": "8GB",
                             "walltime": "02:00:00"}, tmp_path, tmp_path)
    try:
        script = cluster.job_script()
    finally:
        cluster.close()
        forget_credentials(cluster)
    for line in ("#SBATCH -p debug", "#SBATCH -A proj", "#SBATCH --cpus-per-task=4", "#SBATCH --mem=8G",
                 "#SBATCH -t 02:00:00", f"{sys.executable} -m distributed.cli.dask_worker", "--nworkers 4"):
        assert line in script, (line, script)


class KillAWorker:
    """A progress that kills one worker process after the first task is stored."""

    def __init__(self, client):
        self.client, self.killed = client, False

    def expect(self, steps):
        pass

    def advance(self, what):
        if not self.killed:
            pids = self.client.run(os.getpid)
            os.kill(sorted(pids.values())[0], signal.SIGKILL)
            self.killed = True


@needs("liggghts")
@needs("yade")
def test_dask_workers_give_the_in_process_results_bit_for_bit_even_when_one_is_killed(tmp_path):
    campaign = from_dict({**SMALL, "engines": ["reference", "liggghts", "yade"]})
    local = run_campaign(campaign, tmp_path / "local", InProcess())
    on_dask = executor("dask", workers=2)
    try:
        dasked = run_campaign(campaign, tmp_path / "dask", on_dask)
        killed = KillAWorker(on_dask.client)
        survived = run_campaign(campaign, tmp_path / "killed", on_dask, progress=killed)
    finally:
        on_dask.close()
    assert killed.killed and local.tasks == dasked.tasks == survived.tasks == 2 * (2 + 2 * 2) + 2 * 2  # YADE
    assert local.failed == dasked.failed == survived.failed == 0 and local.skipped == []       # has no thornton
    reference = sorted_rows(Store(tmp_path / "local").table())
    for other in ("dask", "killed"):
        rows = sorted_rows(Store(tmp_path / other).table())
        assert rows[KEY].equals(reference[KEY]) and rows[METRICS].equals(reference[METRICS]), other


def test_query_runs_sql_over_the_store(tmp_path, capfd):
    run_campaign(from_dict({**SMALL, "engines": ["reference"]}), tmp_path / "s", InProcess())
    assert main(["query", str(tmp_path / "s"), "SELECT count(*) AS n FROM results", "--csv"]) == 0
    assert capfd.readouterr().out.split() == ["n", "12"]
    assert main(["query", str(tmp_path / "s"), "SELECT nope FROM results"]) == 2


@needs("liggghts")
def test_the_example_campaign_runs_and_its_rerun_is_cached(tmp_path, capfd):
    import json
    example = os.path.join(os.path.dirname(__file__), "..", "examples", "campaign.toml")
    store = str(tmp_path / "store")
    assert main(["campaign", example, "-o", store, "--json"]) == 0
    first = json.loads(capfd.readouterr().out)
    assert (first["tasks"], first["ran"], first["cached"], first["failed"]) == (12, 12, 0, 0)
    assert os.path.isfile(store + ".html") and "liggghts, thornton" in Path(store + ".html").read_text()
    assert main(["campaign", example, "-o", store, "--json", "--executor", "dask", "--workers", "1"]) == 0
    again = json.loads(capfd.readouterr().out)
    assert (again["ran"], again["cached"]) == (0, 12)


def count_engine_runs(monkeypatch, what=lambda run: run.engine):
    """What(run) of the runs each engine is asked to execute (cached ones are not)."""
    from harness.engines import ENGINES
    executed = []
    for name, adapter in ENGINES.items():
        def counting(runs, run=adapter.run):
            executed.extend(what(r) for r in runs)
            return run(runs)
        monkeypatch.setattr(adapter, "run", counting)
    return executed


def test_compare_and_check_take_what_a_store_holds(tmp_path, monkeypatch, capfd):
    executed = count_engine_runs(monkeypatch)
    store = str(tmp_path / "store")
    args = ["compare", "--model", "thornton", "--engines", "reference", "--en", "0.5,0.9", "--angles", "10,40",
            "--store", store, "--quiet"]
    assert main(args + ["-o", str(tmp_path / "a")]) == 0 and executed == ["reference"] * 2
    assert main(args + ["-o", str(tmp_path / "b")]) == 0 and executed == ["reference"] * 2    # nothing ran again
    a, b = (pd.read_csv(tmp_path / d / "results.csv") for d in "ab")
    assert a[METRICS].equals(b[METRICS])
    assert main(["check", "--store", store, "--quiet"]) == 0
    first = len(executed)
    assert main(["check", "--store", store, "--quiet"]) == 0 and len(executed) == first
    capfd.readouterr()


def test_cost_takes_its_converged_truths_from_a_store(tmp_path, monkeypatch, capfd):
    """The truths (2^16 and 2^15 steps per contact) run once; a second study with the store reruns only the timed
    ladder (never stored), and its table's errors are the same."""
    executed = count_engine_runs(monkeypatch, lambda run: (run.engine, run.resolution))
    truths = [("reference", 2 ** 16), ("reference", 2 ** 15)]
    store = str(tmp_path / "store")
    args = ["cost", "--model", "thornton", "--engines", "reference", "--en", "0.5", "--angles", "40",
            "--ladder", "100", "--store", store, "--json"]
    assert main(args + ["-o", str(tmp_path / "a")]) == 0
    first = list(executed)
    assert [r for r in first if r in truths] == truths      # the two truth runs, then through the store
    assert main(args + ["-o", str(tmp_path / "b")]) == 0
    assert [r for r in executed[len(first):] if r in truths] == []
    assert len(executed) > len(first)                       # the timed ladder ran again (how often each curve is
                                                            # timed depends on the machine's noise)
    capfd.readouterr()
    a, b = (pd.read_csv(tmp_path / d / "cost.csv") for d in "ab")
    errors = [c for c in a.columns if c.startswith("err_")]
    assert errors and a[errors].equals(b[errors])


@needs("yade")
def test_a_campaign_on_dask_stopped_by_sigint_leaves_whole_fragments_and_no_process(tmp_path):
    """The driver interrupted while YADE tasks run on two worker processes: exit 130, only whole fragments in the
    store, no worker or engine process left, and the rerun runs only the tasks the store lacks."""
    import json
    import subprocess
    import time
    from test_reliability import descendants, wait_gone
    path = tmp_path / "c.toml"
    path.write_text('laws = ["hertz-mindlin"]\nengines = ["yade"]\ne_n = [0.3, 0.7]\n'
                    'angles = [10, 50]\nspins = [0.0, 5.0, 10.0]\nsteps_per_contact = [500]\n')
    store = tmp_path / "store"
    command = [sys.executable, "-m", "harness", "campaign", str(path), "-o", str(store), "--executor", "dask",
               "--workers", "2"]
    proc = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            preexec_fn=interruptible)
    deadline = time.time() + 180
    while not (store.is_dir() and [n for n in os.listdir(store) if n.startswith("part-")]):
        assert time.time() < deadline and proc.poll() is None, proc.communicate()
        time.sleep(0.2)
    tree = descendants(proc.pid)
    proc.send_signal(signal.SIGINT)
    proc.communicate(timeout=120)
    assert proc.returncode == 130
    assert all(wait_gone(pid, 30) for pid in tree)
    names = os.listdir(store)
    assert not [n for n in names if n.endswith(".tmp")]
    kept = Store(store).finished()
    assert 1 <= len(kept) < 18          # 3 spins x 2 e_n x (paper law, YADE formulas, YADE)
    done = subprocess.run(command + ["--json"], capture_output=True, text=True, timeout=600)
    summary = json.loads(done.stdout)
    assert (summary["tasks"], summary["cached"], summary["ran"]) == (18, len(kept), 18 - len(kept))
