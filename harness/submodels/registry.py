"""The registration table: every sub-model by name (what `--with` and the named laws take) and every compiled kernel
numbered (what the integrators dispatch on). solver/dispatch.py is generated from it (`python -m
harness.submodels.generate`); a normal kernel registered at run time (`register_normal`) is reached through the
extension table the integrators carry, without recompiling them."""
import importlib
from dataclasses import dataclass

from ..errors import UserError
from . import stepping
from .base import N_SLOTS
from .damping.kuwabara_kono import KuwabaraKonoDashpot
from .damping.linear import LinearDashpot
from .damping.none import NoDamping
from .damping.tsuji import TsujiDashpot
from .normal.hertz import Hertz
from .normal.hertz_wall_modulus import HertzWallModulus
from .normal.luding_peak import LudingPeak
from .normal.thornton_ning import ThorntonNing
from .normal.linear import LinearSpring
from .normal.partially_latching_spring import PartiallyLatchingSpring
from .normal.stronge import Stronge
from .normal.thornton import Thornton
from .normal.walton_braun import WaltonBraun
from .normal.cundall_strack import CundallStrackSpring
from .normal.luding_incremental import LudingIncremental
from .normal.linear_modulus import LinearModulus
from .tangential.contact_radius_spring import ContactRadiusSpring
from .tangential.mindlin_wall_coefficient import MindlinPairCoefficient, MindlinWallCoefficient
from .tangential.linear import LinearTangential
from .tangential.mindlin import Mindlin
from .tangential.mindlin_deresiewicz import MindlinDeresiewicz
from .tangential.mindlin_unloading import MindlinUnloading
from .tangential.viscous import ViscousTangential
from .tangential.walton_braun import WaltonBraunTangential


@dataclass(frozen=True)
class Kernel:
    """A compiled kernel: its family and name, its module, the function each dispatch point calls there, and what
    the integrators must know of it."""
    family: str
    name: str
    module: str
    functions: tuple            # ((dispatch point, attribute of the module), ...)
    adaptive: bool = False      # the adaptive integrator covers it (it has the ODE's functions)
    history_reset: tuple = ()   # normal: an incremental law's history at first touch and after a contact
    viscous: bool = False       # tangential: no spring, F = -min(c_t |V_s|, mu F_n) sign V_s
    implicit: bool = False      # tangential: stiff, integrated implicitly in its hidden variable, with reversal events
    log_rate: int = 0           # tangential: F_s a'/a in the ODE: 0 never, 1 while a shrinks (eq. 18b), 2 always
    slots: tuple = ()           # normal: the names of its parameter slots p1.. (NormalParameters' names)


NORMAL_POINTS = ("force", "below", "slope", "residual", "kink", "step")
TANGENTIAL_POINTS = ("stiffness", "spring", "after_cap", "force_from_w", "w_from_force", "edge_w", "onset_w")
IMPLICIT_POINTS = ("force_from_w", "w_from_force", "edge_w", "onset_w")
SUBMODELS = "harness.submodels"


def normal_kernel(module):
    """The Kernel of a normal kernel module (NAME, ADAPTIVE, SLOTS, HISTORY_RESET and the dispatch points it
    defines), refused with what is missing (check_normal_module)."""
    m = importlib.import_module(module)
    check_normal_module(m, module)
    return Kernel("normal", m.NAME, module, tuple((p, p) for p in NORMAL_POINTS if hasattr(m, p)),
                  adaptive=m.ADAPTIVE, history_reset=tuple(getattr(m, "HISTORY_RESET", ())), slots=tuple(m.SLOTS))


def tangential_kernel(name, module, adaptive=False, **functions_and_capabilities):
    """The Kernel of tangential kernel `name` in submodels/tangential/<module>.py: the dispatch points it answers
    (point=attribute), its capabilities (viscous, implicit, log_rate), refused with what is missing
    (check_tangential_module)."""
    capabilities = {k: functions_and_capabilities.pop(k) for k in ("viscous", "implicit", "log_rate")
                    if k in functions_and_capabilities}
    path = f"{SUBMODELS}.tangential.{module}" if "." not in module else module
    unknown = sorted(set(functions_and_capabilities) - set(TANGENTIAL_POINTS))
    if unknown:
        raise UserError(f"tangential kernel {name!r}: no dispatch point {', '.join(unknown)}; the points are "
                        f"{', '.join(TANGENTIAL_POINTS)}")
    kernel = Kernel("tangential", name, path, tuple((p, functions_and_capabilities[p]) for p in TANGENTIAL_POINTS
                                                    if p in functions_and_capabilities),
                    adaptive=adaptive, **capabilities)
    check_tangential_module(kernel, importlib.import_module(path))
    return kernel


def missing_names(m, names):
    return [n for n in names if not callable(getattr(m, n, None))]


def check_normal_module(m, module):
    """A normal kernel module declares NAME (str), ADAPTIVE (bool) and SLOTS (at most four distinct names of its
    parameters p1..p4) and defines `force` (or, incremental, `step` with HISTORY_RESET); with ADAPTIVE, `slope` (the
    adaptive integrator's). below, residual and kink are optional: no force below contact, no dent, no kink."""
    problems = [f"constant {c}" for c, kind in (("NAME", str), ("ADAPTIVE", bool), ("SLOTS", tuple))
                if not isinstance(getattr(m, c, None), kind)]
    slots = getattr(m, "SLOTS", ())
    if isinstance(slots, tuple) and (len(slots) > N_SLOTS or len(set(slots)) != len(slots)
                                     or not all(isinstance(s, str) and s.isidentifier() for s in slots)):
        problems.append(f"SLOTS as at most {N_SLOTS} distinct names, got {slots!r}")
    if hasattr(m, "step") or hasattr(m, "HISTORY_RESET"):
        problems += [f"function {n}" for n in missing_names(m, ("step",))]
        if not isinstance(getattr(m, "HISTORY_RESET", None), tuple):
            problems.append("constant HISTORY_RESET (its history at first touch)")
    else:
        problems += [f"function {n}" for n in missing_names(m, ("force",))]
    if getattr(m, "ADAPTIVE", False) is True:
        problems += [f"function {n} (ADAPTIVE)" for n in missing_names(m, ("force", "slope"))]
    problems += [f"function {n} (defined but not callable)" for n in ("below", "residual", "kink")
                 if hasattr(m, n) and not callable(getattr(m, n))]
    if problems:
        raise UserError(f"normal kernel module {module} lacks {', '.join(problems)}")


def check_tangential_module(kernel, m):
    """A tangential kernel answers `stiffness`; a spring (not viscous) `spring`; an implicit one its four event
    points (IMPLICIT_POINTS); every attribute it names is a function of its module."""
    points = dict(kernel.functions)
    required = ["stiffness"] + ([] if kernel.viscous else ["spring"]) + (list(IMPLICIT_POINTS) if kernel.implicit
                                                                          else [])
    problems = [f"dispatch point {p}" for p in required if p not in points]
    problems += [f"function {a} (its {p})" for p, a in kernel.functions if not callable(getattr(m, a, None))]
    if problems:
        raise UserError(f"tangential kernel {kernel.name!r} ({kernel.module}) lacks {', '.join(problems)}")


def check_parameters(model, parameters):
    """The parameters a normal model gives, named as its kernel's SLOTS (UserError naming both otherwise)."""
    slots = kernels("normal")[code_of("normal", model.kernel)].slots
    if parameters.names != slots:
        raise UserError(f"the {model.name} normal model gives parameters {', '.join(parameters.names) or 'none'}; "
                        f"its kernel {model.kernel} takes {', '.join(slots) or 'none'}")
    return parameters.values


NORMAL_KERNELS = tuple(normal_kernel(f"{SUBMODELS}.normal.{m}") for m in (
    "linear", "hertz", "walton_braun", "thornton", "stronge", "luding_peak", "thornton_ning",
    "luding_incremental"))

TANGENTIAL_KERNELS = (
    Kernel("tangential", "none", "", (), adaptive=True),   # normal impact without spin, or mu = 0: no tangential model
    tangential_kernel("linear", "linear", True, stiffness="stiffness", spring="spring"),
    tangential_kernel("mindlin:incremental", "mindlin", True, stiffness="stiffness", spring="incremental"),
    tangential_kernel("mindlin:rescale", "mindlin", True, stiffness="stiffness", spring="rescale", log_rate=1),
    tangential_kernel("mindlin:total", "mindlin", True, stiffness="stiffness", spring="total",
                      after_cap="total_after_cap", log_rate=2),
    tangential_kernel("mindlin-deresiewicz", "mindlin_deresiewicz", stiffness="stiffness", spring="spring"),
    tangential_kernel("walton-braun", "walton_braun", True, stiffness="stiffness", spring="spring",
                      force_from_w="force_from_w", w_from_force="w_from_force", edge_w="edge_w", onset_w="onset_w",
                      implicit=True),
    tangential_kernel("viscous:linear", "viscous", stiffness="linear_stiffness", viscous=True),
    tangential_kernel("viscous:mindlin", "viscous", stiffness="mindlin_stiffness", viscous=True),
    tangential_kernel("mindlin:total-rescale", "mindlin_wall_coefficient", stiffness="stiffness",
                      spring="total_rescale", after_cap="total_after_cap"),
    tangential_kernel("mindlin:force-rescale", "mindlin_wall_coefficient", stiffness="stiffness",
                      spring="force_rescale"),
    tangential_kernel("contact-radius-spring", "contact_radius_spring", stiffness="stiffness", spring="spring",
                      after_cap="after_cap"),
    tangential_kernel("mindlin-unloading", "mindlin_unloading", stiffness="stiffness", spring="spring"),
)

# sub-models by the name --with takes; engine dialects' own sub-models are listed apart (engines name them)
NORMAL_MODELS = {cls.name: cls for cls in (LinearSpring, Hertz, WaltonBraun, PartiallyLatchingSpring, Thornton, Stronge)}
ENGINE_NORMAL_MODELS = {cls.name: cls for cls in (LudingPeak, ThorntonNing, CundallStrackSpring, LudingIncremental,
                                                   HertzWallModulus, LinearModulus)}
TANGENTIAL_MODELS = {cls.name: cls for cls in (LinearTangential, Mindlin, MindlinDeresiewicz, WaltonBraunTangential,
                                               ViscousTangential)}
ENGINE_TANGENTIAL_MODELS = {cls.name: cls for cls in (MindlinWallCoefficient, MindlinPairCoefficient,
                                                       ContactRadiusSpring, MindlinUnloading)}
DAMPING_MODELS = {cls.name: cls for cls in (NoDamping, LinearDashpot, TsujiDashpot, KuwabaraKonoDashpot)}
INTEGRATORS = {s.name: s for s in stepping.INTEGRATORS}          # stepping sub-models: the codes the steppers take
COULOMB_RULES = {s.name: s for s in stepping.COULOMB_RULES}
GEOMETRIES = {s.name: s for s in stepping.GEOMETRIES}
TOUCHES = {s.name: s for s in stepping.TOUCHES}

EXTENSION_SLOTS = 4         # normal kernels registered at run time, beyond the generated dispatch
EXTENSIONS = []             # their Kernels, in registration order


def kernels(family):
    return NORMAL_KERNELS + tuple(EXTENSIONS) if family == "normal" else TANGENTIAL_KERNELS


def code_of(family, name):
    """The number of kernel `name` in its family (what the integrators dispatch on)."""
    for code, kernel in enumerate(kernels(family)):
        if kernel.name == name:
            return code
    raise UserError(f"no {family} kernel named {name!r}")


def kernel_code(submodel):
    """The number of a sub-model's kernel (what the compiled integrators dispatch on)."""
    return code_of(submodel.family, submodel.kernel)


def kernel_of(family, code):
    return kernels(family)[code]


def python_point(family, code, point):
    """A kernel's dispatch point as plain Python (its compiled function's source, run by the interpreter): for the
    few evaluations outside the integrators, where compiling would cost more than it saves. Leaf functions only."""
    kernel = kernel_of(family, code)
    return getattr(importlib.import_module(kernel.module), dict(kernel.functions)[point]).py_func


def register_normal(model, module):
    """Register a normal sub-model class and the module of its compiled functions at run time: one call where a
    built-in is one registry line. The module defines NAME, ADAPTIVE, SLOTS and `extension(point, p1, p2, p3, p4,
    radius, alpha, alpha_max, x, y)` with the signature solver.extension.SIGNATURE, answering each of its points
    (force, below, slope, residual, kink) with a pair of floats; the class is a normal model of that kernel."""
    m = importlib.import_module(module)
    problems = [f"constant {c}" for c, kind in (("NAME", str), ("ADAPTIVE", bool), ("SLOTS", tuple))
                if not isinstance(getattr(m, c, None), kind)]
    problems += [f"function {n}" for n in missing_names(m, ("extension",))]
    if problems:
        raise UserError(f"normal kernel module {module} lacks {', '.join(problems)}")
    if getattr(model, "family", "") != "normal" or getattr(model, "kernel", None) != m.NAME or not model.name:
        raise UserError(f"{getattr(model, '__name__', model)!r} is not a normal model (family 'normal', a name) of "
                        f"kernel {m.NAME!r}")
    if m.NAME in [k.name for k in kernels("normal")]:
        raise UserError(f"a normal kernel named {m.NAME!r} is registered already")
    if len(EXTENSIONS) >= EXTENSION_SLOTS:
        raise UserError(f"at most {EXTENSION_SLOTS} normal kernels can be registered at run time")
    EXTENSIONS.append(Kernel("normal", m.NAME, module, (("extension", "extension"),), adaptive=m.ADAPTIVE,
                             slots=m.SLOTS))
    NORMAL_MODELS[model.name] = model
