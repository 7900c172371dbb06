"""One home per sub-model and one registration table: the generated dispatch is the registry's, a missing branch is
an error value and never another law, integrators read capabilities rather than names, and a normal law made up in
this file is one module (this one) and one registration call away from `run` and `--converged`."""
import math
import re
from pathlib import Path

import pytest
from numba import njit

import oracles
from harness.jit import python_twin
from harness.scene import Scene
from harness.solver import dispatch
from harness.solver.extension import FORCE, SIGNATURE, SLOPE
from harness.submodels import generate, registry
from harness.submodels.base import NormalModel, NormalParameters

SOLVER = Path(dispatch.__file__).parent


def test_dispatch_is_generated_from_the_registry():
    """solver/dispatch.py is exactly what `python -m harness.submodels.generate` writes from the registry."""
    assert (SOLVER / "dispatch.py").read_text() == generate.source()


def test_integrators_know_capabilities_not_names():
    """No integrator names a kernel: only dispatch.py (generated) holds the kernels' codes; NONE is the one code an
    integrator may test (no tangential model at all)."""
    named = re.compile(r"\b(NORMAL|TANGENTIAL)_(?!NONE\b|HISTORY\b|RESET\b|VISCOUS\b|IMPLICIT\b|ANY_IMPLICIT\b"
                       r"|LOG_RATE\b)[A-Z_]+")
    for path in SOLVER.glob("*.py"):
        if path.name != "dispatch.py":
            assert not named.search(path.read_text()), (path.name, named.search(path.read_text()).group(0))


def test_a_missing_branch_is_an_error_value_not_another_law():
    ning = registry.code_of("normal", "thornton-ning")        # incremental: it has a step, no force
    hysteresis = registry.code_of("normal", "luding-peak")     # not in the adaptive integrator: no slope
    table = tuple([dispatch_missing()] * registry.EXTENSION_SLOTS)
    normal_force, normal_slope = python_twin(dispatch.normal_force), python_twin(dispatch.normal_slope)
    tangential_stiffness = python_twin(dispatch.tangential_stiffness)
    assert all(math.isnan(x) for x in normal_force(ning, 1.0, 1.0, 0.0, 0.0, 1e-3, 1e-6, 1e-6, table))
    assert all(math.isnan(x) for x in normal_slope(hysteresis, 1.0, 2.0, 1.0, 0.0, 1e-3, 1e-6, True, 1.0, 1e-4,
                                                   table))
    empty = dispatch.N_NORMAL + registry.EXTENSION_SLOTS - 1               # a slot nothing registered
    assert all(math.isnan(x) for x in normal_force(empty, 1.0, 0.0, 0.0, 0.0, 1e-3, 1e-6, 1e-6, table))
    assert math.isnan(tangential_stiffness(dispatch.TANGENTIAL_NONE, 1.0, 1e-4))


def dispatch_missing():
    from harness.solver.extension import missing
    return missing


# ---- a made-up normal law, registered from this file: F = k alpha^2, k from Hertz's peak force at V -----------------
NAME = "quadratic"
ADAPTIVE = True
SLOTS = ("k",)


class Quadratic(NormalModel):
    """F = k alpha^2 (made up for this test), k such that the peak force at V equals elastic Hertz's."""
    name, kernel, plastic = NAME, NAME, False

    def parameters(self, contact, e_n, speed):
        alpha, f = hertz_peak(contact, speed)
        k = f / alpha ** 2
        return NormalParameters.named(f / alpha, 2.0 * alpha / speed, k=k)

    def peak(self, contact, e_n, speed):
        alpha, f = hertz_peak(contact, speed)
        return 2.0 * f / alpha, alpha


def hertz_peak(contact, speed):
    h = oracles.hertz_elastic(contact.mass, contact.radius, contact.E_star, speed)
    return h["alpha_max"], h["f_max"]


@njit(SIGNATURE)
def extension(point, p1, p2, p3, p4, radius, alpha, alpha_max, x, y):
    """FORCE: (k alpha^2, sqrt(R alpha)); SLOPE: (2 k alpha, 1/(2 alpha)); BELOW, RESIDUAL, KINK: 0."""
    if point == FORCE:
        return p1 * alpha * alpha, math.sqrt(radius * alpha)
    if point == SLOPE:
        return 2.0 * p1 * alpha, 0.5 / alpha
    return 0.0, 0.0


@pytest.fixture(scope="module")
def registered():
    if NAME not in registry.NORMAL_MODELS:
        registry.register_normal(Quadratic, __name__)
    return Quadratic


def quadratic_oracle(scene, k):
    """m alpha'' = -k alpha^2 integrated by tests/oracles.py (scipy, no harness code): e = 1, alpha_max =
    (3 m V^2/(2 k))^1/3, and the contact time."""
    c = scene.contact
    return oracles.normal_impact(lambda a, v: k * oracles._ppow(a, 2.0), c.mass, scene.speed)


@pytest.mark.parametrize("mode", ["plain", "converged"])
def test_a_law_registered_from_a_test_file_runs_through_run(registered, mode, tmp_path):
    """`harness run --with normal=quadratic`, plain and --converged: its normal impact against the independent
    integration, and an oblique one that stays finite and loses no energy."""
    import pandas as pd
    from harness.commands import main
    out = tmp_path / "r.csv"
    resolution = ["--converged"] if mode == "converged" else ["--steps-per-contact", "4000"]
    code = main(["run", "--model", "thornton", "--with", "normal=quadratic", "--en", "0.5", "--angles", "0,30",
                 *resolution, "-o", str(out), "--quiet"])
    assert code == 0
    frame = pd.read_csv(out)
    scene = Scene()
    k = Quadratic().parameters(scene.contact, 0.5, scene.speed)["k"]
    oracle = quadratic_oracle(scene, k)
    normal = frame[frame.theta_deg == 0].iloc[0]
    tolerance = 1e-6 if mode == "converged" else 1e-5
    assert normal.e_n == pytest.approx(1.0, abs=tolerance)
    assert normal.t_contact == pytest.approx(oracle["t_c"], rel=tolerance)
    assert normal.f_n_max == pytest.approx(oracle["f_max"], rel=tolerance)
    assert (frame.status == "ok").all() and frame.ke_ratio.max() <= 1.0 + 1e-9
    if mode == "converged":
        assert frame.message.str.startswith("converged: adaptive").all()


# ---- registration refuses a kernel module that lacks what its family needs ----------------------------------------
FUNCTIONS = {name: f"def {name}(*args):\n    return 0.0, 0.0\n" for name in
             ("force", "slope", "below", "step", "stiffness", "spring", "extension")}


def throwaway(tmp_path, monkeypatch, text, *functions):
    """A kernel module written to tmp_path with the constants in `text` and the functions named: its import name."""
    throwaway.count = getattr(throwaway, "count", 0) + 1
    package = tmp_path / f"made_up_kernels_{throwaway.count}"
    package.mkdir()
    (package / "__init__.py").write_text("")
    (package / "kernel.py").write_text(text + "".join(FUNCTIONS[f] for f in functions))
    monkeypatch.syspath_prepend(str(tmp_path))
    return f"{package.name}.kernel"


COMPLETE = 'NAME = "made-up"\nADAPTIVE = True\nSLOTS = ("k", "c")\n'


def test_a_complete_normal_module_is_taken_with_its_slot_names(tmp_path, monkeypatch):
    kernel = registry.normal_kernel(throwaway(tmp_path, monkeypatch, COMPLETE, "force", "slope", "below"))
    assert kernel.slots == ("k", "c") and dict(kernel.functions) == {"force": "force", "below": "below",
                                                                     "slope": "slope"}


@pytest.mark.parametrize("text, functions, missing", [
    (COMPLETE, ("slope",), "function force"),                                  # misspelt or absent force
    (COMPLETE, ("force",), "function slope (ADAPTIVE)"),                       # adaptive without its slope
    ('NAME = "made-up"\nADAPTIVE = True\n', ("force", "slope"), "constant SLOTS"),
    ('ADAPTIVE = False\nSLOTS = ()\n', ("force",), "constant NAME"),
    ('NAME = "made-up"\nSLOTS = ()\n', ("force",), "constant ADAPTIVE"),
    ('NAME = "made-up"\nADAPTIVE = False\nSLOTS = ("a", "b", "c", "d", "e")\n', ("force",), "SLOTS as at most 4"),
    ('NAME = "made-up"\nADAPTIVE = False\nSLOTS = ("a", "a")\n', ("force",), "distinct names"),
    ('NAME = "made-up"\nADAPTIVE = False\nSLOTS = ()\n', ("step",), "constant HISTORY_RESET"),
    ('NAME = "made-up"\nADAPTIVE = False\nSLOTS = ()\nHISTORY_RESET = (0.0,)\n', (), "function step"),
])
def test_a_normal_module_lacking_a_required_point_is_refused_naming_it(tmp_path, monkeypatch, text, functions,
                                                                       missing):
    from harness.errors import UserError
    module = throwaway(tmp_path, monkeypatch, text, *functions)
    with pytest.raises(UserError, match=re.escape(missing)):
        registry.normal_kernel(module)


@pytest.mark.parametrize("points, missing", [
    ({"spring": "spring"}, "dispatch point stiffness"),
    ({"stiffness": "stiffness"}, "dispatch point spring"),
    ({"stiffness": "stiffness", "spring": "sprign"}, "function sprign (its spring)"),
    ({"stiffness": "stiffness", "spring": "spring", "implicit": True}, "dispatch point force_from_w"),
    ({"stiffness": "stiffness", "sping": "spring"}, "no dispatch point sping"),
])
def test_a_tangential_kernel_lacking_a_point_its_capabilities_need_is_refused(tmp_path, monkeypatch, points,
                                                                             missing):
    from harness.errors import UserError
    module = throwaway(tmp_path, monkeypatch, "", "stiffness", "spring")
    with pytest.raises(UserError, match=re.escape(missing)):
        registry.tangential_kernel("made-up", module, **points)


def test_a_viscous_tangential_kernel_needs_no_spring(tmp_path, monkeypatch):
    module = throwaway(tmp_path, monkeypatch, "", "stiffness")
    assert registry.tangential_kernel("made-up", module, stiffness="stiffness", viscous=True).viscous


def test_register_normal_refuses_a_module_or_class_that_is_not_one(tmp_path, monkeypatch):
    from harness.errors import UserError
    before = list(registry.EXTENSIONS)
    with pytest.raises(UserError, match="function extension"):
        registry.register_normal(Quadratic, throwaway(tmp_path, monkeypatch, COMPLETE, "force"))
    with pytest.raises(UserError, match="is not a normal model"):
        registry.register_normal(Quadratic, throwaway(tmp_path, monkeypatch, COMPLETE, "extension"))
    assert registry.EXTENSIONS == before


def test_parameters_named_otherwise_than_the_kernels_slots_are_refused():
    from harness.errors import UserError
    from harness.submodels.normal.hertz import Hertz
    contact = Scene().contact
    assert registry.check_parameters(Hertz(), Hertz().parameters(contact, 0.5, 1.0)) == (contact.E_star, 0.0, 0.0,
                                                                                         0.0)
    with pytest.raises(UserError, match="gives parameters k_n; its kernel hertz takes E_star"):
        registry.check_parameters(Hertz(), NormalParameters.named(1.0, 1.0, k_n=contact.E_star))
