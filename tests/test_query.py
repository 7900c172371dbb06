"""`harness query`'s entrance: one read-only SELECT over the store. Every attack of the probe (reading /etc/passwd,
/etc/shadow and /proc/self/environ, writing with COPY, overwriting a fragment, listing directories, attaching a
database, installing an extension) and every query that is not one SELECT is refused in one line with exit 2 and
leaves every file as it was; a result too large to print is refused; a store whose file names carry quotes and glob
characters is read as it is, and its names inject nothing."""
import os
import shutil
import subprocess
import sys
import time

import pytest
from conftest import snapshot

from harness.commands import main


@pytest.fixture
def store(small_store, tmp_path, monkeypatch):
    """A copy of a 2-task, 6-row store in tmp_path, which is also the working directory (where a relative COPY
    would write)."""
    shutil.copytree(small_store, tmp_path / "store")
    monkeypatch.chdir(tmp_path)
    return tmp_path / "store"


def fragment(store):
    return next(n for n in os.listdir(store) if n.startswith("data-"))



ATTACKS = [
    ("SELECT * FROM read_text('/etc/passwd')", "disabled"),
    ("SELECT * FROM read_csv('/etc/shadow')", "disabled"),
    ("SELECT content FROM read_text('/proc/self/environ')", "disabled"),
    ("SELECT * FROM read_blob('/etc/hostname')", "disabled"),
    ("SELECT * FROM read_csv_auto('/etc/passwd', header = false)", "disabled"),
    ("SELECT * FROM read_json_auto('/etc/os-release')", "disabled"),
    ("SELECT * FROM sniff_csv('/etc/passwd')", "disabled"),
    ("SELECT * FROM '/etc/passwd'", "does not exist"),
    ("SELECT * FROM glob('/etc/*')", "disabled"),
    ("SELECT * FROM glob('store/*')", "disabled"),
    ("SELECT * FROM read_parquet('store/*.parquet')", "disabled"),
    ("SELECT * FROM parquet_metadata('store/*.parquet')", "disabled"),
    ("COPY (SELECT 1 AS a) TO 'written.csv'", "not COPY"),
    ("COPY results TO 'store/{name}'", "not COPY"),
    ("EXPORT DATABASE 'exported'", "not EXPORT"),
    ("ATTACH 'created.db' AS other", "not ATTACH"),
    ("INSTALL httpfs", "only reads"),
    ("LOAD httpfs", "only reads"),
    ("SET enable_external_access = true", "not SET"),
    ("RESET lock_configuration", "only reads"),
    ("PRAGMA database_list", "not PRAGMA"),
    ("CALL pragma_version()", "not CALL"),
    ("CREATE TABLE t AS SELECT 1", "not CREATE"),
    ("DROP VIEW results", "not DROP"),
    ("SELECT * FROM query('COPY (SELECT 1) TO ''written.csv''')", "SELECT"),
    ("SELECT 1; COPY (SELECT 1) TO 'written.csv'", "2 statements"),
    ("WITH a AS (SELECT 1) SELECT * FROM read_text('/etc/passwd')", "disabled"),
    ("SELECT * FROM duckdb_extensions()", "disabled"),
]
EMPTY = ["", " ", ";", ";;", "-- only a comment", "/* a comment */", "\n\n"]
TOO_LARGE = [("SELECT * FROM range(200000)", "more than 100000 rows"),
             ("SELECT * FROM range(10000000000000)", "more than 100000 rows"),
             ("SELECT repeat('x', 20000) AS s", "characters"),
             ("SELECT repeat('x', 1000) AS s FROM range(90000)", "more than 64 MiB"),
             ("SELECT repeat('x', 600000000) AS s", "more than 512 MB of memory"),
             ("SELECT list(range(200000000)) AS l", "more than 512 MB of memory"),
             ("SELECT 1 -- " + "x" * 200_000, "longer than")]


def test_the_catalogue_covers_the_probe():
    assert len(ATTACKS) + len(EMPTY) + len(TOO_LARGE) >= 35


@pytest.mark.parametrize("sql, words", ATTACKS + [(q, "empty") for q in EMPTY] + TOO_LARGE,
                         ids=[q[:50] for q, _ in ATTACKS] + [repr(q) for q in EMPTY] + [q[:30] for q, _ in TOO_LARGE])
def test_a_query_that_is_not_one_small_read_is_refused_in_one_line(tmp_path, store, capfd, sql, words):
    before = snapshot(tmp_path)
    code = main(["query", str(store), sql.replace("{name}", fragment(store))])
    out, err = capfd.readouterr()
    lines = err.strip().splitlines()
    assert code == 2, (out[:500], err)
    assert len(lines) == 1 and lines[0].startswith("harness: error: ") and words in lines[0], err
    assert "root:" not in out + err and "Traceback" not in out + err
    assert snapshot(tmp_path) == before


def test_a_query_that_runs_too_long_is_stopped_in_one_line(tmp_path, store, capfd, monkeypatch):
    """With the limit set to 1 s: a count over 10^13 rows would run for hours. Nothing is printed meanwhile (no
    progress bar on stdout)."""
    from harness.studies.campaign import query
    monkeypatch.setattr(query, "MAX_QUERY_S", 1.0)
    started = time.perf_counter()
    code = main(["query", str(store), "SELECT count(*) FROM range(10000000000000)"])
    out, err = capfd.readouterr()
    assert code == 2 and out == "" and err.strip().splitlines() == [
        "harness: error: the query ran longer than 1 s and was stopped: narrow it"], (out, err)
    assert time.perf_counter() - started < 30


def test_a_query_that_would_take_gigabytes_is_refused_at_a_bounded_size(store):
    """DuckDB's own memory limit leaves out a scalar function's result: repeat() of 2 GB grew the process past 4 GB.
    In a process of its own, so that its peak size is its own."""
    code = ("import resource, sys\n"
            "from harness.commands import main\n"
            f"code = main(['query', {str(store)!r}, \"SELECT repeat('x', 2000000000) AS s\"])\n"
            "print(code, resource.getrusage(resource.RUSAGE_SELF).ru_maxrss)")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300)
    exit_code, peak_kib = map(int, done.stdout.split())
    assert exit_code == 2 and done.stderr.strip().splitlines() == [
        "harness: error: the query needs more than 512 MB of memory: narrow it"], done.stderr
    assert peak_kib < 1.5 * 2 ** 20, f"peak {peak_kib / 2 ** 20:.1f} GiB"


@pytest.mark.parametrize("sql, expected", [
    ("SELECT count(*) AS n FROM results", ["n", "6"]),
    ("WITH r AS (SELECT * FROM results) SELECT count(DISTINCT task_key) AS k FROM r", ["k", "2"]),
    ("FROM results SELECT count(*) AS n", ["n", "6"]),
    ("SELECT engine, count(*) AS n FROM results GROUP BY ALL", ["engine,n", "reference,6"]),
])
def test_a_read_only_select_works(store, capfd, sql, expected):
    assert main(["query", str(store), sql, "--csv"]) == 0
    assert capfd.readouterr().out.split() == expected


def test_describe_lists_the_columns(store, capfd):
    assert main(["query", str(store), "DESCRIBE results", "--csv"]) == 0
    out = capfd.readouterr().out
    assert "task_key" in out and "e_t" in out


def test_file_names_with_quotes_are_read_and_inject_nothing(tmp_path, store, capfd):
    """The name closes a string and a list, then runs COPY: SQL made from the names (the view once was) runs it,
    given a second file named to complete the first statement. Read as data, it is one more copy of both tasks."""
    data = fragment(store)
    shutil.copy(store / data, store / "data-0\"'], union_by_name = true); COPY (SELECT 42 AS n) TO $$pwned.csv$$; "
                                      "--.parquet")
    shutil.copy(store / data, store / "data-0\"\\")
    shutil.copy(store / data, store / "data-[*]?'.parquet")
    assert main(["query", str(store), "SELECT count(*) AS n, count(DISTINCT task_key) AS k FROM results",
                 "--csv"]) == 0
    out, err = capfd.readouterr()
    assert out.split() == ["n,k", "6,2"], err
    assert not (tmp_path / "pwned.csv").exists() and not (store / "pwned.csv").exists()


def test_a_fragment_named_like_a_glob_reads_only_itself(tmp_path, store, capfd):
    """`*` in a name is a character, not a pattern matching every fragment."""
    data = fragment(store)
    os.rename(store / data, store / "data-*.parquet")
    assert main(["query", str(store), "SELECT count(*) AS n FROM results", "--csv"]) == 0
    assert capfd.readouterr().out.split() == ["n", "6"]


@pytest.mark.parametrize("sql, words", [
    ("SELECT * FROM store", "Table with name store does not exist"),
    ("SELECT * FROM result", "Table with name result does not exist"),
    ("SELECT e_tt FROM results", 'Referenced column "e_tt" not found'),
])
def test_a_table_or_column_that_does_not_exist_is_told_where_the_rows_are(store, capfd, sql, words):
    """One line: DuckDB's reason, then that the store is the view results, how to list its columns, and the other
    views."""
    assert main(["query", str(store), sql]) == 2
    lines = capfd.readouterr().err.strip().splitlines()
    assert len(lines) == 1 and words in lines[0], lines
    assert "the store is the view results" in lines[0] and "`DESCRIBE results` lists them" in lines[0]
    assert "deviations, agreement and deviation_map" in lines[0]


def test_query_help_names_the_views_and_the_columns_beyond_results_csv(store, capfd):
    """--help names every view the store holds (as DuckDB's catalogue lists them) and every column of `results`
    that results.csv does not have (as DESCRIBE lists them)."""
    import harness
    with pytest.raises(SystemExit):
        main(["query", "--help"])
    text = " ".join(capfd.readouterr().out.split())
    assert main(["query", str(store), "SELECT table_name FROM information_schema.tables WHERE table_type = 'VIEW' "
                 "AND table_name NOT LIKE 'store_%'", "--csv"]) == 0
    views = capfd.readouterr().out.split()[1:]
    assert sorted(views) == ["agreement", "deviation_map", "deviations", "results"]
    assert "over the view results" in text and all(view in text for view in views)
    assert main(["query", str(store), "SELECT column_name FROM (DESCRIBE results)", "--csv"]) == 0
    extra = set(capfd.readouterr().out.split()[1:]) - set(harness.columns.index)
    assert extra and all(column in text for column in extra), extra
