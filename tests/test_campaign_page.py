"""The campaign page, data first: each table it shows is what `harness query` prints for the command shown above
it (the agreement with the formulas and the e_n x angle maps against independent pairings of the store's rows in
pandas), and a campaign over initial spins stores each spin's impacts as a direct run gives them, with Omega* moving
as theory says, and draws its figures against the spin."""
import csv
import io
import math

import pandas as pd
import pytest

import harness
from conftest import needs
from harness.analyses.agreement import agreement
from harness.commands import main
from test_figures_and_citation import assert_whole, campaign_page, files_of, paired_worst

SMALL = """name = "small"
laws = ["hertz-mindlin"]
engines = ["reference", "liggghts"]
e_n = [0.5, 0.8]
angles = [20, 60]
mus = [0.1, 0.3]
steps_per_contact = [200]
"""
RADIUS, MU, ANGLE = 0.01, 0.3, 45.0
ROLLING = math.sin(math.radians(ANGLE)) / RADIUS      # omega0 = V_t/R: the contact point does not slip at first


def printed(store, sql, capfd):
    """What `harness query STORE SQL --csv` prints, as rows of cells."""
    assert main(["query", str(store), sql, "--csv"]) == 0
    return list(csv.reader(io.StringIO(capfd.readouterr().out)))


def same_cell(shown, exact):
    """A cell as the page shows it (rounded to 3 or 4 digits) against the value the query prints."""
    try:
        return float(shown) == pytest.approx(float(exact), rel=5e-3)
    except ValueError:
        return shown == exact


@needs("liggghts")
def test_each_table_the_page_shows_is_what_harness_query_prints(tmp_path, capfd):
    store, page = campaign_page(tmp_path, SMALL, capfd)
    kinds = [next((v for v in ("agreement", "deviation_map", "deviations", "results") if f"FROM {v}" in t["sql"]))
             for t in page.tables]
    assert sorted(kinds) == ["agreement", "deviation_map", "deviations", "results"]
    for table in page.tables:
        out = printed(store, table["sql"], capfd)
        assert out[0] == table["head"]
        body = [row for row in table["rows"] if row]
        assert len(body) == len(out) - 1 > 0
        for shown, exact in zip(body, out[1:]):
            assert len(shown) == len(exact) and all(map(same_cell, shown, exact)), (shown, exact)
    rows = pd.read_parquet(store)
    agreed = printed(store, next(t["sql"] for t in page.tables if "FROM agreement" in t["sql"]), capfd)
    worst = {float(row[agreed[0].index("mu")]): float(row[agreed[0].index("worst")]) for row in agreed[1:]}
    assert worst == pytest.approx({mu: agreement(group, "liggghts").max_rel_diff.max()
                                   for mu, group in rows.groupby("mu")}, rel=1e-9, abs=0)
    mapped = printed(store, next(t["sql"] for t in page.tables if "deviation_map" in t["sql"]), capfd)
    cells = {(float(row[0]), float(angle)): float(value) for row in mapped[1:]
             for angle, value in zip(mapped[0][1:], row[1:])}
    assert cells == pytest.approx(paired_worst(rows, "e_t", ("e_n_target", "theta_deg")), rel=1e-12)
    assert min(cells.values()) > 0


def test_a_campaign_over_spins_stores_each_spin_as_a_direct_run_gives_it(tmp_path, capfd):
    """Three spins: none, rolling (V_t = R omega0: no slip, so no tangential force, so v_t and omega leave as they
    came and Omega* = -2 R omega0/(mu (1 + e) V_n)) and its reverse (slip 2 V_t, Psi1* ~ 8.9 > 7: sliding
    throughout, so Omega* is the rolling spin's term plus -5, the rigid sphere's); each row as harness.run gives it
    at that spin; the page draws e_n, e_t and Omega* against the spin, each also an SVG and a PDF."""
    spins = [0.0, ROLLING, -ROLLING]
    store, page = campaign_page(
        tmp_path, f'name = "spins"\nlaws = ["hertz-mindlin"]\nengines = ["reference"]\ne_n = [0.5]\n'
        f'angles = [{ANGLE!r}]\nspeeds = [1.0]\nmus = [{MU!r}]\nradii = [{RADIUS!r}]\n'
        f'spins = [{", ".join(map(repr, spins))}]\nsteps_per_contact = [500]\n', capfd)
    rows = pd.read_parquet(store).set_index("omega0")
    assert sorted(rows.index) == sorted(spins)
    for spin in spins:
        direct = harness.run("hertz-mindlin", en=[0.5], angles=[ANGLE], speed=1.0, mu=MU, radius=RADIUS,
                             omega0=spin, steps_per_contact=500).iloc[0]
        for column in ("e_n", "e_t", "omega1", "omega_star"):
            assert rows.loc[spin, column] == pytest.approx(direct[column], rel=1e-12, abs=1e-12)
    rolling = rows.loc[ROLLING]
    unit = MU * (1 + rolling.e_n) * rolling.v_n0 / 2
    assert rolling.omega1 == pytest.approx(ROLLING, rel=1e-9) and rolling.e_t == pytest.approx(1, rel=1e-9)
    assert rolling.omega_star == pytest.approx(-RADIUS * ROLLING / unit, rel=1e-9)
    backward = rows.loc[-ROLLING]
    unit = MU * (1 + backward.e_n) * backward.v_n0 / 2
    assert backward.psi1_star > 7
    assert backward.omega_star == pytest.approx(RADIUS * ROLLING / unit - 5, abs=1e-3)
    assert rows.loc[0.0].omega_star != pytest.approx(backward.omega_star, abs=0.1)
    assert [f["parameter"] for f in page.figures] == ["omega0"] * 3
    assert [t["parameter"] for t in page.tables] == ["omega0"]
    for svg, pdf in files_of(tmp_path, page):
        assert svg.name.endswith("-vs-omega0.svg")
        assert_whole(svg, pdf)


def test_the_failed_tasks_the_page_shows_are_what_harness_query_prints(tmp_path, monkeypatch, capfd):
    """A LIGGGHTS that crashes (a stand-in script): its tasks are failed in the store, and the page's failed-tasks
    table is what `harness query` prints for the SQL shown above it, one row per e_n with the crash's reason."""
    from conftest import fake_executable
    from harness.engines import liggghts
    from test_figures_and_citation import Page
    monkeypatch.setenv(liggghts.BINARY_VARIABLE, fake_executable(tmp_path, 'echo "ERROR: Illegal fix wall"; exit 1'))
    spec = tmp_path / "campaign.toml"
    spec.write_text(SMALL.replace("mus = [0.1, 0.3]\n", ""))
    store = tmp_path / "store"
    main(["campaign", str(spec), "-o", str(store), "--quiet"])
    capfd.readouterr()
    page = Page((tmp_path / "store.html").read_text())
    failed = [t for t in page.tables if "status = 'failed'" in t["sql"]]
    assert len(failed) == 1
    out = printed(store, failed[0]["sql"], capfd)
    body = [row for row in failed[0]["rows"] if row]
    assert out[0] == failed[0]["head"] == ["engine", "model", "e_n_target", "message"]
    assert [r[:3] for r in out[1:]] == [["liggghts", "hertz-mindlin", "0.5"], ["liggghts", "hertz-mindlin", "0.8"]]
    assert len(body) == 2 and all(map(same_cell, body[0], out[1])) and all(map(same_cell, body[1], out[2]))
    stored = pd.read_parquet(store)
    assert set(stored[stored.status == "failed"].engine) == {"liggghts"}


def test_each_deviation_map_has_a_colour_key_from_zero_to_its_largest_value(tmp_path):
    """Under each e_n x angle map, swatches from white at 0 to the colour of the map's largest cell, each labelled
    with the value it stands for."""
    import re
    from harness.studies.campaign.page import PageData, Shown
    from harness.views.campaign_html import write_campaign_report
    grid = pd.DataFrame({"e_n_target": [0.5, 0.9], "20.0": [0.012, 0.03], "60.0": [0.25, float("nan")]})
    table = pd.DataFrame({"status": ["ok"], "task_key": ["k"], "model": ["hertz-mindlin"], "engine": ["liggghts"]})
    data = PageData([], maps=[Shown("liggghts, hertz-mindlin", "SELECT 1", grid)])
    page = (tmp_path / "store.html")
    write_campaign_report(table, str(page), "small", data, "store")
    text = page.read_text()
    shaded = re.findall(r'<td style="background: (rgb\([0-9,]+\))">([0-9.e-]+)</td>', text)
    cells = {float(value): colour for colour, value in shaded}
    key = re.search(r'<p class="key">(.*?)</p>', text)
    assert key, "no colour key under the map"
    swatches = re.findall(r'background: (rgb\([0-9,]+\))">([0-9.e-]+)</span>', key.group(1))
    assert swatches[0] == ("rgb(255,255,255)", "0") and float(swatches[-1][1]) == 0.25
    assert swatches[-1][0] == cells[0.25]
    shades = [int(colour.split(",")[1]) for colour, _ in swatches]
    assert shades == sorted(shades, reverse=True) and len(set(shades)) == len(shades)
