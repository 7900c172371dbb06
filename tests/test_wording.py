"""Sentences harness builds count and compare properly: one impact is "1 impact" and its verb agrees, a loss is said
as less (never "-0.19 more"), and a worst case claims only what holds at its impact."""
import pytest

import harness
from harness.analyses.findings import findings
from harness.analyses.physics import engine_physics
from harness.views.terminal import physics_phrase
from harness.infra.wording import counted, more_or_less, verb


def test_counts_verbs_and_signed_amounts():
    assert [counted(n, "impact") for n in (0, 1, 2)] == ["0 impacts", "1 impact", "2 impacts"]
    assert counted(1, "copy", "copies") == "1 copy" and counted(3, "copy", "copies") == "3 copies"
    assert [verb(1, "ends"), verb(2, "ends"), verb(2, "passes"), verb(2, "has")] == ["ends", "end", "pass", "have"]
    assert more_or_less(0.006) == "0.006 more" and more_or_less(-0.19) == "0.19 less"
    assert more_or_less(-75.0, "%") == "75% less"


def as_engine(frame, name="kratos"):
    """The paper law's rows again as an engine's own run (engine and dialect `name`)."""
    return frame.assign(engine=name, dialect=name)


@pytest.fixture(scope="module")
def normal_impact():
    """One normal impact at e_n 0.5: it keeps e_n^2 = 0.25 of its kinetic energy (no tangential motion)."""
    paper = harness.run("hertz-mindlin", en=[0.5], angles=[0], steps_per_contact=500)
    return paper.assign(engine="reference", dialect="paper")


def test_a_loss_of_energy_is_said_as_less_and_one_impact_in_the_singular(normal_impact):
    import pandas as pd
    physics = engine_physics(pd.concat([normal_impact, as_engine(normal_impact)]), "kratos")
    energy = next(c for c in physics["checks"] if c["check"] == "energy")
    assert energy["text"].startswith("ends with 75% less total kinetic energy than it began with")
    assert physics_phrase(physics).endswith("every check holds on 1 impact")


def test_a_sticking_worst_case_does_not_claim_the_paper_law_slides(normal_impact):
    """At normal impact |J_t| = 0 x mu J_n: the Coulomb check's worst case, but the paper law does not slide there."""
    import pandas as pd
    physics = engine_physics(pd.concat([normal_impact, as_engine(normal_impact)]), "kratos")
    coulomb = next(c for c in physics["checks"] if c["check"] == "coulomb")
    assert coulomb["passed"] and coulomb["text"].startswith("tangential impulse 0 x mu J_n (1 below Coulomb's bound)")


@pytest.mark.parametrize("angles", [[40], [40, 50]])
def test_impacts_short_of_the_coulomb_bound_are_counted_with_their_verb(angles):
    """At 40 and 50 deg (Psi1* 11 and 16, beyond the Hertz-Mindlin threshold 6.3 at e_n 0.5) the paper law slides
    throughout; an engine keeping 5% of the tangential velocity change back transmits less than mu J_n."""
    import pandas as pd
    paper = harness.run("hertz-mindlin", en=[0.5], angles=angles, steps_per_contact=500).assign(
        engine="reference", dialect="paper")
    short = as_engine(paper).assign(v_t1=lambda f: f.v_t1 - 0.05 * (f.v_t1 - f.v_t0))
    found = findings(pd.concat([paper, short]))
    detail = found[found.kind == "Coulomb bound from below"].detail.iloc[0]
    one = len(angles) == 1
    assert detail.startswith(f"{len(angles)} impact{'' if one else 's'} the paper law slides throughout "
                             f"transmit{'s' if one else ''} less than mu J_n")


def test_compare_verbose_prints_no_nan(tmp_path, capfd):
    """Hertz-Mindlin has no derived sliding condition (docs/laws.md#sliding-throughout): its cells say '-' under a
    heading that says what '-' means, never 'nan'."""
    from harness.commands import main
    assert main(["compare", "--model", "hertz-mindlin", "--engines", "reference", "--en", "0.5", "--angles", "0,30",
                 "--steps-per-contact", "200", "--verbose", "-o", str(tmp_path / "out")]) == 0
    out = capfd.readouterr().out
    assert "nan" not in out.lower() and "'-': none found, or no condition derived" in " ".join(out.split())
