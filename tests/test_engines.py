"""The engine registry and the layers: every engine implements the declared protocol; data walks one way (nothing
below a command imports a command, analyses and views import no engine runner)."""
import ast
import inspect
import pathlib

import pytest

import harness
from harness.engines import ENGINES, EXTERNAL, get_engine
from harness.engines.protocol import Engine, Option, Status
from harness.errors import UserError
from harness.laws import LAWS

PACKAGE = pathlib.Path(harness.__file__).parent
PROTOCOL = [name for name, value in vars(Engine).items() if not name.startswith("_") and callable(value)]
DECLARED = list(Engine.__annotations__)


@pytest.mark.parametrize("name", list(ENGINES))
def test_every_engine_implements_the_protocol(name):
    engine = ENGINES[name]
    missing = [attr for attr in PROTOCOL + DECLARED if not hasattr(engine, attr)]
    assert not missing, f"{name} lacks {missing}"
    assert engine.NAME == name
    assert all(isinstance(o, Option) and o.default == o.values[0] for o in engine.OPTIONS.values())
    for attr in PROTOCOL:
        assert callable(getattr(engine, attr)), attr
    assert set(engine.MODELS) <= set(LAWS)
    for law in LAWS:
        status = engine.status(law)
        assert isinstance(status, Status) and status.name == name
        if status.available:
            assert engine.supports(law) and engine.dialect(law, {}).name == law
        else:
            assert status.reason, (name, law)


def test_the_reference_is_an_engine_that_runs_every_law():
    reference = ENGINES["reference"]
    assert reference.available() and all(reference.supports(law) for law in LAWS)
    assert "reference" not in EXTERNAL and set(EXTERNAL) == set(ENGINES) - {"reference"}


@pytest.mark.parametrize("name", EXTERNAL)
def test_undeclared_options_are_one_line_user_errors(name):
    engine = ENGINES[name]
    law = next(iter(engine.MODELS))
    with pytest.raises(UserError, match=f"unknown {name} option 'colour'"):
        engine.dialect(law, {"colour": "red"})
    key, option = next(iter(engine.OPTIONS.items()))
    with pytest.raises(UserError, match=f"{name} option {key} takes {' or '.join(option.values)}"):
        engine.dialect(law, {key: "no-such-value"})


def test_an_unknown_engine_names_the_known_ones():
    with pytest.raises(UserError, match="unknown engine 'abaqus'; known: reference, liggghts, yade"):
        get_engine("abaqus")


def imports_of(path):
    """Absolute names of the harness modules a file imports (at any depth, lazily or not)."""
    module = ".".join(path.relative_to(PACKAGE.parent).with_suffix("").parts)
    package = module if path.name == "__init__.py" else module.rsplit(".", 1)[0]
    package = package.removesuffix(".__init__")
    found = set()
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.ImportFrom):
            if node.level:
                base = package.split(".")[:len(package.split(".")) - node.level + 1]
                target = ".".join(base + ([node.module] if node.module else []))
            else:
                target = node.module or ""
            found |= {target} | {f"{target}.{alias.name}" for alias in node.names}
        elif isinstance(node, ast.Import):
            found |= {alias.name for alias in node.names}
    return {name for name in found if name.startswith("harness")}


def modules():
    for path in sorted(PACKAGE.rglob("*.py")):
        yield ".".join(path.relative_to(PACKAGE.parent).with_suffix("").parts), path


def test_nothing_below_a_command_imports_a_command():
    offenders = [(name, sorted(i for i in imports_of(path) if i.startswith("harness.commands")))
                 for name, path in modules() if not name.startswith("harness.commands") and name != "harness.__main__"]
    assert not [o for o in offenders if o[1]], offenders


@pytest.mark.parametrize("layer", ["harness.analyses", "harness.views", "harness.submodels", "harness.solver",
                                   "harness.laws"])
def test_lower_layers_do_not_import_the_layers_above(layer):
    """Analyses and views read tables; sub-models, the solver and the laws know nothing of plans, engines or
    outputs (cost is the analysis that builds its own plans)."""
    above = {"harness.analyses": ("harness.views", "harness.api", "harness.outputs"),
             "harness.views": ("harness.api", "harness.execute", "harness.plan", "harness.engines.batches"),
             "harness.submodels": ("harness.plan", "harness.engines", "harness.analyses", "harness.views",
                                   "harness.api", "harness.outputs"),
             "harness.solver": ("harness.plan", "harness.engines", "harness.analyses", "harness.views", "harness.api",
                                "harness.outputs"),
             "harness.laws": ("harness.plan", "harness.engines", "harness.analyses", "harness.views", "harness.api",
                              "harness.outputs")}[layer]
    offenders = {name: sorted(i for i in imports_of(path) if i.startswith(above))
                 for name, path in modules() if name.startswith(layer)}
    assert not {k: v for k, v in offenders.items() if v}


def test_modules_stay_small():
    sizes = {name: len(path.read_text().splitlines()) for name, path in modules()}
    assert max(sizes.values()) <= 400, sorted(sizes.items(), key=lambda kv: -kv[1])[:3]


def test_the_committed_baseline_ships_with_the_package():
    from harness.baseline import BASELINE_FILE, DEFAULT_BASELINE
    shipped = pathlib.Path(DEFAULT_BASELINE) / BASELINE_FILE
    committed = PACKAGE.parent / "baselines" / BASELINE_FILE
    assert shipped.is_file()
    if committed.is_file():                      # from a checkout: the same bytes
        assert shipped.read_bytes() == committed.read_bytes()


def test_public_api_is_run_and_compare():
    assert inspect.signature(harness.run).parameters["model"]
    assert {"model", "engines", "engine_options"} <= set(inspect.signature(harness.compare).parameters)
