"""The HTML report in a real headless browser (Debian chromium via Selenium): no console errors, every figure
rendered at a real size, the tables hold the expected rows; a screenshot is saved."""
import os
import subprocess
import sys

import pytest

CHROMIUM, DRIVER = "/usr/bin/chromium", "/usr/bin/chromedriver"
pytestmark = [pytest.mark.engine,         # the report of a comparison with every engine that is installed
              pytest.mark.skipif(not (os.path.exists(CHROMIUM) and os.path.exists(DRIVER)),
                                 reason="Debian chromium and chromium-driver are not installed")]


@pytest.fixture(scope="module")
def report(tmp_path_factory):
    out = tmp_path_factory.mktemp("report")
    proc = subprocess.run([sys.executable, "-m", "harness", "compare", "--model", "hertz-mindlin", "--en",
                           "0.5,0.1", "--angles", "0,30,60", "-o", str(out)], capture_output=True, text=True,
                          timeout=600)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    return out


@pytest.fixture(scope="module")
def browser(tmp_path_factory):
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service
    options = webdriver.ChromeOptions()
    options.binary_location = CHROMIUM
    for flag in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                 "--disable-background-networking", "--disable-component-update", "--disable-sync",
                 "--window-size=1300,2000", f"--user-data-dir={tmp_path_factory.mktemp('chromium')}"):
        options.add_argument(flag)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    driver = webdriver.Chrome(service=Service(DRIVER), options=options)
    yield driver
    driver.quit()


def test_report_renders_figures_and_tables_without_errors(report, browser):
    from selenium.webdriver.common.by import By
    browser.get(f"file://{report / 'report.html'}")
    assert "hertz-mindlin" in browser.title
    severe = [entry for entry in browser.get_log("browser") if entry["level"] == "SEVERE"]
    assert severe == []
    figures = browser.find_elements(By.CSS_SELECTOR, "figure > svg")
    assert len(figures) >= 5                                  # four per-law figures and the force curves
    for figure in figures:
        assert figure.size["width"] > 300 and figure.size["height"] > 150
    headings = [h.text for h in browser.find_elements(By.TAG_NAME, "h2")]
    agreement = headings.index("Agreement: engine against its own formulas at equal time step")
    table = browser.find_elements(By.XPATH, f"(//h2)[{agreement + 1}]/following-sibling::table[1]//tr")
    from harness.engines import ENGINES, EXTERNAL
    engines = [name for name in EXTERNAL if ENGINES[name].available()]
    assert len(table) - 1 == 3 * len(engines)                 # v_n1, v_t1, omega1 per engine
    assert all("True" in row.text for row in table[1:])
    facts = browser.find_elements(
        By.XPATH, f"(//h2)[{headings.index('Run facts') + 1}]/following-sibling::table[1]//tr")
    import pandas as pd
    results = pd.read_csv(report / "results.csv")
    runs = results.groupby(["engine", "dialect"]).agg(n=("wall_s", "size"), steps=("steps_per_contact", "first"))
    assert len(facts) - 1 == len(runs) == 1 + 2 * len(engines)    # paper law, and per engine its run and dialect
    for row in facts[1:]:
        cells = [c.text for c in row.find_elements(By.TAG_NAME, "td")]
        expected = runs.loc[(cells[0], cells[1])]
        assert int(cells[4]) == expected.steps and int(cells[7]) == expected.n
        assert "double" in cells[3] and float(cells[9]) > 0           # arithmetic stated, wall time measured
    shot = report / "report.png"
    browser.save_screenshot(str(shot))
    assert shot.stat().st_size > 10000


def test_report_opens_with_the_verdict_per_engine_and_where_everything_is(report, browser):
    """The summary box comes first: the physics verdict, one row per engine with its version, whether it reproduces
    the paper law (an engine whose rebound velocities differ from the paper law's by more than 1% of V, recomputed
    here from results.csv, deviates), its agreement, worst difference and tolerance as results.csv gives them, the
    scene, the command line and a link to every file beside it."""
    from selenium.webdriver.common.by import By
    import numpy as np
    import pandas as pd
    from harness.analyses.agreement import AGREEMENT_TOLERANCE
    browser.get(f"file://{report / 'report.html'}")
    summary = browser.find_element(By.ID, "summary")
    first = browser.find_element(By.XPATH, "//body/*[2]")
    assert first.get_attribute("id") == "summary"                    # right under the title
    results = pd.read_csv(report / "results.csv")
    paper = results[results.dialect == "paper"].set_index("theta_deg e_n_target".split())
    speed = np.hypot(paper.v_n0, paper.v_t0)
    far = {e for e in results.engine.unique() if e != "reference" and max(
        ((results[results.engine == e].set_index(paper.index.names)[m] - paper[m]) * (paper.radius if m == "omega1"
         else 1) / speed).abs().max() for m in ("v_n1", "v_t1", "omega1")) > 0.01}
    headline = summary.find_element(By.CLASS_NAME, "verdict").text
    assert far and "do not reproduce the paper law" in headline or "does not reproduce" in headline
    assert "each engine computes its own formulas" in headline and "agree" not in summary.get_attribute("class")
    rows = summary.find_elements(By.XPATH, ".//table//tr")[1:]
    engines = sorted(e for e in results.engine.unique() if e != "reference")
    assert sorted(r.find_elements(By.TAG_NAME, "td")[0].text for r in rows) == engines
    for row in rows:
        cells = [c.text for c in row.find_elements(By.TAG_NAME, "td")]
        assert cells[1] == str(results[results.engine == cells[0]].engine_version.iloc[0])
        assert cells[2] in ("deviates", "marginal") if cells[0] in far else cells[2] in ("deviates", "marginal",
                                                                                          "reproduces")
        agreement, worst = cells[4].split(" (")
        assert agreement == "agrees" and float(worst.split()[0]) < AGREEMENT_TOLERANCE
        assert float(worst.rstrip(")").split("; ")[1]) == AGREEMENT_TOLERANCE
    text = summary.text
    assert "harness compare --model hertz-mindlin" in text and "radius 25 mm" in text and "70 GPa" in text
    links = {a.get_attribute("href").rsplit("/", 1)[1] for a in summary.find_elements(By.TAG_NAME, "a")
             if a.get_attribute("href").startswith("file:")}
    assert {"results.csv", "run.json", "attribution.csv"} <= links
    assert all((report / name).exists() for name in links)
    contents = [a.get_attribute("href").rsplit("#", 1)[1] for a in browser.find_elements(By.CSS_SELECTOR, "nav a")]
    assert contents and all(browser.find_elements(By.ID, anchor) for anchor in contents)


def test_rebuilding_the_report_simulates_nothing(report, monkeypatch):
    """`harness report DIR` reads the directory only: the kernel and every engine are made to fail, and the
    rebuilt report still holds the same tables and figures."""
    import harness.engines.runner as runner
    import harness.solver.simulate as simulation
    from harness.views.html import rebuild

    def forbidden(*args, **kwargs):
        raise AssertionError("report rebuilding must not simulate")
    monkeypatch.setattr(simulation, "integrate", forbidden)
    monkeypatch.setattr(simulation, "simulate", forbidden)
    monkeypatch.setattr(runner.subprocess, "Popen", forbidden)
    before = (report / "report.html").read_text()
    (report / "report.html").unlink()
    after = open(rebuild(str(report))).read()
    assert after.count("<figure><svg") == before.count("<figure><svg") >= 5
    for heading in ("Agreement: engine against its own formulas", "Attribution, one ingredient",
                    "Normal impact against elastic Hertz"):
        assert heading in after


def test_the_report_does_not_scroll_sideways_at_1300_px(report, browser):
    """The window is 1300 px wide: the page is no wider than the window (a wide table scrolls inside its own box),
    and every figure fits the page."""
    browser.get(f"file://{report / 'report.html'}")
    page, window = browser.execute_script(
        "return [document.documentElement.scrollWidth, document.documentElement.clientWidth]")
    assert window <= 1300 and page <= window, (page, window)
    right = browser.execute_script("return Math.max(...Array.from(document.querySelectorAll('figure > svg'))"
                                   ".map(e => e.getBoundingClientRect().right))")
    assert right <= window
