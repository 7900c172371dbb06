"""The registration table: every sub-model by name (what `--with` and the named laws take) and every compiled kernel
module numbered in its family (what the integrators dispatch on), one line each, appended so that the existing codes
keep their numbers. solver/dispatch.py and solver/layout.py are generated from it (`python -m
harness.submodels.generate`); a normal kernel registered at run time (`register_normal`) is reached through the
extension table the integrators carry, without recompiling them."""
import importlib
from dataclasses import dataclass

from ..infra.errors import UserError
from .base import N_SLOTS
from .families import FAMILIES, check_module
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
    """A kernel module: its family and name, its import path, the dispatch points it defines, its slots, its
    summary and its capabilities ((NAME, value), ...), read as lower-case attributes (kernel.adaptive)."""
    family: str
    name: str
    module: str
    functions: tuple            # the dispatch points the module defines
    slots: tuple = ()
    summary: str = ""
    capabilities: tuple = ()

    def __getattr__(self, name):
        for key, value in self.__dict__.get("capabilities", ()):
            if key.lower() == name:
                return value
        raise AttributeError(name)


SUBMODELS = "harness.submodels"


def kernel_module(family, module):
    """The Kernel of kernel module `module` (an import path) of `family`, refused with what it lacks
    (families.check_module)."""
    m = importlib.import_module(module)
    spec = FAMILIES[family]
    check_module(spec, m, module)
    return Kernel(family, m.NAME, module, tuple(p.name for p in spec.points if hasattr(m, p.name)), tuple(m.SLOTS),
                  m.SUMMARY, tuple((c, getattr(m, c, default)) for c, (_, default) in spec.capabilities.items()))


def registered(family, modules):
    """The Kernels of submodels/<family>/<module>.py for each module, in order: their codes."""
    return tuple(kernel_module(family, f"{SUBMODELS}.{family}.{module}") for module in modules)


NO_TANGENTIAL = Kernel("tangential", "none", "", (), (), "no tangential model: a normal impact without spin, or mu = 0",
                       (("ADAPTIVE", True), ("VISCOUS", False), ("IMPLICIT", False), ("LOG_RATE", 0)))

NORMAL_KERNELS = registered("normal", (
    "linear",
    "hertz",
    "walton_braun",
    "thornton",
    "stronge",
    "luding_peak",
    "thornton_ning",
    "luding_incremental",
))
END_KERNELS = registered("end", (
    "tension",
    "no_tension",
))
TANGENTIAL_KERNELS = (NO_TANGENTIAL,) + registered("tangential", (
    "linear",
    "mindlin_incremental",
    "mindlin_rescale",
    "mindlin_total",
    "mindlin_deresiewicz",
    "walton_braun",
    "viscous_linear",
    "viscous_mindlin",
    "mindlin_total_rescale",
    "mindlin_force_rescale",
    "contact_radius_spring",
    "mindlin_unloading",
))
INTEGRATOR_KERNELS = registered("integrator", (
    "paper",
    "velocity_verlet",
    "leapfrog",
))
COULOMB_KERNELS = registered("coulomb", (
    "spring",
    "total",
    "total_cases",
    "spring_first",
))
GEOMETRY_KERNELS = registered("geometry", (
    "wall",
    "stand_in_sphere",
    "pair",
    "pair_vector",
))
TOUCH_KERNELS = registered("touch", (
    "gap",
    "overlap",
))
BUILT_IN = {"normal": NORMAL_KERNELS, "end": END_KERNELS, "tangential": TANGENTIAL_KERNELS,
            "integrator": INTEGRATOR_KERNELS, "coulomb": COULOMB_KERNELS, "geometry": GEOMETRY_KERNELS,
            "touch": TOUCH_KERNELS}

# sub-models by the name --with takes; engine dialects' own sub-models are listed apart (engines name them)
NORMAL_MODELS = {cls.name: cls for cls in
                 (LinearSpring, Hertz, WaltonBraun, PartiallyLatchingSpring, Thornton, Stronge)}
ENGINE_NORMAL_MODELS = {cls.name: cls for cls in (LudingPeak, ThorntonNing, CundallStrackSpring, LudingIncremental,
                                                   HertzWallModulus, LinearModulus)}
TANGENTIAL_MODELS = {cls.name: cls for cls in (LinearTangential, Mindlin, MindlinDeresiewicz, WaltonBraunTangential,
                                               ViscousTangential)}
ENGINE_TANGENTIAL_MODELS = {cls.name: cls for cls in (MindlinWallCoefficient, MindlinPairCoefficient,
                                                       ContactRadiusSpring, MindlinUnloading)}
DAMPING_MODELS = {cls.name: cls for cls in (NoDamping, LinearDashpot, TsujiDashpot, KuwabaraKonoDashpot)}
INTEGRATORS = {k.name: k for k in INTEGRATOR_KERNELS}     # stepping sub-models by the name a law gives
COULOMB_RULES = {k.name: k for k in COULOMB_KERNELS}
GEOMETRIES = {k.name: k for k in GEOMETRY_KERNELS}
TOUCHES = {k.name: k for k in TOUCH_KERNELS}
ENDS = {k.name: k for k in END_KERNELS}

EXTENSION_SLOTS = 4         # normal kernels registered at run time, beyond the generated dispatch
EXTENSIONS = []             # their Kernels, in registration order


def kernels(family):
    """Every kernel of `family` by code (normal: the built-in ones, then those registered at run time)."""
    return BUILT_IN[family] + (tuple(EXTENSIONS) if family == "normal" else ())


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


def check_parameters(model, parameters):
    """The parameters a normal model gives, named as its kernel's SLOTS (UserError naming both otherwise)."""
    slots = kernels("normal")[code_of("normal", model.kernel)].slots
    if parameters.names != slots:
        raise UserError(f"the {model.name} normal model gives parameters {', '.join(parameters.names) or 'none'}; "
                        f"its kernel {model.kernel} takes {', '.join(slots) or 'none'}")
    return parameters.values


def python_point(family, code, point):
    """A kernel's dispatch point as plain Python (its compiled function's source, run by the interpreter): for the
    few evaluations outside the integrators, where compiling would cost more than it saves. Leaf functions only."""
    kernel = kernel_of(family, code)
    return getattr(importlib.import_module(kernel.module), point).py_func


def register_normal(model, module):
    """Register a normal sub-model class and the module of its compiled functions at run time: one call where a
    built-in is one registry line. The module declares NAME, SUMMARY, ADAPTIVE and SLOTS (at most N_SLOTS) and
    defines `extension(point, slots, radius, alpha, alpha_max, x, y)` with the signature solver.extension.SIGNATURE
    (slots: the normal family's block of the kernel row, its SLOTS first), answering each of its points (force,
    below, slope, residual, kink) with a pair of floats; the class is a normal model of that kernel."""
    m = importlib.import_module(module)
    problems = [f"constant {c}" for c, kind in (("NAME", str), ("SUMMARY", str), ("ADAPTIVE", bool), ("SLOTS", tuple))
                if not isinstance(getattr(m, c, None), kind)]
    if isinstance(getattr(m, "SLOTS", None), tuple) and len(m.SLOTS) > N_SLOTS:
        problems.append(f"SLOTS as at most {N_SLOTS} names")
    problems += [f"function {n}" for n in ("extension",) if not callable(getattr(m, n, None))]
    if problems:
        raise UserError(f"normal kernel module {module} lacks {', '.join(problems)}")
    if getattr(model, "family", "") != "normal" or getattr(model, "kernel", None) != m.NAME or not model.name:
        raise UserError(f"{getattr(model, '__name__', model)!r} is not a normal model (family 'normal', a name) of "
                        f"kernel {m.NAME!r}")
    if m.NAME in [k.name for k in kernels("normal")]:
        raise UserError(f"a normal kernel named {m.NAME!r} is registered already")
    if len(EXTENSIONS) >= EXTENSION_SLOTS:
        raise UserError(f"at most {EXTENSION_SLOTS} normal kernels can be registered at run time")
    EXTENSIONS.append(Kernel("normal", m.NAME, module, ("extension",), m.SLOTS, m.SUMMARY,
                             (("ADAPTIVE", m.ADAPTIVE), ("HISTORY_RESET", ()))))
    NORMAL_MODELS[model.name] = model
