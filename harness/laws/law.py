"""A contact law: a composition of normal, damping, end-rule, tangential and tangential-dashpot sub-models and the
scheme that integrates them, built and checked from the registry's names."""
from dataclasses import dataclass, replace

from ..infra.errors import UserError
from ..submodels.damping.kuwabara_kono import KuwabaraKonoDashpot
from ..submodels.damping.linear import LinearDashpot
from ..submodels.damping.none import NoDamping
from ..submodels.damping.tsuji import TsujiDashpot
from ..submodels.normal.hertz import Hertz
from ..submodels.normal.linear import LinearSpring
from ..submodels.registry import (COULOMB_RULES, DAMPING_MODELS, ENDS, ENGINE_NORMAL_MODELS, ENGINE_TANGENTIAL_MODELS,
                                  GEOMETRIES, INTEGRATORS, NORMAL_MODELS, TANGENTIAL_MODELS, TOUCHES, kernel_code,
                                  kernel_of)
from ..submodels.stepping import EVERY, STEPPERS, TOUCH_STEPPERS
from ..submodels.tangential_damping import TangentialDashpot

END_RULES = tuple(ENDS)
SLIPS = ("lever", "noratch", "noratch-sphere", "noratch-pair")
TORQUES = ("lever", "contact-point")
LEVERS = ("0", "0.25", "0.5", "1")
SUBMODEL_KEYS = ("normal", "damping", "end", "tangential", "tangential-damping", "integrator", "coulomb", "geometry",
                 "lever", "slip", "torque", "touch")


@dataclass(frozen=True)
class Law:
    """One contact law: sub-models chosen independently (as LAMMPS pair granular), defaults from the paper."""
    name: str
    normal: object
    damping: object
    end: str
    tangential: object
    tangential_damping: TangentialDashpot = TangentialDashpot("none")
    integrator: str = "paper"            # time stepping: 'paper' (second order), 'velocity-verlet', 'leapfrog'
    coulomb: str = "spring-first"        # the Coulomb rule (submodels/stepping.py): the spring tested first, then
                                         # spring + dashpot ('spring-first'), the spring alone, or their sum
    geometry: str = "wall"               # a wall, a stand-in sphere, or two spheres (submodels/stepping.py)
    lever: float = 0.0                   # lever arm R - lever * alpha for slip and torque (paper 0)
    slip: str = "lever"                  # slip V_t - lever omega, or the noRatch form with the wall's reference
                                         # radius 1e8 R ('noratch', flat wall) or R ('noratch-sphere'), or
                                         # with two spheres' R1 + R2 ('noratch-pair')
    torque: str = "lever"                # torque lever: the slip's ('lever'), or each body's R_i - d/2
                                         # ('contact-point', Verlet schemes)
    touch: str = "gap"                   # contact from gap 0 (force at first touch) or from overlap > 0 (none)
    summary: str = ""
    dialect: str = "paper"               # whose formulas these are: the paper's, or an engine's

    def describe(self):
        """Sub-model names as {key: label}, the form `harness models` prints."""
        damping = self.damping.name + (f":{self.damping.calibration}" if self.damping.calibration else "")
        return {"normal": self.normal.label(), "damping": damping, "end": self.end,
                "tangential": self.tangential.label(), "tangential-damping": self.tangential_damping.label(),
                "integrator": self.integrator, "coulomb": self.coulomb, "geometry": self.geometry,
                "lever": {0.0: "R", 0.25: "R - d/4", 0.5: "R - d/2", 1.0: "R - d"}.get(self.lever,
                                                                                     f"R - {self.lever:g} d"),
                "slip": self.slip, "torque": self.torque, "touch": self.touch}

    def undefined(self, contact, e_n, speed):
        """Why this composition's contact force is not a number at target e_n (a sub-model's 0/0), '' when it is one:
        every impact then ends not finite."""
        return self.tangential.undefined(self.damping.dashpot(self.normal, contact, e_n, speed, self.end))

    @property
    def provisional(self):
        return self.normal.name in ("stronge", "partially-latching-spring")


def _split(spec):
    name, _, option = str(spec).partition(":")
    return name, option or None


def _damping(spec):
    name, option = _split(spec)
    if name not in DAMPING_MODELS:
        raise UserError(f"unknown damping {name!r}; known: {', '.join(DAMPING_MODELS)}")
    cls = DAMPING_MODELS[name]
    return cls(option) if option else cls()


def _tangential(spec):
    name, option = _split(spec)
    models = {**TANGENTIAL_MODELS, **ENGINE_TANGENTIAL_MODELS}
    if name not in models:
        raise UserError(f"unknown tangential model {name!r}; known: {', '.join(TANGENTIAL_MODELS)}")
    cls = models[name]
    return cls(option) if option else cls()


def _choice(key, spec, allowed):
    if spec not in allowed:
        raise UserError(f"{key} must be one of {', '.join(allowed)}, got {spec!r}")
    return spec


def replace_submodels(law, overrides, dialect=None):
    """`law` with the given sub-models replaced ({'tangential': 'mindlin:total', 'end': 'tension'}, ...); `dialect`
    renames its dialect."""
    changes = {} if dialect is None else {"dialect": dialect}
    for key, spec in (overrides or {}).items():
        if key == "normal":
            models = {**NORMAL_MODELS, **ENGINE_NORMAL_MODELS}
            name, option = _split(spec)
            if name not in models:
                raise UserError(f"unknown normal model {name!r}; known: {', '.join(models)}")
            if option and not hasattr(models[name], "CALIBRATIONS"):
                raise UserError(f"the {name} normal model takes no option, got {spec!r}")
            changes["normal"] = models[name](option) if option else models[name]()
        elif key == "damping":
            changes["damping"] = _damping(spec)
        elif key == "end":
            changes["end"] = _choice(key, spec, END_RULES)
        elif key == "tangential":
            changes["tangential"] = _tangential(spec)
        elif key == "tangential-damping":
            changes["tangential_damping"] = TangentialDashpot(spec)
        elif key == "integrator":
            changes["integrator"] = _choice(key, spec, tuple(INTEGRATORS))
        elif key == "coulomb":
            changes["coulomb"] = _choice(key, spec, tuple(COULOMB_RULES))
        elif key == "geometry":
            changes["geometry"] = _choice(key, spec, tuple(GEOMETRIES))
        elif key == "lever":
            changes["lever"] = float(_choice(key, spec, LEVERS))
        elif key == "slip":
            changes["slip"] = _choice(key, spec, SLIPS)
        elif key == "torque":
            changes["torque"] = _choice(key, spec, TORQUES)
        elif key == "touch":
            changes["touch"] = _choice(key, spec, tuple(TOUCHES))
        else:
            raise UserError(f"unknown sub-model {key!r}; known: {', '.join(SUBMODEL_KEYS)}")
    law = replace(law, **changes) if changes else law
    check_composition(law)
    return law


def check_composition(law):
    """Reject compositions that have no meaning (a dashpot on a plastic law, tension with a latching spring...)."""
    if isinstance(law.damping, LinearDashpot) and not isinstance(law.normal, LinearSpring):
        raise UserError("the linear dashpot calibration needs the linear normal spring")
    if isinstance(law.damping, (TsujiDashpot, KuwabaraKonoDashpot)) and not isinstance(law.normal, Hertz):
        raise UserError(f"the {law.damping.name} dashpot needs the hertz normal model")
    if law.normal.plastic and not isinstance(law.damping, NoDamping):
        raise UserError(f"{law.normal.name} dissipates plastically; use damping none")
    if kernel_of("normal", kernel_code(law.normal)).history_reset and law.integrator == "paper":
        raise UserError(f"the incremental {law.normal.name} force is defined step by step only in an engine's scheme")
    if law.normal.plastic and law.end != "no-tension":
        raise UserError(f"{law.normal.name} ends contact at zero force; use end no-tension")
    check_stepping(law)


def check_stepping(law):
    """Reject an (integrator, geometry) pair no stepper computes, a Coulomb rule or touch rule its stepper does not
    apply, and a stand-in sphere without a normal model that gives its radius."""
    stepper = STEPPERS.get((law.integrator, law.geometry))
    if stepper is None:
        known = ", ".join(f"{i} with {g}" for i, g in STEPPERS)
        raise UserError(f"no stepper integrates {law.integrator} with geometry {law.geometry}; known: {known}")
    rules = tuple(COULOMB_RULES) if stepper[1] == EVERY else stepper[1]
    if law.coulomb not in rules:
        raise UserError(f"the {law.integrator} stepper with geometry {law.geometry} applies Coulomb rule "
                        f"{' or '.join(rules)}, not {law.coulomb}")
    touches = TOUCH_STEPPERS.get((law.integrator, law.geometry), ("gap",))
    if law.touch not in touches:
        raise UserError(f"the {law.integrator} stepper with geometry {law.geometry} applies touch rule "
                        f"{' or '.join(touches)}, not {law.touch}")
    if law.geometry == "stand-in-sphere" and not hasattr(law.normal, "stand_in_radius"):
        raise UserError(f"geometry stand-in-sphere needs a normal model with a stand-in radius, not {law.normal.name}")

