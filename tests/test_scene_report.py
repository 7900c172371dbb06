"""A scene run's page (scene.html) and its files: every check row on the page with the verdict counted from
checks.csv, the checks not applicable with their reasons, a figure per case, the page rebuilt by `harness report DIR`
from the files alone, and the energy drawn checked against a sphere's energy computed here."""
import json
import math
import re

import numpy as np
import pandas as pd
import pytest

from harness.commands import main
from harness.views.scene_html import specific_energy

GLASS = ["--E", "70e9", "--nu", "0.3", "--rho", "2650"]


@pytest.fixture(scope="module")
def bounce_dir(tmp_path_factory):
    """A Hertz bounce (its checks not applicable) and a linear one, each run once for the module."""
    out = {}
    for law in ("hertz-mindlin", "linear-spring-dashpot"):
        directory = tmp_path_factory.mktemp(law) / "out"
        code = main(["run", "--model", law, "--scene", "bounce", "--scene-param", "height=0.01", "--scene-param",
                     "bounces=2", "--radius", "1e-3", "--en", "0.5,0.8", *GLASS, "-o",
                     str(directory)])
        assert code == 0
        out[law] = directory
    return out


def page_text(directory):
    return (directory / "scene.html").read_text()


def test_the_page_holds_every_check_row_and_the_verdict_counted_from_checks_csv(bounce_dir):
    directory = bounce_dir["linear-spring-dashpot"]
    checks, html = pd.read_csv(directory / "checks.csv"), page_text(directory)
    assert len(checks) == 8 and checks.passed.all()
    assert "Every check passes: 8 of 8." in html
    for case in checks.case:
        assert f"<td>{case}</td>" in html
    assert len(re.findall(r"<figure>", html)) == 2          # one per case: e_n 0.5 and 0.8
    assert (directory / "figures" / "scene-bounce-e_n-0.5.svg").is_file()


def test_checks_not_applicable_are_on_the_page_with_their_reason(bounce_dir):
    directory = bounce_dir["hertz-mindlin"]
    described = json.loads((directory / "scene.json").read_text())
    assert set(described["not_applicable"]) == {"rebound-speed-ratio", "apex-height"}
    html = page_text(directory)
    assert "No closed-form check applies to this law on this scene." in html
    for reason in described["not_applicable"].values():
        assert reason.replace("'", "&#39;") in html


def test_report_rebuilds_the_page_from_the_files_alone(bounce_dir, capfd):
    directory = bounce_dir["linear-spring-dashpot"]
    before = page_text(directory)
    (directory / "scene.html").unlink()
    assert main(["report", str(directory)]) == 0
    assert capfd.readouterr().out.strip() == f"wrote {directory / 'scene.html'}"

    def words(text):
        """The page without its date and with each figure's SVG as one token (matplotlib's ids are random)."""
        return re.sub(r"<svg.*?</svg>", "INLINE-SVG", re.sub(r"\d{4}-\d\d-\d\d \d\d:\d\d", "DATE", text), flags=re.S)
    assert words(page_text(directory)) == words(before)
    assert words(before).count("INLINE-SVG") == 2


def test_the_energy_drawn_is_the_spheres_kinetic_rotational_and_gravitational_energy_per_mass():
    """Two bodies at two times: (vx^2 + vz^2)/2 + g z + (2/5 R^2 w^2)/2 each, summed per time."""
    radius, g = 0.01, 9.81
    frame = pd.DataFrame({"t": [0.0, 0.0, 1.0, 1.0], "body": [0, 1, 0, 1], "z": [0.1, 0.3, 0.2, 0.0],
                          "vx": [1.0, 0.0, 2.0, 0.5], "vz": [0.0, -1.0, 1.0, 0.0], "w": [10.0, 0.0, 0.0, 50.0]})
    energy = specific_energy(frame, radius, g)

    def one(z, vx, vz, w):
        return 0.5 * (vx * vx + vz * vz) + g * z + 0.5 * 0.4 * radius ** 2 * w * w
    assert energy.to_numpy() == pytest.approx([one(0.1, 1.0, 0.0, 10.0) + one(0.3, 0.0, -1.0, 0.0),
                                               one(0.2, 2.0, 1.0, 0.0) + one(0.0, 0.5, 0.0, 50.0)], rel=1e-15)


def test_energy_in_free_flight_stays_constant_as_newton_says(bounce_dir):
    """Before the first touch the bounce is a free fall: its energy per mass stays g h0 + g R to 1e-9."""
    directory = bounce_dir["linear-spring-dashpot"]
    series = pd.read_csv(directory / "series.csv")
    first = series[series.case == series.case.iloc[0]]
    flying = first[first.z > 1e-3 + 1e-6]
    flying = flying[flying.t < flying.t[flying.vz > 0].min()] if (flying.vz > 0).any() else flying
    energy = specific_energy(flying, 1e-3, 9.81).to_numpy()
    assert len(energy) > 10
    assert np.abs(energy / (9.81 * (0.01 + 1e-3)) - 1.0).max() < 1e-9
    assert math.isfinite(energy[0])
