"""One home per sub-model and one registration table: the generated modules are the registry's, a missing branch is
an error value and never another law, integrators read capabilities rather than names and call every sub-model
through the generated dispatch, a normal law made up in this file is one module (this one) and one registration
call away from `run` and `--converged`, and a made-up Coulomb rule is one module and one registry line away from
`harness run --with coulomb=...`."""
import math
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from numba import njit

import oracles
from harness.infra.jit import python_twin
from harness.scenes.scene import Scene
from harness.solver import dispatch, layout
from harness.solver.extension import FORCE, SIGNATURE, SLOPE
from harness.submodels import generate, registry
from harness.submodels.base import NormalModel, NormalParameters
from harness.submodels.families import FAMILIES

SOLVER = Path(dispatch.__file__).parent
GENERATED = ("dispatch.py", "layout.py", "switches.py")


def test_the_solver_modules_are_generated_from_the_registry():
    """solver/dispatch.py, layout.py and switches.py are exactly what `python -m harness.submodels.generate`
    writes from the registry."""
    for name, text in generate.sources().items():
        assert (SOLVER / name).read_text() == text, name
    assert set(generate.sources()) == set(GENERATED)


def solver_sources():
    """(name, text) of the solver's hand-written modules."""
    return [(path.name, path.read_text()) for path in sorted(SOLVER.glob("*.py")) if path.name not in GENERATED]


def test_integrators_know_capabilities_not_names():
    """No hand-written solver module names a sub-model's code (dispatch.py holds them, generated); NONE is the one
    code an integrator may test (no tangential model at all)."""
    codes = {f"{generate.ident(f)}_{generate.ident(k.name)}" for f in FAMILIES for k in registry.kernels(f)}
    codes.discard("TANGENTIAL_NONE")
    for name, text in solver_sources():
        named = sorted(codes & set(re.findall(r"\b[A-Z][A-Z0-9_]*\b", text)))
        assert not named, (name, named)


def test_no_stepper_branches_by_hand_on_a_sub_model_code():
    """A row's sub-model codes reach the solver's steppers only through the generated dispatch and capability
    tables: no hand-written module compares a code column with anything but TANGENTIAL_NONE."""
    compared = re.compile(r"I_(NORMAL|END|TANGENTIAL|INTEGRATOR|COULOMB|GEOMETRY|TOUCH)\]\s*[=!]=\s*"
                          r"(?![\s]|TANGENTIAL_NONE)")
    for name, text in solver_sources():
        assert not compared.search(text), (name, compared.search(text).group(0))


def test_the_check_sees_a_hand_written_branch():
    """Positive control of the two checks above: a branch on the Coulomb rule's code, named or numbered."""
    codes = {f"{generate.ident(f)}_{generate.ident(k.name)}" for f in FAMILIES for k in registry.kernels(f)}
    text = "if ints[L.I_COULOMB] == COULOMB_TOTAL:\n    pass\n"
    assert "COULOMB_TOTAL" in codes & set(re.findall(r"\b[A-Z][A-Z0-9_]*\b", text))
    assert re.search(r"I_(COULOMB)\]\s*[=!]=\s*(?![\s]|TANGENTIAL_NONE)", text)


def test_no_positional_parameter_slots_are_left():
    """Kernels take their slots by name: no p1..p4 argument in the solver or the sub-models, no hand-numbered P_
    column."""
    for path in sorted((SOLVER.parent / "solver").glob("*.py")) + sorted((SOLVER.parent / "submodels").rglob("*.py")):
        text = path.read_text()
        assert not re.search(r"\bp[1-4]\b", text), path
        assert not re.search(r"\bP_[A-Z]", text), path


def test_each_kernel_slot_has_its_named_column_in_its_family_block():
    """layout.FAMILY_KERNEL_SLOT is the family block's first column plus the slot's place in the kernel's SLOTS."""
    for family in FAMILIES:
        start, end = layout.BLOCKS[family], getattr(layout, f"{generate.ident(family)}_BLOCK_END")
        for kernel in registry.BUILT_IN[family]:
            for k, slot in enumerate(kernel.slots):
                name = f"{generate.ident(family)}_{generate.ident(kernel.name)}_{generate.ident(slot)}"
                column = getattr(layout, name)
                assert column == start + k < end


def test_a_missing_branch_is_an_error_value_not_another_law():
    ning = registry.code_of("normal", "thornton-ning")        # incremental: it has a step, no force
    hysteresis = registry.code_of("normal", "luding-peak")     # not in the adaptive integrator: no slope
    table = tuple([dispatch_missing()] * registry.EXTENSION_SLOTS)
    p = np.zeros(layout.N_PARAMS)
    p[layout.NORMAL_BLOCK:layout.NORMAL_BLOCK + 3] = 1.0, 2.0, 1.0
    normal_force, normal_slope = python_twin(dispatch.normal_force), python_twin(dispatch.normal_slope)
    tangential_stiffness = python_twin(dispatch.tangential_stiffness)
    assert all(math.isnan(x) for x in normal_force(ning, p, 1e-3, 1e-6, 1e-6, table))
    assert all(math.isnan(x) for x in normal_slope(hysteresis, p, 1e-3, 1e-6, True, 1.0, 1e-4, table))
    empty = dispatch.N_NORMAL + registry.EXTENSION_SLOTS - 1               # a slot nothing registered
    assert all(math.isnan(x) for x in normal_force(empty, p, 1e-3, 1e-6, 1e-6, table))
    assert math.isnan(tangential_stiffness(dispatch.TANGENTIAL_NONE, p, 1e-4))
    beyond = len(registry.kernels("coulomb"))                              # a Coulomb code nothing registered
    f_t, f_s, cut = python_twin(dispatch.coulomb_cap)(beyond, p, 1.0, 0.0, 0.0, 0.0, 2.0)
    assert math.isnan(f_t) and math.isnan(f_s) and not cut


def dispatch_missing():
    from harness.solver.extension import missing
    return missing


# ---- a made-up normal law, registered from this file: F = k alpha^2, k from Hertz's peak force at V -----------------
NAME = "quadratic"
SUMMARY = "F = k alpha^2 (made up for this test)"
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
def extension(point, slots, radius, alpha, alpha_max, x, y):
    """FORCE: (k alpha^2, sqrt(R alpha)); SLOPE: (2 k alpha, 1/(2 alpha)); BELOW, RESIDUAL, KINK: 0. k: slots[0]."""
    k = slots[0]
    if point == FORCE:
        return k * alpha * alpha, math.sqrt(radius * alpha)
    if point == SLOPE:
        return 2.0 * k * alpha, 0.5 / alpha
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


# ---- registration refuses a kernel module that lacks what its family needs -----------------------------------------
def function(name, parameters="*args"):
    return f"def {name}({parameters}):\n    return 0.0, 0.0\n"


def throwaway(tmp_path, monkeypatch, text):
    """A kernel module written to tmp_path holding `text`: its import name."""
    throwaway.count = getattr(throwaway, "count", 0) + 1
    package = tmp_path / f"made_up_kernels_{throwaway.count}"
    package.mkdir()
    (package / "__init__.py").write_text("")
    (package / "kernel.py").write_text(text)
    monkeypatch.syspath_prepend(str(tmp_path))
    return f"{package.name}.kernel"


HEAD = 'NAME = "made-up"\nSUMMARY = "made up"\n'
NORMAL = HEAD + 'ADAPTIVE = True\nSLOTS = ("k", "c")\n'
FORCE_KC, SLOPE_KC = function("force", "k, c, radius, alpha, alpha_max"), function("slope", "k, c, *rest")


def test_a_complete_normal_module_is_taken_with_its_slot_names(tmp_path, monkeypatch):
    module = throwaway(tmp_path, monkeypatch, NORMAL + FORCE_KC + SLOPE_KC + function("below", "k, c, alpha"))
    kernel = registry.kernel_module("normal", module)
    assert kernel.slots == ("k", "c") and set(kernel.functions) == {"force", "below", "slope"} and kernel.adaptive


@pytest.mark.parametrize("family, text, missing", [
    ("normal", NORMAL + SLOPE_KC, "function force"),                                  # misspelt or absent force
    ("normal", NORMAL + FORCE_KC, "function slope (ADAPTIVE)"),                       # adaptive without its slope
    ("normal", NORMAL + function("force", "c, k, *rest") + SLOPE_KC, "function force taking its SLOTS k, c first"),
    ("normal", HEAD + 'ADAPTIVE = True\n' + function("force") + function("slope"), "constant SLOTS"),
    ("normal", 'SUMMARY = "x"\nADAPTIVE = False\nSLOTS = ()\n' + function("force"), "constant NAME"),
    ("normal", 'NAME = "x"\nADAPTIVE = False\nSLOTS = ()\n' + function("force"), "constant SUMMARY"),
    ("normal", HEAD + 'SLOTS = ()\n' + function("force"), "constant ADAPTIVE (bool)"),
    ("normal", HEAD + 'ADAPTIVE = False\nSLOTS = ("a", "b", "c", "d", "e")\n' + function("force"),
     "SLOTS as at most 4"),
    ("normal", HEAD + 'ADAPTIVE = False\nSLOTS = ("a", "a")\n' + function("force"), "distinct names"),
    ("normal", HEAD + 'ADAPTIVE = False\nSLOTS = ()\n' + function("step"), "constant HISTORY_RESET"),
    ("normal", HEAD + 'ADAPTIVE = False\nSLOTS = ()\nHISTORY_RESET = (0.0,)\n', "function step"),
    ("tangential", HEAD + 'SLOTS = ("k",)\n' + function("spring", "k, *rest"), "function stiffness"),
    ("tangential", HEAD + 'SLOTS = ("k",)\n' + function("stiffness", "k, a"), "function spring"),
    ("tangential", HEAD + 'SLOTS = ("k",)\nIMPLICIT = True\n' + function("stiffness", "k, a")
     + function("spring", "k, *rest"), "function force_from_w (IMPLICIT)"),
    ("tangential", HEAD + 'SLOTS = ("k", "g")\nVISCOUS = True\n' + function("stiffness", "k, g, a"),
     "SLOTS as at most 1"),
    ("tangential", HEAD + 'SLOTS = ("k",)\nVISCOUS = 1\n' + function("stiffness", "k, a"), "constant VISCOUS (bool)"),
    ("coulomb", HEAD + 'SLOTS = ()\n' + function("cpa"), "function cap"),
    ("coulomb", HEAD + 'SLOTS = ("factor",)\n' + function("cap", "factor, *rest"), "function parameters(law, scene)"),
    ("touch", HEAD + 'SLOTS = ()\n', "function contact"),
    ("end", HEAD + 'SLOTS = ()\n' + function("clip"), "constant PULLS (bool)"),
    ("integrator", HEAD + 'SLOTS = ()\n', "constant EXPLICIT (bool)"),
    ("geometry", 'NAME = "made-up"\nSLOTS = ()\n', "constant SUMMARY"),
])
def test_a_module_lacking_what_its_family_needs_is_refused_naming_it(tmp_path, monkeypatch, family, text, missing):
    """One made-up module per refusal, each refused with a line naming what it lacks."""
    from harness.infra.errors import UserError
    module = throwaway(tmp_path, monkeypatch, text)
    with pytest.raises(UserError, match=re.escape(missing)) as refused:
        registry.kernel_module(family, module)
    assert str(refused.value).startswith(f"{family} kernel module {module} lacks") and "\n" not in str(refused.value)


def test_a_viscous_tangential_module_needs_no_spring(tmp_path, monkeypatch):
    module = throwaway(tmp_path, monkeypatch, HEAD + 'SLOTS = ("k",)\nVISCOUS = True\n' + function("stiffness", "k, a"))
    assert registry.kernel_module("tangential", module).viscous


def test_register_normal_refuses_a_module_or_class_that_is_not_one(tmp_path, monkeypatch):
    from harness.infra.errors import UserError
    before = list(registry.EXTENSIONS)
    with pytest.raises(UserError, match="function extension"):
        registry.register_normal(Quadratic, throwaway(tmp_path, monkeypatch, NORMAL + FORCE_KC))
    with pytest.raises(UserError, match="is not a normal model"):
        registry.register_normal(Quadratic, throwaway(tmp_path, monkeypatch, NORMAL + function("extension")))
    assert registry.EXTENSIONS == before


def test_parameters_named_otherwise_than_the_kernels_slots_are_refused():
    from harness.infra.errors import UserError
    from harness.submodels.normal.hertz import Hertz
    contact = Scene().contact
    assert registry.check_parameters(Hertz(), Hertz().parameters(contact, 0.5, 1.0)) == (contact.E_star,)
    with pytest.raises(UserError, match="gives parameters k_n; its kernel hertz takes E_star"):
        registry.check_parameters(Hertz(), NormalParameters.named(1.0, 1.0, k_n=contact.E_star))


# ---- a made-up Coulomb rule: one module and one registry line ------------------------------------------------------
DOUBLED = '''"""Coulomb rule 'doubled' (made up for a test): the spring capped at 2 mu |F_n|, its dashpot below it."""
import math

from ...infra.jit import compiled
from . import clip

NAME = "doubled"
SUMMARY = "the spring capped at twice mu |F_n| (made up for a test)"
SLOTS = ()


@compiled
def cap(f_s, damping, k_t, slip, limit):
    """The 'spring' rule at twice the cap."""
    if abs(f_s) > 2.0 * limit:
        f_s = clip(f_s, 2.0 * limit)
        return f_s, f_s, True
    if damping == 0.0:
        return f_s, f_s, False
    return f_s - damping * math.sqrt(k_t) * slip, f_s, False
'''
RULES_LINE = '    "spring_first",\n'         # the last registered rule: the made-up one is appended


@pytest.fixture(scope="module")
def with_doubled_rule(tmp_path_factory):
    """A copy of the package with submodels/coulomb/doubled.py and its one registry line, its generated modules
    rewritten (`python -m harness.submodels.generate`): (environment to run it in, its directory)."""
    import harness
    top = tmp_path_factory.mktemp("made_up_rule")
    package = top / "harness"
    shutil.copytree(Path(harness.__file__).parent, package, ignore=shutil.ignore_patterns("__pycache__"))
    (package / "submodels" / "coulomb" / "doubled.py").write_text(DOUBLED)
    registry_file = package / "submodels" / "registry.py"
    text = registry_file.read_text()
    assert text.count(RULES_LINE) == 1
    registry_file.write_text(text.replace(RULES_LINE, RULES_LINE + '    "doubled",\n'))
    env = {**os.environ, "PYTHONPATH": str(top), "NUMBA_CACHE_DIR": str(top / "numba")}
    done = subprocess.run([sys.executable, "-m", "harness.submodels.generate"], cwd=top, env=env,
                          capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr[-2000:]
    return env, top


def run_rule(env, top, rule):
    """`harness run` of an undamped linear spring with a linear tangential spring, stepped by leapfrog under Coulomb
    rule `rule`, at impact angles where the contact slides throughout: its table."""
    import pandas as pd
    out = top / f"{rule}.csv"
    done = subprocess.run([sys.executable, "-m", "harness", "run", "--model", "linear-spring-dashpot", "--with",
                           "integrator=leapfrog", "--with", f"coulomb={rule}", "--with", "damping=none", "--with",
                           "tangential-damping=none", "--en", "0.9", "--angles", "82,85,87", "--steps-per-contact",
                           "2000", "-o", str(out), "--quiet"], cwd=top, env=env, capture_output=True, text=True,
                          timeout=1800)
    assert done.returncode == 0, done.stderr[-2000:]
    return pd.read_csv(out)


@pytest.mark.parametrize("rule, multiple", [("doubled", 2.0), ("spring", 1.0)])
def test_a_coulomb_rule_made_up_as_one_module_and_one_registry_line_runs(with_doubled_rule, rule, multiple):
    """The made-up rule runs through `harness run --with coulomb=doubled`. The spring rises from first touch faster
    than the cap (k_t |V_s| > 2 mu k_n V_n at these angles, no dashpot) and never falls below it (unloading shrinks
    the cap, not a linear spring): the contact slides throughout, so the friction impulse is the cap's multiple of
    the normal impulse (closed form, per unit mass): v_t1 = v_t0 - k mu (v_n0 + v_n1), R omega1 = 5/2 k mu (v_n0 +
    v_n1) for a solid sphere, k = 2 for the made-up rule, 1 for the built-in 'spring' (which tells the two apart)."""
    frame = run_rule(*with_doubled_rule, rule)
    assert (frame.status == "ok").all()
    impulse = multiple * frame.mu * (frame.v_n0 + frame.v_n1)
    assert np.allclose(frame.v_t1, frame.v_t0 - impulse, rtol=0, atol=1e-9 * frame.v_t0.max())
    assert np.allclose(frame.omega1 * frame.radius, 2.5 * impulse, rtol=0, atol=1e-9 * frame.v_t0.max())
