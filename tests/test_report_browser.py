"""The HTML report in a real headless browser (Debian chromium via Selenium): no console errors, every figure
rendered at a real size, the tables hold the expected rows; a screenshot is saved."""
import os
import subprocess
import sys

import pytest

CHROMIUM, DRIVER = "/usr/bin/chromium", "/usr/bin/chromedriver"
pytestmark = pytest.mark.skipif(not (os.path.exists(CHROMIUM) and os.path.exists(DRIVER)),
                                reason="Debian chromium and chromium-driver are not installed")


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
    images = browser.find_elements(By.TAG_NAME, "img")
    assert len(images) >= 5                                  # four per-law figures and the force curves
    for image in images:
        width, height, complete = browser.execute_script(
            "return [arguments[0].naturalWidth, arguments[0].naturalHeight, arguments[0].complete];", image)
        assert complete and width > 300 and height > 150
    headings = [h.text for h in browser.find_elements(By.TAG_NAME, "h2")]
    agreement = headings.index("Agreement: engine against its dialect at equal time step")
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


def test_rebuilding_the_report_simulates_nothing(report, monkeypatch):
    """`harness report DIR` reads the directory only: the kernel and every engine are made to fail, and the
    rebuilt report still holds the same tables and figures."""
    import harness.engines.runner as runner
    import harness.solver.reference as reference
    from harness.views.html import rebuild

    def forbidden(*args, **kwargs):
        raise AssertionError("report rebuilding must not simulate")
    monkeypatch.setattr(reference, "integrate", forbidden)
    monkeypatch.setattr(reference, "simulate", forbidden)
    monkeypatch.setattr(runner.subprocess, "Popen", forbidden)
    before = (report / "report.html").read_text()
    (report / "report.html").unlink()
    after = open(rebuild(str(report))).read()
    assert after.count("data:image/png;base64,") == before.count("data:image/png;base64,") >= 5
    for heading in ("Agreement: engine against its dialect", "Attribution:", "Normal impact against elastic Hertz"):
        assert heading in after
