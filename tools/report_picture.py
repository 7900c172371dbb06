"""The README's picture of the report: its top (the summary and the contents) in headless Debian chromium, as a PNG.

    .venv/bin/python tools/report_picture.py harness-out docs/report.png
"""
import sys
import tempfile
from pathlib import Path

from selenium import webdriver
from selenium.webdriver.chrome.service import Service

CHROMIUM, DRIVER = "/usr/bin/chromium", "/usr/bin/chromedriver"
WIDTH, HEIGHT = 1300, 1000


def picture(report_dir, out):
    options = webdriver.ChromeOptions()
    options.binary_location = CHROMIUM
    with tempfile.TemporaryDirectory(prefix="harness-chromium-") as profile:
        for flag in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-dev-shm-usage",
                     f"--window-size={WIDTH},{HEIGHT}", f"--user-data-dir={profile}"):
            options.add_argument(flag)
        driver = webdriver.Chrome(service=Service(DRIVER), options=options)
        try:
            driver.get(Path(report_dir, "report.html").resolve().as_uri())
            driver.save_screenshot(str(out))
        finally:
            driver.quit()


if __name__ == "__main__":
    picture(sys.argv[1], sys.argv[2])
