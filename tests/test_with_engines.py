"""`--with KEY=VALUE` reaches an engine: its inputs follow the replaced sub-model where they have a setting for it
(Engine.WITH), and the engine still agrees with its dialect, which carries the replacement; elsewhere the engine is
refused with the reason (named in --engines) or skipped with it (not named)."""
import pytest

from conftest import agreement, needs
from harness import compare
from harness.commands import main
from harness.engines import ENGINES
from harness.infra.errors import UserError

SCENE = dict(en=[0.5], angles=[10, 40], omega0=-50.0)


@pytest.mark.parametrize("engine,law,key,value,options", [
    ("liggghts", "hertz-mindlin", "tangential-damping", "none", {"tangential_damping": "off"}),
    ("liggghts", "linear-spring-dashpot", "end", "no-tension", {"limitForce": "on"}),
    ("liggghts", "walton-braun", "end", "no-tension", {}),                  # its dialect has it already
    ("lammps", "hertz-mindlin", "tangential-damping", "none", {"with:tangential-damping": "none"}),
])
def test_a_replacement_maps_to_the_engine_options_whose_dialect_carries_it(engine, law, key, value, options):
    found = ENGINES[engine]
    assert found.with_options(law, {key: value}) == options
    assert found.dialect(law, options).describe()[key] == value != found.dialect(law).describe()[key] or not options


@pytest.mark.parametrize("engine,law,key,value", [
    ("liggghts", "thornton", "tangential-damping", "none"),               # thornton_ning ignores tangential_damping
    ("yade", "hertz-mindlin", "tangential-damping", "none"),
    ("lammps", "hertz-mindlin", "end", "no-tension"),
])
def test_a_replacement_its_inputs_cannot_compute_is_refused_with_the_reason(engine, law, key, value):
    with pytest.raises(UserError, match=f"{engine} cannot follow --with {key}={value}: its {law} inputs have no "):
        ENGINES[engine].with_options(law, {key: value})


def test_a_replacement_clashing_with_an_engine_option_given_is_refused():
    with pytest.raises(UserError, match="needs liggghts option tangential_damping=off, not on"):
        ENGINES["liggghts"].with_options("hertz-mindlin", {"tangential-damping": "none"}, {"tangential_damping": "on"})


@needs("liggghts")
@needs("lammps")
@pytest.mark.parametrize("engine,law", [("liggghts", "hertz-mindlin"), ("lammps", "hertz-mindlin"),
                                        ("lammps", "linear-spring-dashpot")])
def test_the_engine_follows_the_replacement_and_agrees_with_its_dialect(engine, law):
    """The oracle is the engine itself: its run with the replacement agrees with the replaced dialect to round-off,
    and differs from its run without it (the replacement is not decoration)."""
    plain = compare(law, engines=[engine], **SCENE).results
    replaced = compare(law, engines=[engine], with_={"tangential-damping": "none"}, **SCENE).results
    assert agreement(replaced[replaced.dialect == engine], engine) < 1e-6
    runs = [frame[frame.engine == engine].reset_index(drop=True) for frame in (plain, replaced)]
    assert (runs[0].v_t1 - runs[1].v_t1).abs().max() > 1e-4


@needs("yade")
def test_an_engine_named_that_cannot_follow_is_one_line_and_2(tmp_path, capsys):
    assert main(["compare", "--model", "hertz-mindlin", "--engines", "yade", "--en", "0.5", "--angles", "10",
                 "--with", "tangential-damping=none", "-o", str(tmp_path)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert err == ["harness: error: yade cannot follow --with tangential-damping=none: its hertz-mindlin inputs have "
                   "no setting that computes it (docs/yade-dialect.md)"]


@needs("yade")
def test_an_engine_not_named_that_cannot_follow_is_skipped_with_the_reason():
    result = compare("hertz-mindlin", with_={"tangential-damping": "none"}, en=[0.5], angles=[10])
    assert dict(result.skipped)["yade"].startswith("yade cannot follow --with tangential-damping=none")
    assert "yade" not in set(result.results.engine)
