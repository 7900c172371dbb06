"""The catalogue of bad input through the Python API: a keyword of the wrong type is a TypeError naming it, a bad
value a ValueError, both harness.infra.errors.UserError (the line the CLI prints), raised before anything runs; and
`Comparison.ok` holds only when agreement holds for what was asked, as `compare` exits 0."""
import pytest

import harness
from harness.commands import main
from harness.infra.errors import UserError, UserTypeError

BASE = dict(en=[0.5], angles=[10.0])

WRONG_TYPES = [   # (keywords, the keyword the message must name)
    (dict(engines="liggghts"), "engines"), (dict(engines=3), "engines"), (dict(engines=[3]), "engines"),
    (dict(engines=("reference", None)), "engines"),
    (dict(en=0.5), "en"), (dict(en="0.5"), "en"), (dict(en=None), "en"), (dict(en=["0.5"]), "en"),
    (dict(en=[True]), "en"), (dict(en={0.5}), "en"), (dict(en=[[0.5]]), "en"),
    (dict(angles=10), "angles"), (dict(angles="10"), "angles"), (dict(angles=(a for a in [10])), "angles"),
    (dict(psi=1.0, angles=None), "psi"), (dict(vt="1", angles=None), "vt"),
    (dict(wall=None), "wall"), (dict(wall=3), "wall"), (dict(wall={"E": 1e9}), "wall"),
    (dict(dt="1e-7"), "dt"), (dict(dt=[1e-7]), "dt"), (dict(dt=True), "dt"),
    (dict(steps_per_contact="100"), "steps_per_contact"), (dict(steps_per_contact=100.0), "steps_per_contact"),
    (dict(steps_per_contact=True), "steps_per_contact"),
    (dict(converged="no"), "converged"), (dict(converged=1), "converged"), (dict(converged=None), "converged"),
    (dict(material=None), "material"), (dict(material=3), "material"),
    (dict(mu="0.3"), "mu"), (dict(mu=True), "mu"), (dict(radius="0.01"), "radius"), (dict(E="7e10"), "E"),
    (dict(nu=[0.3]), "nu"), (dict(rho="2650"), "rho"), (dict(speed="5"), "speed"),
    (dict(normal_speed="5"), "normal_speed"), (dict(omega0=None), "omega0"), (dict(omega0="5"), "omega0"),
    (dict(gravity=None), "gravity"), (dict(target=3), "target"), (dict(target=None), "target"),
    (dict(target="sphere", target_radius="0.01"), "target_radius"),
    (dict(target="sphere", target_material=None), "target_material"),
    (dict(target="sphere", target_material=3), "target_material"),
    (dict(target="sphere", target_omega="1"), "target_omega"),
    (dict(target="sphere", target_fixed="no"), "target_fixed"),
    (dict(target="sphere", target_fixed=None), "target_fixed"),
    (dict(with_="end=tension"), "with_"), (dict(with_=["end=tension"]), "with_"), (dict(with_=3), "with_"),
    (dict(with_={"end": 3}), "with_"),
    (dict(engine_options="liggghts:limitForce=on"), "engine_options"),
    (dict(engine_options={"liggghts": "limitForce=on"}), "engine_options"),
    (dict(engine_options={"liggghts": {"limitForce": True}}), "engine_options"),
    (dict(engine_options=3), "engine_options"), (dict(engine_options=[("liggghts", "limitForce")]), "engine_options"),
    (dict(tolerances="velocity=0.02"), "tolerances"), (dict(tolerances=3), "tolerances"),
    (dict(tolerances=[3]), "tolerances"), (dict(tolerances={"velocity": "0.02"}), "tolerances"),
    (dict(bogus=1), "bogus"), (dict(overrides={"end": "tension"}), "overrides"),
]
COMPARE_ONLY = ("engines", "engine_options", "tolerances")


def cases(catalogue):
    """Each case through harness.run and harness.compare (engine keywords through compare alone)."""
    for keywords, name in catalogue:
        for call in ("run", "compare"):
            if call == "run" and set(keywords) & set(COMPARE_ONLY):
                continue
            shown = ", ".join(f"{k}=" + ("<generator>" if hasattr(v, "__next__") else repr(v))
                              for k, v in keywords.items())
            yield pytest.param(call, keywords, name, id=f"{call} {shown}"[:90])


@pytest.mark.parametrize("call, keywords, name", list(cases(WRONG_TYPES)))
def test_a_keyword_of_the_wrong_type_is_a_type_error_naming_it(call, keywords, name):
    with pytest.raises(TypeError) as raised:
        getattr(harness, call)("hertz-mindlin", **{**BASE, **keywords})
    assert isinstance(raised.value, UserError) and isinstance(raised.value, ValueError)
    assert name in str(raised.value) and "\n" not in str(raised.value)


@pytest.mark.parametrize("model", [3, None, ["thornton"]])
def test_a_model_that_is_not_a_name_is_a_type_error(model):
    with pytest.raises(UserTypeError, match="model"):
        harness.run(model, **BASE)


WRONG_VALUES = [   # right types, values refused with the bound or the contradiction
    (dict(en=[5e-324]), "en"), (dict(en=[1e-4]), "e_n"), (dict(mu=5e-324), "mu"), (dict(angles=[1e-320]), "angles"),
    (dict(omega0=-1e-310), "omega0"), (dict(dt=5e-324), "dt"), (dict(nu=5e-324), "nu"),
    (dict(normal_speed=5.0, angles=[89.9]), "tangential speeds"),
    (dict(target="sphere", target_radius=1e308), "target radius"),
    (dict(target="sphere", target_material="E=5e-324,nu=0.3,rho=1000"), "target-material E"),
    (dict(wall="E=1e308,nu=0.3"), "wall E"),
    (dict(engines=["liggghts", "liggghts"]), "--engines"),
    (dict(engines=["reference"], engine_options={"reference": {"foo": "bar"}}), "reference option"),
    (dict(engines=["yade"], engine_options={"liggghts": {"limitForce": "on"}}), "liggghts"),
]


@pytest.mark.parametrize("call, keywords, name", list(cases(WRONG_VALUES)))
def test_a_bad_value_is_a_value_error_not_a_type_error(call, keywords, name):
    with pytest.raises(ValueError) as raised:
        getattr(harness, call)("hertz-mindlin", **{**BASE, **keywords})
    assert isinstance(raised.value, UserError) and not isinstance(raised.value, TypeError)
    assert name in str(raised.value) and "\n" not in str(raised.value)


def test_numbers_of_any_real_type_are_taken_as_floats():
    """numpy scalars and arrays, ints and tuples are numbers and lists of numbers, as the CLI's floats are."""
    import numpy as np
    from harness.runs.request import Request
    request = Request.from_keywords("hertz-mindlin", en=np.array([0.5]), angles=(10,), mu=np.float32(0.25),
                                    speed=2, steps_per_contact=np.int64(200))
    assert request.scene.e_n == (0.5,) and request.scene.angles_deg == (10.0,) and request.resolution == 200
    assert type(request.scene.mu) is float and request.scene.mu == 0.25 and type(request.scene.speed) is float


def test_a_comparison_is_not_ok_when_the_only_engine_asked_for_was_skipped(tmp_path, capfd):
    """LIGGGHTS is nowhere here (tests not marked `engine` see no engine): asked for alone, it is skipped, nothing
    is compared, and neither `ok` nor the command's exit code may say agreement."""
    comparison = harness.compare("hertz-mindlin", engines=["liggghts"], **BASE)
    assert comparison.skipped and not comparison.engines
    assert comparison.ok is False
    code = main(["compare", "--model", "hertz-mindlin", "--engines", "liggghts", "--en", "0.5", "--angles", "10",
                 "-o", str(tmp_path / "out"), "--quiet"])
    assert code == 3


def test_a_comparison_is_not_ok_when_nothing_was_compared():
    """Every engine by default, none installed: nothing compared, not ok (compare exits 3)."""
    comparison = harness.compare("hertz-mindlin", **BASE)
    assert not comparison.engines and comparison.ok is False


def test_a_comparison_of_the_reference_alone_is_ok(tmp_path):
    """The reference alone (or no engine) was asked for: no engine's agreement is in question (compare exits 0)."""
    assert harness.compare("hertz-mindlin", engines=["reference"], **BASE).ok is True
    assert harness.compare("hertz-mindlin", engines=[], **BASE).ok is True
    assert main(["compare", "--model", "hertz-mindlin", "--engines", "reference", "--en", "0.5", "--angles", "10",
                 "-o", str(tmp_path / "out"), "--quiet"]) == 0
