"""What the report's figures show: a panel per e_n even when every impact lies beyond the paper's Psi1* window
(steep angles alone), with the count of impacts not drawn."""
import math

import matplotlib
import pytest

from harness.commands import main

matplotlib.use("Agg")


def psi1_star(theta_deg, e_n, mu=0.1):
    """The paper's Psi1* of an impact without spin: 2 V_t / (mu (1 + e) V_n) = 2 tan(theta) / (mu (1 + e))."""
    return 2.0 * math.tan(math.radians(theta_deg)) / (mu * (1.0 + e_n))


@pytest.mark.parametrize("angles", ["60", "65,71,77"])
def test_steep_angles_alone_draw_a_panel_per_e_n_that_counts_what_lies_beyond(tmp_path, capfd, angles):
    """At 60 deg and beyond every impact of the paper's scene has Psi1* > 14 (23 at 60 deg and e_n 0.5): the report
    still draws each e_n's panel, saying how many impacts lie beyond the window, and compare exits 0."""
    thetas = [float(a) for a in angles.split(",")]
    e_ns = (0.5, 0.9)
    assert min(psi1_star(t, e) for t in thetas for e in e_ns) > 14.0
    out = tmp_path / "out"
    code = main(["compare", "--model", "hertz-mindlin", "--engines", "reference", "--en", "0.5,0.9", "--angles",
                 angles, "--steps-per-contact", "200", "-o", str(out)])
    assert code == 0, capfd.readouterr()
    words = f"{len(thetas)} impact{'s' if len(thetas) > 1 else ''} beyond Psi1* = 14 not drawn"
    for name in ("psi2", "omega", "e_t"):
        svg = (out / "figures" / f"hertz-mindlin-{name}-vs-psi1.svg").read_text()
        assert svg.count(words) == len(e_ns), name
        assert all(f"e_n = {e:g}" in svg for e in e_ns)
