"""The structure of the package: data walks one way (nothing below a command imports a command, lower layers do
not import higher ones), no import cycles, small modules, package data where a plain install finds it."""
import ast
import inspect
import pathlib

import pytest

import harness

PACKAGE = pathlib.Path(harness.__file__).parent


def imports_of(path, package=None):
    """Absolute names of the harness modules a file imports (at any depth, lazily or not)."""
    parts = path.relative_to((package or PACKAGE).parent).with_suffix("").parts
    package = ".".join(parts[:-1])
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
    """(name, path) of every module of the package; a package by its own name."""
    for path in sorted(PACKAGE.rglob("*.py")):
        parts = path.relative_to(PACKAGE.parent).with_suffix("").parts
        yield ".".join(parts[:-1] if parts[-1] == "__init__" else parts), path


def test_nothing_below_a_command_imports_a_command():
    offenders = [(name, sorted(i for i in imports_of(path) if i.startswith("harness.commands")))
                 for name, path in modules() if not name.startswith("harness.commands") and name != "harness.__main__"]
    assert not [o for o in offenders if o[1]], offenders


FLOORS = {"infra": 0, "scenes": 1, "submodels": 1, "data": 2, "laws": 2, "solver": 3, "engines": 4, "analyses": 4,
          "runs": 5, "studies": 6, "views": 7, "api": 8, "commands": 9}
# infra: files, errors, compiling; scenes and sub-models; the tables and shipped data, the laws; the solver; the
# engines and the analyses (neither imports the other); runs: request, plan, execute, outputs; studies: calibration,
# cost, campaigns, verification; views; the Python API; the command line


def root_entries(package=None):
    """The package root's entries (caches aside)."""
    return sorted(p.name for p in (package or PACKAGE).iterdir() if p.name != "__pycache__")


def test_the_root_holds_a_few_subpackages_named_by_their_role():
    entries = root_entries()
    assert len(entries) <= 15, entries
    assert set(entries) == {"__init__.py", "__main__.py", *FLOORS}, set(entries) ^ {"__init__.py", "__main__.py",
                                                                                     *FLOORS}


def floor_breaks(package=None):
    """[(module, the module it imports on its own floor or above)] over every subpackage of FLOORS."""
    package = package or PACKAGE
    breaks = []
    for path in sorted(package.rglob("*.py")):
        parts = path.relative_to(package.parent).with_suffix("").parts
        if len(parts) < 3 or parts[1] not in FLOORS:
            continue
        name = ".".join(parts)
        for target in sorted(imports_of(path, package)):
            floor = target.split(".")[1] if target.count(".") else ""
            if floor in FLOORS and floor != parts[1] and FLOORS[floor] >= FLOORS[parts[1]]:
                breaks.append((name, target))
    return breaks


def test_no_import_runs_back_up_a_floor():
    """Every subpackage imports only from the floors below its own (FLOORS), at any depth, lazily or not."""
    assert not floor_breaks()


def test_the_floor_check_sees_an_upward_import(tmp_path):
    """The check above fails on an infra module importing the plan, even inside a function."""
    root = tmp_path / "harness"
    (root / "infra").mkdir(parents=True)
    (root / "infra" / "files.py").write_text("def f():\n    from ..runs.plan import Run\n")
    assert floor_breaks(root) == [("harness.infra.files", "harness.runs.plan"),
                                  ("harness.infra.files", "harness.runs.plan.Run")]


@pytest.mark.parametrize("layer", ["harness.analyses", "harness.views", "harness.submodels", "harness.solver",
                                   "harness.laws"])
def test_lower_layers_do_not_import_the_layers_above(layer):
    """Analyses and views read tables (the plan runs, analyses read its results, a view asks no engine or solver:
    only the colours engines declare); sub-models, the solver and the laws know nothing of plans, engines or
    outputs."""
    running = ("harness.runs.execute", "harness.runs.plan", "harness.engines", "harness.solver.simulate",
               "harness.solver.batch", "harness.studies.cost_plan", "harness.studies.cost_truth",
               "harness.studies.cost_estimate", "harness.studies.sliding_search", "harness.studies.paper")
    beside = ("harness.runs.plan", "harness.engines", "harness.analyses", "harness.views", "harness.api",
              "harness.runs.outputs")
    above = {"harness.analyses": ("harness.views", "harness.api", "harness.runs.outputs") + running,
             "harness.views": ("harness.api",) + running,
             "harness.submodels": beside, "harness.solver": beside, "harness.laws": beside}[layer]
    offenders = {name: sorted(i for i in imports_of(path) if i.startswith(above)
                              and not i.startswith("harness.engines.styles"))
                 for name, path in modules() if name.startswith(layer)}
    assert not {k: v for k, v in offenders.items() if v}


ENGINE_NAMES = ("liggghts", "yade", "lammps", "kratos")


@pytest.mark.parametrize("layer", ["solver", "submodels"])
def test_no_engine_is_named_in_the_solver_or_the_submodels(layer):
    """The solver and the sub-models say what they compute, never whose code computes it: no engine name in their
    code, docstrings or comments (an engine's knowledge lives in its subpackage and docs/<engine>-dialect.md)."""
    found = [f"{path.relative_to(PACKAGE)}:{number}: {line.strip()}"
             for path in sorted((PACKAGE / layer).rglob("*.py"))
             for number, line in enumerate(path.read_text().splitlines(), 1)
             if any(name in line.lower() for name in ENGINE_NAMES)]
    assert not found, "\n".join(found)


def test_the_engine_name_check_sees_a_comment(tmp_path):
    """The check above fails on an engine named in a comment of a module of its layer."""
    layer = tmp_path / "solver"
    layer.mkdir()
    (layer / "step.py").write_text("x = 1   # as Yade does\n")
    globals()["PACKAGE"], saved = tmp_path, PACKAGE
    try:
        with pytest.raises(AssertionError, match="step.py:1"):
            test_no_engine_is_named_in_the_solver_or_the_submodels("solver")
    finally:
        globals()["PACKAGE"] = saved


def test_modules_stay_small():
    sizes = {name: len(path.read_text().splitlines()) for name, path in modules()}
    assert max(sizes.values()) <= 400, sorted(sizes.items(), key=lambda kv: -kv[1])[:3]


def test_the_committed_baseline_ships_with_the_package():
    from harness.studies.baseline import BASELINE_FILE, DEFAULT_BASELINE
    shipped = pathlib.Path(DEFAULT_BASELINE) / BASELINE_FILE
    committed = PACKAGE.parent / "baselines" / BASELINE_FILE
    assert shipped.is_file()
    if committed.is_file():                      # from a checkout: the same bytes
        assert shipped.read_bytes() == committed.read_bytes()


def test_public_api_is_run_and_compare():
    assert inspect.signature(harness.run).parameters["model"]
    assert {"model", "engines", "engine_options"} <= set(inspect.signature(harness.compare).parameters)


def import_graph():
    """{module: the harness modules it imports}, an attribute import counted as an import of its module."""
    known = dict(modules())

    def module_of(name):
        while name and name not in known:
            name = name.rpartition(".")[0]
        return name
    graph = {}
    for name, path in known.items():
        graph[name] = {module_of(i) for i in imports_of(path)} - {"", name}
    return graph


def test_no_import_cycles():
    """Not even through an import inside a function: every module can be understood from the ones below it."""
    graph = import_graph()
    state, cycles = {}, []

    def visit(node, path):
        state[node] = "open"
        for nxt in sorted(graph[node]):
            if state.get(nxt) == "open":
                cycles.append(path[path.index(nxt):] + [nxt])
            elif nxt not in state:
                visit(nxt, path + [nxt])
        state[node] = "done"
    for node in sorted(graph):
        if node not in state:
            visit(node, [node])
    assert not cycles, "\n".join(" -> ".join(c) for c in cycles[:5])
