"""A compiled internal function carries no Python wrapper (harness/infra/jit.py): Python calling it would jump to a null
address. So no plain Python function of harness calls one; tests go through harness.infra.jit.python_twin."""
import ast
import importlib
import importlib.util
import pkgutil
import types
from pathlib import Path

from numba.core.registry import CPUDispatcher

import harness

COMPILED_DECORATORS = {"compiled", "njit", "jit"}


def unwrapped(value):
    """A compiled function Python cannot call."""
    return isinstance(value, CPUDispatcher) and bool(value.targetoptions.get("no_cpython_wrapper"))


def resolve(expression, namespace):
    """The object a call's target names in the module's namespace (a name, or attributes of a module), else None."""
    if isinstance(expression, ast.Name):
        return namespace.get(expression.id)
    if isinstance(expression, ast.Attribute):
        owner = resolve(expression.value, namespace)
        return getattr(owner, expression.attr, None) if isinstance(owner, types.ModuleType) else None
    return None


def compiled_function(node):
    names = {ast.unparse(d.func if isinstance(d, ast.Call) else d).rpartition(".")[2] for d in node.decorator_list}
    return bool(names & COMPILED_DECORATORS)


def local_imports(function, module):
    """The names a function imports itself (`from .dispatch import f` inside it)."""
    names = {}
    for node in ast.walk(function):
        if isinstance(node, ast.ImportFrom):
            source = importlib.import_module("." * node.level + (node.module or ""), module.__package__)
            for alias in node.names:
                names[alias.asname or alias.name] = getattr(source, alias.name, None)
    return names


def python_calls_to_unwrapped(module):
    """(function, call target) of every call, in the module's plain Python functions, of an unwrapped compiled one."""
    found = []
    for node in ast.walk(ast.parse(Path(module.__file__).read_text())):
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)) and not compiled_function(node):
            namespace = {**vars(module), **local_imports(node, module)}
            for call in ast.walk(node):
                if isinstance(call, ast.Call) and unwrapped(resolve(call.func, namespace)):
                    found.append((node.name, ast.unparse(call.func)))
    return found


def test_no_python_function_calls_a_compiled_internal():
    modules = [importlib.import_module(m.name) for m in pkgutil.walk_packages(harness.__path__, "harness.")
               if not m.name.endswith("__main__")]
    assert len(modules) > 100
    found = {m.__name__: calls for m in modules if (calls := python_calls_to_unwrapped(m))}
    assert found == {}


def test_the_check_finds_such_a_call(tmp_path):
    """Positive control: a Python function reading k_t through the compiled dispatch (what the stability check did)."""
    source = tmp_path / "reads_k_t.py"
    source.write_text("from harness.solver import dispatch\n\n\n"
                      "def k_t(code, p1, a):\n    from harness.solver.dispatch import tangential_stiffness\n"
                      "    return tangential_stiffness(code, p1, a)\n\n\n"
                      "def k_t_again(code, p1, a):\n    return dispatch.tangential_stiffness(code, p1, a)\n")
    spec = importlib.util.spec_from_file_location("reads_k_t", source)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    assert python_calls_to_unwrapped(module) == [("k_t", "tangential_stiffness"),
                                                 ("k_t_again", "dispatch.tangential_stiffness")]


PYTHON_CALL = """
import math
from harness.infra.jit import python_twin
from harness.solver.spring import mean_radius
from harness.submodels.coulomb import clip
print(python_twin(mean_radius)(1.0, 1.0), flush=True)
try:
    clip(2.0, 1.0)
except TypeError as error:
    print(f"TypeError: {error}", flush=True)
"""


def test_a_python_call_of_a_compiled_function_raises_naming_its_twin():
    """Calling a compiled function from Python raises a one-line TypeError naming python_twin (it used to jump to a
    null address: exit 139). In a subprocess, so that a segfault fails this test, not the run; its compiled callers
    still work (the kernel integrates a batch first)."""
    import subprocess
    import sys
    script = ("import numpy as np\nfrom harness.laws import compose\nfrom harness.scenes.scene import Scene\n"
              "from harness.solver.simulate import simulate\n"
              "frame = simulate(compose('hertz-mindlin'), Scene(e_n=(0.5,), angles_deg=(30.0,)), 100)[0]\n"
              "print('status', frame.status.iloc[0], flush=True)\n" + PYTHON_CALL)
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=900)
    assert done.returncode == 0, (done.returncode, done.stderr[-2000:])
    lines = done.stdout.splitlines()
    assert lines[0] == "status ok" and float(lines[1]) == 1.0
    assert lines[2] == ("TypeError: clip is compiled for compiled callers only (no Python wrapper); from Python call "
                        "harness.infra.jit.python_twin(clip)")
