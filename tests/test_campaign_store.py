"""The campaign store's entrance: a damaged fragment (truncated, empty, foreign, not Parquet, a directory, a FIFO, a
link, holding another task) is named in one line with exit 2 by every command that reads a store (campaign, query,
compare, check and cost with --store), nothing is written, and --drop-damaged removes it so that its tasks rerun.
Each task is read once, whatever a crash left in two files; a store path that is not a directory is refused before
anything is written."""
import os
import shutil
import subprocess
import sys

import pandas as pd
import pyarrow as pa
import pyarrow.parquet as pq
import pytest
from conftest import SMALL_CAMPAIGN, snapshot

from harness.studies.campaign.driver import run_campaign
from harness.studies.campaign.executors import InProcess
from harness.studies.campaign.spec import from_dict
from harness.studies.campaign.store import KEY, Store
from harness.commands import main
from harness.runs.keys import run_key
from harness.runs.plan import compare_plan
from harness.runs.request import Request

TOML = 'laws = ["thornton"]\ne_n = [0.5, 0.9]\nangles = [10, 50, 85]\nsteps_per_contact = [500]\n'


@pytest.fixture
def store(small_store, tmp_path):
    shutil.copytree(small_store, tmp_path / "store")
    (tmp_path / "c.toml").write_text(TOML)
    return tmp_path / "store"


def only(directory, prefix):
    names = [n for n in os.listdir(directory) if n.startswith(prefix)]
    assert len(names) == 1, names
    return names[0]


def truncated(store):
    name = only(store, "data-")
    path = store / name
    path.write_bytes(path.read_bytes()[: path.stat().st_size // 2])
    return name


def empty(store):
    (store / "part-0123456789abcdef0123.parquet").write_bytes(b"")
    return "part-0123456789abcdef0123.parquet"


def foreign(store):
    pq.write_table(pa.table({"a": [1, 2]}), store / "foreign.parquet")
    return "foreign.parquet"


def not_parquet(store):
    (store / "garbage.parquet").write_bytes(os.urandom(4096))
    return "garbage.parquet"


def directory(store):
    (store / "part-aaaa.parquet").mkdir()
    (store / "part-aaaa.parquet" / "x").write_text("x")
    return "part-aaaa.parquet"


def link(store):
    (store / "part-bbbb.parquet").symlink_to(store / only(store, "data-"))
    return "part-bbbb.parquet"


def link_to_passwd(store):
    (store / "linked.parquet").symlink_to("/etc/passwd")
    return "linked.parquet"


def another_task(store):
    frame = pd.read_parquet(store / only(store, "data-"))
    one = frame[frame[KEY] == frame[KEY].iloc[0]]
    one.to_parquet(store / "part-ffffffffffffffffffff.parquet", index=False)
    return "part-ffffffffffffffffffff.parquet"


def key_not_text(store):
    pq.write_table(pa.table({KEY: [1], "engine": ["reference"], "status": ["ok"]}), store / "numbers.parquet")
    return "numbers.parquet"


def fifo(store):
    os.mkfifo(store / "part-cccc.parquet")
    return "part-cccc.parquet"


DAMAGE = [truncated, empty, foreign, not_parquet, directory, link, link_to_passwd, another_task, key_not_text]


def commands(tmp_path, store):
    """Every command that reads a store, each writing (if it wrote) into tmp_path/out."""
    out = str(tmp_path / "out")
    return {
        "campaign": ["campaign", str(tmp_path / "c.toml"), "-o", str(store), "--quiet"],
        "campaign --dry-run": ["campaign", str(tmp_path / "c.toml"), "-o", str(store), "--dry-run"],
        "query": ["query", str(store), "SELECT count(*) AS n FROM results"],
        "compare": ["compare", "--model", "thornton", "--engines", "reference", "--en", "0.5", "--angles", "10",
                    "--store", str(store), "-o", out, "--quiet"],
        "check": ["check", "--store", str(store), "--quiet"],
        "cost": ["cost", "--model", "thornton", "--engines", "reference", "--en", "0.5", "--angles", "40",
                 "--ladder", "100", "--store", str(store), "-o", out, "--quiet"],
    }


COMMANDS = ["campaign", "campaign --dry-run", "query", "compare", "check", "cost"]


def test_the_catalogue_covers_each_damage_and_command():
    assert len(DAMAGE) + 1 >= 10 and len(COMMANDS) == 6


@pytest.mark.parametrize("command", COMMANDS)
@pytest.mark.parametrize("damage", DAMAGE, ids=lambda d: d.__name__)
def test_a_damaged_fragment_is_named_in_one_line_and_nothing_is_written(tmp_path, store, capfd, damage, command):
    name = damage(store)
    before = snapshot(tmp_path)
    code = main(commands(tmp_path, store)[command])
    out, err = capfd.readouterr()
    lines = err.strip().splitlines()
    assert code == 2, (out, err)
    assert len(lines) == 1 and lines[0].startswith("harness: error: ") and name in lines[0], err
    assert "--drop-damaged" in lines[0] and "Traceback" not in out + err
    assert snapshot(tmp_path) == before


@pytest.mark.parametrize("command", COMMANDS)
def test_a_fifo_fragment_is_refused_without_blocking(tmp_path, store, command):
    """As a process with a deadline: opening the FIFO to read it would block for ever."""
    name = fifo(store)
    before = snapshot(tmp_path)
    done = subprocess.run([sys.executable, "-m", "harness", *commands(tmp_path, store)[command]],
                          capture_output=True, text=True, timeout=120, stdin=subprocess.DEVNULL)
    lines = done.stderr.strip().splitlines()
    assert done.returncode == 2 and len(lines) == 1 and name in lines[0] and "FIFO" in lines[0], done.stderr
    assert snapshot(tmp_path) == before


def test_drop_damaged_removes_the_fragments_and_their_tasks_rerun(tmp_path, store, capfd):
    import json
    damaged = [truncated(store), empty(store), directory(store), link(store), fifo(store)]
    target = os.path.realpath(store / only(store, "data-"))
    assert main(["campaign", str(tmp_path / "c.toml"), "-o", str(store), "--json", "--drop-damaged"]) == 0
    out, err = capfd.readouterr()
    summary = json.loads(out)
    assert (summary["tasks"], summary["ran"], summary["cached"]) == (2, 2, 0)    # the data file held both
    assert all(name in err for name in damaged) and "Traceback" not in err
    assert not any(os.path.lexists(store / name) for name in damaged[1:])
    assert not os.path.exists(target) or os.path.getsize(target) > 0
    assert main(["query", str(store), "SELECT count(*) AS n, count(DISTINCT task_key) AS k FROM results",
                 "--csv"]) == 0
    assert capfd.readouterr().out.split() == ["n,k", "6,2"]


def test_query_drops_a_damaged_fragment_when_asked(tmp_path, store, capfd):
    name = not_parquet(store)
    assert main(["query", str(store), "SELECT count(*) AS n FROM results", "--csv", "--drop-damaged"]) == 0
    out, err = capfd.readouterr()
    assert out.split() == ["n", "6"] and name in err and not (store / name).exists()


def test_a_task_left_in_a_part_and_a_data_file_is_read_once(tmp_path, store, capfd):
    """A crash between writing the compacted file and removing the parts leaves each task twice."""
    frame = pd.read_parquet(store / only(store, "data-"))
    for key, rows in frame.groupby(KEY):
        rows.to_parquet(store / f"part-{key}.parquet", index=False)
    assert len(Store(store).table()) == 6
    assert main(["query", str(store), "SELECT count(*) AS n FROM results", "--csv"]) == 0
    assert capfd.readouterr().out.split() == ["n", "6"]
    again = run_campaign(from_dict(SMALL_CAMPAIGN), store, InProcess())         # its compaction removes the older copy
    assert again.ran == 0 and len(pd.read_parquet(store)) == 6
    assert [n for n in os.listdir(store) if n.endswith(".parquet")] == [only(store, "data-")]


def test_two_compacted_files_with_the_same_tasks_are_read_once(tmp_path, store, capfd):
    name = only(store, "data-")
    shutil.copy(store / name, store / "data-000000000000.parquet")
    frame = pd.read_parquet(store / name)
    rows = frame[frame[KEY] == frame[KEY].iloc[0]]
    rows.to_parquet(store / "data-ffffffffffff.parquet", index=False)           # a third, holding one task
    assert len(Store(store).table()) == 6
    assert main(["query", str(store), "SELECT count(*) AS n, count(DISTINCT task_key) AS k FROM results",
                 "--csv"]) == 0
    assert capfd.readouterr().out.split() == ["n,k", "6,2"]


def count_engine_runs(monkeypatch):
    """The runs each engine is asked to execute (cached ones are not)."""
    from harness.engines import ENGINES
    executed = []
    for adapter in ENGINES.values():
        def counting(runs, run=adapter.run):
            executed.extend(r.engine for r in runs)
            return run(runs)
        monkeypatch.setattr(adapter, "run", counting)
    return executed


def test_compare_takes_what_a_campaign_of_integers_stored(tmp_path, store, monkeypatch, capfd):
    """The campaign file says angles = [10, 50, 85]; compare's --angles are floats: nothing reruns."""
    executed = count_engine_runs(monkeypatch)
    assert main(["compare", "--model", "thornton", "--engines", "reference", "--en", "0.5,0.9", "--angles",
                 "10,50,85", "--steps-per-contact", "500", "--store", str(store), "-o", str(tmp_path / "out"),
                 "--quiet"]) == 0
    capfd.readouterr()
    assert executed == []


def test_integer_and_float_scenes_have_one_key():
    def keys(**scene):
        request = Request.from_keywords("thornton", en=[0.5], steps_per_contact=500, **scene)
        return {run_key(run) for run in compare_plan(request.law, request.scene, request.resolution, {})}
    assert keys(angles=[10, 30], speed=5, omega0=0, mu=1) == keys(angles=[10.0, 30.0], speed=5.0, omega0=0.0,
                                                                   mu=1.0)


@pytest.mark.parametrize("command", ["compare", "check", "cost"])
def test_a_store_path_that_is_a_file_is_refused_before_anything_is_written(tmp_path, capfd, command):
    path = tmp_path / "store"
    path.write_text("not a store")
    before = snapshot(tmp_path)
    code = main(commands(tmp_path, path)[command])
    out, err = capfd.readouterr()
    lines = err.strip().splitlines()
    assert code == 2 and len(lines) == 1 and "not a directory" in lines[0], err
    assert snapshot(tmp_path) == before


def test_query_refuses_a_store_that_is_missing_or_empty(tmp_path, capfd):
    assert main(["query", str(tmp_path / "nowhere"), "SELECT 1"]) == 2
    assert "no campaign store" in capfd.readouterr().err
    (tmp_path / "empty").mkdir()
    assert main(["query", str(tmp_path / "empty"), "SELECT 1"]) == 2
    assert "holds no campaign results" in capfd.readouterr().err
    assert sorted(os.listdir(tmp_path)) == ["empty"]


def test_an_interrupt_while_a_fragment_is_written_leaves_no_temporary_file(tmp_path, store, monkeypatch):
    kept = Store(store)
    frame = kept.read(kept.files()[0])
    written = pq.write_table

    def interrupted(table, where, **options):
        written(table.slice(0, 1), where, **options)      # some bytes are on disk when the interrupt comes
        raise KeyboardInterrupt
    monkeypatch.setattr(pq, "write_table", interrupted)
    before = sorted(os.listdir(store))
    with pytest.raises(KeyboardInterrupt):
        kept.put(frame[KEY].iloc[0], frame)
    assert sorted(os.listdir(store)) == before
