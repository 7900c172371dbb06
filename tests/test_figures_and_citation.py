"""Figures for a paper and how to cite: a campaign over mu x speed draws each metric against each swept parameter
over tables that `harness query` reproduces; every figure of a report is also an SVG and a PDF file beside it,
rebuilt by `harness report`; `harness cite` prints BibTeX with the sources' DOIs; CITATION.cff names this version."""
import csv
import io
import os
import re
import xml.etree.ElementTree as ElementTree
from html.parser import HTMLParser
from pathlib import Path

import pandas as pd
import pytest

import harness
from conftest import needs
from harness.infra.citation import DOCS_URL, PROJECT_URL
from harness.commands import main
from harness.infra.version import RELEASED

ROOT = Path(__file__).resolve().parent.parent
MU_SPEED = """name = "mu-speed"
laws = ["hertz-mindlin"]
engines = ["reference"]
e_n = [0.5]
angles = [20, 45, 70]
mus = [0.1, 0.3]
speeds = [1.0, 5.0]
steps_per_contact = [200]
"""


class Page(HTMLParser):
    """What a test reads of a report: figures (with their data-parameter and links), the tables shown under a
    `harness query` command (their SQL, swept parameter if any, header and rows of cells) and every link."""

    def __init__(self, text):
        super().__init__()
        self.figures, self.tables, self.links = [], [], []
        self._figure = self._table = self._cell = None
        self.feed(text)

    def handle_starttag(self, tag, attrs):
        attrs = dict(attrs)
        if tag == "figure":
            self._figure = {"parameter": attrs.get("data-parameter"), "links": []}
            self.figures.append(self._figure)
        elif tag == "div" and "query" in (attrs.get("class") or "").split():
            self._table = {"parameter": attrs.get("data-parameter"), "sql": attrs["data-sql"], "head": [], "rows": []}
            self.tables.append(self._table)
        elif tag == "a":
            self.links.append(attrs.get("href", ""))
            if self._figure is not None:
                self._figure["links"].append(attrs.get("href", ""))
        elif tag == "tr" and self._table is not None:
            self._table["rows"].append([])
        elif tag in ("th", "td") and self._table is not None:
            self._cell = tag
            if len(self._table["rows"]) > 1:
                self._table["rows"][-1].append("")

    def handle_endtag(self, tag):
        if tag == "p" and self._figure is not None and self._figure["links"]:
            self._figure = None                    # the figure's links end its entry
        elif tag == "div":
            self._table = None
        elif tag in ("th", "td"):
            self._cell = None

    def handle_data(self, data):
        if self._cell == "th" and self._table is not None and len(self._table["rows"]) == 1:
            self._table["head"].append(data.strip())
        elif self._cell is not None and self._table is not None:
            self._table["rows"][-1][-1] += data.strip()


def files_of(directory, page):
    """Every figure's (svg, pdf) paths, from the page's links, each figure having both."""
    out = []
    for figure in page.figures:
        svg = [link for link in figure["links"] if link.endswith(".svg")]
        pdf = [link for link in figure["links"] if link.endswith(".pdf")]
        assert len(svg) == len(pdf) == 1, figure
        out.append((directory / svg[0], directory / pdf[0]))
    return out


def assert_whole(svg, pdf):
    assert pdf.read_bytes().startswith(b"%PDF-") and pdf.read_bytes().rstrip().endswith(b"%%EOF")
    assert ElementTree.parse(svg).getroot().tag.endswith("svg")


def campaign_page(directory, text, capfd):
    """Run the campaign file `text` into directory/store; its path and its page (Page)."""
    spec = directory / "campaign.toml"
    spec.write_text(text)
    store = directory / "store"
    assert main(["campaign", str(spec), "-o", str(store), "--quiet"]) == 0
    capfd.readouterr()
    return store, Page((directory / "store.html").read_text())


def test_a_mu_by_speed_campaign_draws_each_metric_against_each_parameter(tmp_path, capfd):
    """Three figures (e_n, e_t, Omega*) per swept parameter and none for what was not swept; each figure an SVG and
    a PDF file; each table the page shows is what `harness query` prints for the SQL the page gives, and its means
    are the store's rows averaged here with pandas."""
    store, page = campaign_page(tmp_path, MU_SPEED, capfd)
    per_parameter = {}
    for figure in page.figures:
        if figure["parameter"]:
            per_parameter[figure["parameter"]] = per_parameter.get(figure["parameter"], 0) + 1
    assert per_parameter == {"mu": 3, "speed": 3}
    for svg, pdf in files_of(tmp_path, Page((tmp_path / "store.html").read_text())):
        assert svg.parent.name == "store-figures"
        assert_whole(svg, pdf)
    assert {t["parameter"] for t in page.tables} == {"mu", "speed"}
    rows = pd.read_parquet(store)
    for table in page.tables:
        assert main(["query", str(store), table["sql"], "--csv"]) == 0
        printed = list(csv.reader(io.StringIO(capfd.readouterr().out)))
        assert printed[0] == table["head"]
        assert len(printed) == len(table["rows"])             # header and rows alike
        mean = rows.groupby(table["parameter"]).e_t.mean()
        column = printed[0].index("mean_e_t")
        shown = {float(row[printed[0].index(table["parameter"])]): float(row[column]) for row in printed[1:]}
        assert shown == pytest.approx(mean.to_dict(), rel=1e-12)


def test_every_figure_of_a_compare_report_is_a_file_that_report_rebuilds(tmp_path, capfd):
    """SVG and PDF files for every figure of the report, named for what they show; `harness report` writes them
    again; a figures entry that is a file is refused in one line before anything is written."""
    out = tmp_path / "out"
    assert main(["compare", "--model", "hertz-mindlin", "--engines", "reference", "--en", "0.5", "--angles",
                 "20,60", "--steps-per-contact", "200", "-o", str(out)]) == 0
    page = Page((out / "report.html").read_text())
    files = files_of(out, page)
    assert len(files) == len(page.figures) >= 5
    assert out / "figures" / "hertz-mindlin-e_t-vs-psi1.svg" in [svg for svg, _ in files]
    for svg, pdf in files:
        assert_whole(svg, pdf)
    for svg, pdf in files:
        svg.unlink()
        pdf.unlink()
    assert main(["report", str(out)]) == 0
    assert all(svg.exists() and pdf.exists() for svg, pdf in files)
    assert [link for link in page.links if "docs/" in link] and \
        all(link.startswith(DOCS_URL) for link in page.links if "docs/" in link)
    (out / "figures").rename(tmp_path / "kept")
    (out / "figures").write_text("not a folder")
    capfd.readouterr()
    assert main(["report", str(out)]) == 2
    err = capfd.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "figures" in err[0] and "not a directory" in err[0]


def test_cite_prints_bibtex_for_harness_the_paper_and_the_benchmark(capfd):
    assert main(["cite"]) == 0
    text = capfd.readouterr().out
    entries = re.findall(r"@(\w+)\{(\w+),\n((?:  \w+ = \{.*\},?\n)+)\}", text)
    assert len(entries) == text.count("@") == 3
    fields = {key: dict(re.findall(r"  (\w+) = \{(.*)\}", body)) for _, key, body in entries}
    assert fields["harness"]["version"] == harness.__version__ and fields["harness"]["url"] == PROJECT_URL
    assert fields["thornton2013"]["doi"] == "10.1016/j.powtec.2012.08.012"
    assert fields["thornton2013"]["pages"] == "30--46" and fields["thornton2013"]["volume"] == "233"
    assert fields["chung2011"]["doi"] == "10.1007/s10035-011-0277-0" and fields["chung2011"]["pages"] == "643--656"
    assert all(body.count("{") == body.count("}") for _, _, body in entries)


PUBLICATIONS = {"liggghts": ("kloss2012", "10.1504/PCFD.2012.047457"),          # Kloss et al. 2012, PCFD 12
                "yade": ("smilauer2021", "10.5281/zenodo.5705394"),              # Yade Documentation, 3rd ed.
                "lammps": ("thompson2022", "10.1016/j.cpc.2021.108171"),         # Thompson et al. 2022, CPC 271
                "kratos": ("dadvand2010", "10.1007/s11831-010-9045-2")}          # Dadvand et al. 2010, ACME 17


def bib_fields(text):
    """{key: {field: value}} of every BibTeX entry printed, each entry whole (its braces balanced)."""
    entries = re.findall(r"@(\w+)\{(\w+),\n((?:  \w+ = \{.*\},?\n)+)\}", text)
    assert len(entries) == text.count("\n@") + text.startswith("@")
    assert all(body.count("{") == body.count("}") for _, _, body in entries)
    return {key: dict(re.findall(r"  (\w+) = \{(.*)\}", body)) for _, key, body in entries}


@pytest.mark.engine
def test_cite_lists_each_installed_engine_with_every_version_harness_engines_finds(capfd):
    import json
    assert main(["engines", "--json"]) == 0
    versions = {}
    for row in json.loads(capfd.readouterr().out):
        if "version" in row:
            versions.setdefault(row["engine"], []).append(row["version"])
    assert versions, "no engine is installed"
    assert main(["cite"]) == 0
    fields = bib_fields(capfd.readouterr().out)
    assert set(fields) == {"harness", "thornton2013", "chung2011"} | {PUBLICATIONS[e][0] for e in versions}
    for engine, found in versions.items():
        entry = fields[PUBLICATIONS[engine][0]]
        assert entry["doi"] == PUBLICATIONS[engine][1]
        assert entry["note"] == f"{engine} {', '.join(found)}, installed here (harness engines)"


@needs("liggghts")
def test_cite_of_a_compare_directory_names_the_engines_and_versions_it_ran(tmp_path, capfd):
    out = tmp_path / "out"
    assert main(["compare", "--model", "hertz-mindlin", "--engines", "liggghts", "--en", "0.5", "--angles", "10",
                 "-o", str(out)]) == 0
    ran = pd.read_csv(out / "results.csv")
    version = ran[ran.engine == "liggghts"].engine_version.astype(str).unique()
    capfd.readouterr()
    assert main(["cite", str(out)]) == 0
    fields = bib_fields(capfd.readouterr().out)
    assert set(fields) == {"harness", "thornton2013", "chung2011", "kloss2012"} and len(version) == 1
    assert fields["kloss2012"]["note"] == f"liggghts {version[0]}, as run by harness compare in {out}"
    (tmp_path / "empty").mkdir()
    assert main(["cite", str(tmp_path / "empty")]) == 2
    err = capfd.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "is not a results directory" in err[0]


def test_citation_cff_names_this_version_date_and_address():
    text = (ROOT / "CITATION.cff").read_text()
    top = dict(re.findall(r"^([a-z-]+): \"?([^\"\n]*)\"?$", text, re.M))
    assert top["version"] == harness.__version__
    assert top["date-released"] == RELEASED
    assert top["url"] == PROJECT_URL
    assert os.path.basename(PROJECT_URL) == "harness"


@pytest.mark.parametrize("extra, words", [
    ({"walls": ["steel"]}, "walls[0] is a string ('steel'); expected one of same, rigid"),
    ({"mus": 0.1}, "mus is a float (0.1); expected an array of numbers"),
    ({"targets": [1]}, "targets[0] is an integer (1); expected one of wall, sphere"),
    ({"radii": [0.01], "materials": [{"radius": 0.02, "E": 1e9, "nu": 0.3, "rho": 2500, "mu": 0.3}]},
     "give radius in materials or radii, not both"),
])
def test_a_scene_list_of_the_wrong_kind_is_one_line(extra, words):
    from harness.studies.campaign.spec import from_dict
    from harness.infra.errors import UserError
    with pytest.raises(UserError) as caught:
        from_dict({"laws": ["hertz-mindlin"], **extra})
    assert words in str(caught.value) and "\n" not in str(caught.value)


def test_each_scene_list_reaches_the_requests():
    from harness.studies.campaign.spec import from_dict
    campaign = from_dict({"laws": ["hertz-mindlin"], "mus": [0.1, 0.4], "radii": [0.005, 0.01], "walls": ["rigid"]})
    assert sorted((r.scene.mu, r.scene.radius, r.scene.wall) for r in campaign.requests) == [
        (0.1, 0.005, "rigid"), (0.1, 0.01, "rigid"), (0.4, 0.005, "rigid"), (0.4, 0.01, "rigid")]


@needs("liggghts")
def test_the_deviations_view_is_the_pandas_pairing_of_the_rows(tmp_path):
    """The view `deviations` (DuckDB) gives per mu the worst |e_t(LIGGGHTS) - e_t(paper law)| that pairing the
    store's rows impact by impact in pandas gives."""
    from harness.studies.campaign.driver import run_campaign
    from harness.studies.campaign.executors import InProcess
    from harness.studies.campaign.query import query
    from harness.studies.campaign.spec import from_dict
    from harness.studies.campaign.store import Store
    store = tmp_path / "store"
    for mu in (0.1, 0.3):
        run_campaign(from_dict({"laws": ["hertz-mindlin"], "engines": ["reference", "liggghts"], "e_n": [0.5],
                                "angles": [30.0, 60.0], "mus": [mu], "steps_per_contact": [200]}), store, InProcess())
    worst = query(Store(store, create=False), "SELECT mu, max(d_e_t) AS worst FROM deviations GROUP BY mu")
    assert len(worst) == 2
    assert dict(zip(worst.mu, worst.worst)) == pytest.approx(paired_worst(pd.read_parquet(store), "e_t", "mu"),
                                                             rel=1e-12)
    assert worst.worst.min() > 0


def paired_worst(rows, metric, by):
    """{value(s) of the column or columns `by`: the worst |metric(LIGGGHTS, its formulas) - metric(paper law)|},
    paired impact by impact."""
    mine = rows[(rows.engine == "liggghts") & (rows.dialect == "liggghts") & (rows.status == "ok")]
    paper = rows[(rows.engine == "reference") & (rows.dialect == "paper")]
    pairs = mine.merge(paper, on=["mu", "e_n_target", "theta_deg", "speed"], suffixes=("", "_paper"))
    pairs = pairs.assign(diff=(pairs[metric] - pairs[metric + "_paper"]).abs())
    return pairs.groupby(list(by) if isinstance(by, tuple) else by)["diff"].max().to_dict()
