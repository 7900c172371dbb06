"""The paper's setting by default: the tcc13 scene, its normalisation, the linear law's equal-duration calibration,
--normal-speed, and `harness paper` (its tables against closed forms and independent integrations)."""
import math
import subprocess
import sys

import numpy as np
import pandas as pd
import pytest
from scipy.optimize import brentq

import oracles
from harness.laws import compose
from harness.scenes.materials import get_material
from harness.scenes.scene import Scene
from harness.solver.simulate import simulate


def test_the_paper_scene_is_the_default():
    """Thornton, Cummins & Cleary (2013) as Kratos and LIGGGHTS-PFM give it: R 25 mm, E 70 GPa, nu 0.3, rho 2650,
    mu 0.1, a wall of the same material, 5 m/s, e_n 0.25/0.5/0.75/0.9."""
    scene, preset = Scene(), get_material("tcc13")
    assert (scene.radius, scene.E, scene.nu, scene.rho, scene.mu, scene.speed) == (0.025, 70e9, 0.3, 2650.0, 0.1, 5.0)
    assert (preset.radius, preset.E, preset.nu, preset.rho, preset.mu) == (0.025, 70e9, 0.3, 2650.0, 0.1)
    assert scene.e_n == (0.25, 0.5, 0.75, 0.9) and scene.wall == "same" and scene.material == "tcc13"
    assert scene.contact.E_star == pytest.approx(70e9 / (2 * (1 - 0.09)), rel=1e-15)


def test_linear_law_lasts_as_long_as_elastic_hertz():
    """k_n = m (pi/t_H)^2: at e_n = 1 the linear spring's contact equals the elastic Hertz duration at the scene
    speed (closed form, oracles.hertz_elastic), and its damped contacts end as Schwager & Poeschel's no-tension
    oscillator does (oracles.lsd_notension_t_c)."""
    scene = Scene(e_n=(1.0, 0.5), angles_deg=(0.0,))
    c = scene.contact
    hertz = oracles.hertz_elastic(c.mass, c.radius, c.E_star, scene.speed)
    frame = simulate(compose("linear-spring-dashpot"), scene, converged=True)[0]
    assert frame.t_contact.iloc[0] == pytest.approx(hertz["t_c"], rel=1e-6)
    w0 = math.pi / hertz["t_c"]
    g = oracles.lsd_notension_g(0.5)
    assert frame.t_contact.iloc[1] == pytest.approx(oracles.lsd_notension_t_c(g, w0), rel=1e-6)


def test_kt_over_kn_is_kappa_with_the_normal_dashpots_ratio():
    """The paper's linear law: k_t = kappa k_n (0.8235 at nu 0.3), c_t = 2 g sqrt(m k_t) with the normal g."""
    from harness.solver import layout as L
    from harness.solver.simulate import batch_at
    scene = Scene(e_n=(0.5,), angles_deg=(30.0,))
    params = batch_at(compose("linear-spring-dashpot"), scene, 0.5, 1000).params[0]
    k_n, c_n = params[L.NORMAL_LINEAR_K_N], params[L.DAMPING_C0]
    assert params[L.TANGENTIAL_LINEAR_K_T] == pytest.approx(2 * 0.7 / 1.7 * k_n, rel=1e-15)
    g = c_n / (2 * math.sqrt(scene.contact.mass * k_n))
    k_t = params[L.TANGENTIAL_LINEAR_K_T]
    prefactor = params[L.TANGENTIAL_DAMPING_PREFACTOR]
    assert prefactor * math.sqrt(k_t) == pytest.approx(2 * g * math.sqrt(scene.contact.mass * k_t))


def test_tangential_dashpot_options():
    """'sphere-mass': c_t = 2 g sqrt(m_t k_t) with m_t = m/(1 + m R^2/I) = 2/7 m for a solid sphere on a wall;
    'classical': g_t = -ln e/sqrt(ln^2 e + pi^2); 'total' and the default 'spring-first' set the kernel's Coulomb
    test; an unknown option is one line of bad input."""
    from harness.infra.errors import UserError
    from harness.solver import layout as L
    from harness.solver.simulate import batch_at
    scene = Scene(e_n=(0.5,), angles_deg=(30.0,))
    plain = batch_at(compose("linear-spring-dashpot"), scene, 0.5, 1000).params[0]
    law = compose("linear-spring-dashpot", {"tangential-damping": "classical:total:sphere-mass"})
    params = batch_at(law, scene, 0.5, 1000).params[0]
    beta = -math.log(0.5) / math.sqrt(math.log(0.5) ** 2 + math.pi ** 2)
    prefactor = params[L.TANGENTIAL_DAMPING_PREFACTOR]
    assert prefactor == pytest.approx(2 * beta * math.sqrt(2.0 / 7.0 * scene.contact.mass), rel=1e-12)
    assert (plain[L.TANGENTIAL_DAMPING_CONE], params[L.TANGENTIAL_DAMPING_CONE]) == (0.0, 1.0)
    assert law.describe()["tangential-damping"] == "classical:total:sphere-mass"
    assert compose("hertz-mindlin").describe()["tangential-damping"] == "normal-ratio"
    with pytest.raises(UserError, match="options are"):
        compose("hertz-mindlin", {"tangential-damping": "normal-ratio:heavy"})


def test_normal_speed_holds_v_n_as_kratos_does():
    scene = Scene(e_n=(0.5,), angles_deg=(0.0, 30.0, 60.0), speed_is="normal")
    v_n, v_t, _, theta = scene.impacts(0.5)
    assert np.all(v_n == 5.0) and np.allclose(v_t, 5.0 * np.tan(np.radians([0, 30, 60])), rtol=1e-15)
    assert list(theta) == [0.0, 30.0, 60.0]
    resultant = Scene(e_n=(0.5,), angles_deg=(60.0,))
    assert np.hypot(*resultant.impacts(0.5)[:2])[0] == pytest.approx(5.0)


def harness(*args, cwd=None):
    return subprocess.run([sys.executable, "-m", "harness", *args], capture_output=True, text=True, cwd=cwd,
                          timeout=600)


@pytest.fixture(scope="module")
def paper_dir(tmp_path_factory):
    out = tmp_path_factory.mktemp("paper")
    proc = harness("paper", "--laws", "thornton,linear-spring-dashpot,partially-latching-spring",
                   "--steps-per-contact", "1000", "-o", str(out))
    assert proc.returncode == 0, proc.stderr
    (out.parent / "paper-stdout.txt").write_text(proc.stdout)
    return out


def test_paper_writes_its_tables_and_page(paper_dir):
    oblique = pd.read_csv(paper_dir / "paper.csv")
    assert set(oblique.model) == {"thornton", "linear-spring-dashpot", "partially-latching-spring",
                                  "hertz-mindlin (elastic)"}
    assert (oblique.v_n0 == 5.0).all() and oblique.psi1_star.max() == pytest.approx(14.0, rel=1e-3)
    assert set(oblique[oblique.model == "thornton"].e_n_target) == {0.25, 0.5, 0.75, 0.9}
    html = (paper_dir / "paper.html").read_text()
    assert html.count("<svg") == 4 and "provisional" in html
    assert "partially-latching-spring</b>" in html                 # named among the reconstructed laws


def test_paper_prints_and_writes_the_distance_from_the_published_points(paper_dir):
    """The linear law's distances per e_n and quantity (the page's table too), the points overlaid on its figure;
    none for the laws the paper's published curves do not cover."""
    published = pd.read_csv(paper_dir / "paper-published.csv")
    assert set(published.model) == {"linear-spring-dashpot"} and len(published) == 12
    assert set(published.quantity) == {"psi2_star", "omega_star", "e_t"} and (published.points >= 8).all()
    stdout = (paper_dir.parent / "paper-stdout.txt").read_text()
    assert "distance from the paper's published points (e_t's x10)" in stdout
    assert "every law, e_n and quantity within the goal" in stdout
    html = (paper_dir / "paper.html").read_text()
    assert 'id="published"' in html and "paper-published.csv" in html and "Kratos Multiphysics" in html
    assert html.count('id="published-points') == 3 * 4


def test_paper_normal_impacts_match_independent_integrations(paper_dir):
    """Thornton's contact duration and peak force against elastic Hertz, from oracles.thornton_impact (scipy, no
    harness code), at e_n 0.5 and 0.25."""
    normal = pd.read_csv(paper_dir / "paper-normal.csv")
    c, v = Scene().contact, 5.0
    hertz = oracles.hertz_elastic(c.mass, c.radius, c.E_star, v)
    for e in (0.5, 0.25):
        r = brentq(lambda x: oracles.thornton_e(1.0, x) - e, 1e-12, 1.0 - 1e-12, xtol=1e-15)   # V_y/V
        p_y = (r * r * v * v * c.E_star ** 4 * c.rho * 40.0 / math.pi ** 4) ** 0.2
        oracle = oracles.thornton_impact(p_y, c.E_star, c.radius, c.mass, v)
        row = normal[(normal.model == "thornton") & (normal.e_n_target == e)].iloc[0]
        assert row["t_c/t_Hertz"] == pytest.approx(oracle["t_c"] / hertz["t_c"], rel=1e-4)
        assert row["F_max/F_Hertz"] == pytest.approx(oracle["f_max"] / hertz["f_max"], rel=1e-4)


def test_paper_sliding_table_agrees_with_its_conditions(paper_dir):
    """Each threshold within its bracket (+1e-5) of its condition; the kernel's search (the linear law, whose
    tangential dashpot keeps it off the adaptive integrator) may find it lower by a stick hidden in its last step."""
    sliding = pd.read_csv(paper_dir / "paper-sliding.csv")
    assert len(sliding) == 12
    low = np.where(sliding.method.str.startswith("kernel"), 5e-5, sliding.resolution + 1e-5)
    assert ((sliding.difference >= -low) & (sliding.difference <= sliding.resolution + 1e-5)).all()


def test_paper_refuses_an_unknown_law(tmp_path):
    proc = harness("paper", "--laws", "nonsense", "-o", str(tmp_path / "p"))
    assert proc.returncode == 2 and proc.stderr.count("\n") == 1 and "unknown law" in proc.stderr
    assert not (tmp_path / "p").exists()


def test_paper_labels_its_first_table_and_says_in_words_where_a_law_never_slides(tmp_path):
    """Walton-Braun's spring never reaches the cone (docs/laws.md#sliding-throughout): its rows say so in words, under
    a heading that names the table; no 'nan' anywhere in what paper prints."""
    proc = harness("paper", "--laws", "walton-braun,thornton", "--steps-per-contact", "200", "-o", str(tmp_path))
    assert proc.returncode == 0, proc.stderr
    lines = proc.stdout.splitlines()
    assert lines[0].startswith("where each law slides throughout") and "nan" not in proc.stdout.lower()
    rows = [line.split() for line in lines if line.strip().startswith(("walton-braun", "thornton"))]
    assert len(rows) == 8
    assert all(row[2:] == ["none", "<=", "40", "no", "condition", "-"] for row in rows if row[0] == "walton-braun")
    sliding = pd.read_csv(tmp_path / "paper-sliding.csv").set_index(["model", "e_n_target"])
    for row in (r for r in rows if r[0] == "thornton"):
        assert float(row[2]) == pytest.approx(sliding.loc[("thornton", float(row[1]))].simulated, abs=5e-5)


def test_paper_page_gives_contact_times_and_peak_forces_to_four_figures(paper_dir):
    """The page's table of normal impacts holds each contact time (about 1e-4 s) as paper-normal.csv does, to 4
    significant figures (it once rounded them to 0.0001 or 0.0002)."""
    from html.parser import HTMLParser

    class Cells(HTMLParser):
        rows, inside = [], False

        def handle_starttag(self, tag, attrs):
            self.inside = self.inside or ("id", "normal") in attrs
            if self.inside and tag == "tr":
                self.rows.append([])

        def handle_data(self, data):
            if self.inside and self.rows and data.strip():
                self.rows[-1].append(data.strip())

        def handle_endtag(self, tag):
            self.inside = self.inside and tag != "table"
    page = Cells()
    page.feed((paper_dir / "paper.html").read_text())
    head, body = page.rows[0], page.rows[1:]
    assert "contact time [s]" in head and "peak force [N]" in head and len(body) == 12
    normal = pd.read_csv(paper_dir / "paper-normal.csv").set_index(["model", "e_n_target"])
    for row in body:
        expected = normal.loc[(row[0], float(row[1]))]
        assert float(row[head.index("contact time [s]")]) == pytest.approx(expected.t_contact, rel=1e-3)
        assert float(row[head.index("peak force [N]")]) == pytest.approx(expected.f_n_max, rel=1e-3)
