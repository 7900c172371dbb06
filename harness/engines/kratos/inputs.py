"""Kratos DEMApplication 10.4.4's contact inputs as a user writes them (docs/kratos-dialect.md#your-own-inputs): the
material and material-relation variables of a MaterialsDEM.json, `NAME value` or `"NAME": value` (YOUNG_MODULUS,
POISSON_RATIO, COEFFICIENT_OF_RESTITUTION, STATIC_FRICTION, DYNAMIC_FRICTION, DEM_DISCONTINUUM_CONSTITUTIVE_LAW_NAME,
...), one material for the sphere and its wall or target sphere, composed of neutral sub-models with those numbers."""
import math
import re
from dataclasses import dataclass

from ..user_inputs import EngineInput, Flag, refuse
from ...infra.errors import not_modelled
from ...infra.errors import UserError
from ...submodels.calibration import thornton_appendix_b_g
from ...submodels.damping import Dashpot
from ...submodels.damping.fixed import FixedDashpot
from ...submodels.damping.linear import LinearDashpot
from ...submodels.normal.linear_modulus import BETAS, LinearModulus, modulus_stiffness
from ...submodels.tangential.mindlin_unloading import MindlinUnloading
from .dialect import COMMON, PAIR

LAWS = {"DEM_D_Hertz_viscous_Coulomb": "hertz-mindlin", "DEM_D_Linear_viscous_Coulomb": "linear-spring-dashpot"}
OTHER_LAWS = ("DEM_D_JKR_Cohesive_Law", "DEM_D_DMT_Cohesive_Law", "DEM_D_Stress_Dependent_Cohesive",
              "DEM_D_Linear_Custom_Constants", "DEM_D_Hertz_viscous_Coulomb_Nestle", "DEM_D_Conical_damage",
              "DEM_D_Linear_classic", "DEM_D_Quadratic", "DEM_D_void")
NUMBERS = ("YOUNG_MODULUS", "POISSON_RATIO", "COEFFICIENT_OF_RESTITUTION", "STATIC_FRICTION", "DYNAMIC_FRICTION",
           "FRICTION_DECAY", "PARTICLE_DENSITY", "ROLLING_FRICTION", "ROLLING_FRICTION_WITH_WALLS",
           "PARTICLE_COHESION", "AMOUNT_OF_COHESION_FROM_STRESS", "COMPUTE_WEAR", "SEVERITY_OF_WEAR",
           "IMPACT_WEAR_SEVERITY", "BRINELL_HARDNESS")
WORDS = ("DEM_DISCONTINUUM_CONSTITUTIVE_LAW_NAME", "DEM_ROLLING_FRICTION_MODEL_NAME")
NOT_YET = {"ROLLING_FRICTION": "rolling friction", "ROLLING_FRICTION_WITH_WALLS": "rolling friction with walls",
           "PARTICLE_COHESION": "cohesion", "AMOUNT_OF_COHESION_FROM_STRESS": "cohesion"}
UNUSED = ("PARTICLE_DENSITY", "FRICTION_DECAY", "COMPUTE_WEAR", "SEVERITY_OF_WEAR", "IMPACT_WEAR_SEVERITY",
          "BRINELL_HARDNESS")
NEEDS = ("YOUNG_MODULUS", "POISSON_RATIO", "COEFFICIENT_OF_RESTITUTION", "STATIC_FRICTION", "DYNAMIC_FRICTION",
         "DEM_DISCONTINUUM_CONSTITUTIVE_LAW_NAME")
PAIR_WORD = re.compile(r'"?([A-Z][A-Z_]+)"?\s*[:=]?\s*("[^"]*"|[^\s,{}"]+)')
VOCABULARY = ", ".join(NUMBERS + WORDS)


@dataclass(frozen=True)
class KratosInput(EngineInput):
    """A parsed Kratos input: its law (DEM_DISCONTINUUM_CONSTITUTIVE_LAW_NAME) and its variables."""
    law: str = "DEM_D_Hertz_viscous_Coulomb"
    variables: tuple = ()

    @property
    def values(self):
        return dict(self.variables)

    def law_family(self):
        return LAWS[self.law]

    def flags(self, version=None):
        v = self.values
        why = {"PARTICLE_DENSITY": "the sphere's density is the scene's (--rho)",
               "FRICTION_DECAY": "with STATIC_FRICTION equal to DYNAMIC_FRICTION it changes nothing"}
        return tuple(Flag(name, f"{name} {v[name]:g} not used: " + why.get(name, "harness runs no wear"))
                     for name in UNUSED if name in v)

    def other_engines(self, contact):
        """[(engine, text, release)]: the other engines' inputs with the same numbers (engines/material_inputs.py); for
        the linear law LAMMPS hooke with Kratos' k_n on a wall, k_t = 2(1 - nu)/(2 - nu) k_n and x_gamma_t =
        sqrt(k_t/k_n) (c = 2 g sqrt(m k) on both springs)."""
        from ..material_inputs import hertz_material, linear_spring
        v = self.values
        young, nu, e, mu = (v["YOUNG_MODULUS"], v["POISSON_RATIO"], v["COEFFICIENT_OF_RESTITUTION"],
                            v["STATIC_FRICTION"])
        if self.law == "DEM_D_Hertz_viscous_Coulomb":
            return hertz_material(young, nu, e, mu, skip="kratos")
        k_n = modulus_stiffness(young / (2.0 * (1.0 - nu * nu)), contact.radius, BETAS["wall"])
        ratio = 2.0 * (1.0 - nu) / (2.0 - nu)
        return linear_spring(k_n, ratio * k_n, e, math.sqrt(ratio), mu, skip="kratos")

    def deck_values(self):
        """What the script template takes: the law, E, nu (every material), e and mu, as given."""
        v = self.values
        return dict(counterpart=self.law, E=v["YOUNG_MODULUS"], nu=v["POISSON_RATIO"],
                    e_n=v["COEFFICIENT_OF_RESTITUTION"], mu=v["STATIC_FRICTION"])

    def composition(self, target, version=None):
        """Kratos' formulas with these numbers, one material on both sides (E* = E/(2(1 - nu^2)), G* = E/(4(2 - nu)(1 +
        nu))): Hertz F = 4/3 E* sqrt(R) d^3/2 with the App. B damping of e on k_n = 2 E* sqrt(R d), k_t = 8 G* a
        rescaled on unloading; linear k_n = beta E* pi 0.31225 R* (beta 1 on a wall, 1.432 between spheres) with the
        1e-4-bisected Schwager-Poeschel damping of e and k_t = 2(1 - nu)/(2 - nu) k_n; c_t = 2 g sqrt(m k_t) with the
        normal's g (DEM_D_Hertz_viscous_Coulomb_CL.cpp, DEM_D_Linear_viscous_Coulomb_CL.cpp, sphere_strategy.py)."""
        from ...laws.law import Law, replace_submodels
        from ...submodels.normal.given import GivenHertz
        from ...submodels.tangential.linear import LinearTangential
        from ...submodels.tangential_damping import TangentialDashpot
        v = self.values
        young, nu, e = v["YOUNG_MODULUS"], v["POISSON_RATIO"], v["COEFFICIENT_OF_RESTITUTION"]
        e_star, g_star = young / (2.0 * (1.0 - nu * nu)), young / (4.0 * (2.0 - nu) * (1.0 + nu))
        overrides = dict(COMMON, **(PAIR if target == "sphere" else {}))
        if self.law == "DEM_D_Hertz_viscous_Coulomb":
            damping = _AppendixB(e, e_star)
            law = Law("input", GivenHertz(e_star), damping, "no-tension",
                      _GivenMindlinUnloading(g_star), TangentialDashpot("normal-ratio"),
                      summary=f"Kratos {self.law} E {young:g} nu {nu:g} e {e:g}")
        else:
            beta = BETAS["pair" if target == "sphere" else "wall"]
            law = Law("input", _GivenModulus(e_star, beta), _GivenRestitution(LinearDashpot, "bisection", e),
                      "no-tension", LinearTangential(repr(2.0 * (1.0 - nu) / (2.0 - nu))),
                      TangentialDashpot("normal-ratio"), summary=f"Kratos {self.law} E {young:g} nu {nu:g} e {e:g}")
        return replace_submodels(law, overrides)


def _GivenRestitution(base, calibration, e):
    """The dashpot `base(calibration)` calibrated from the input's e, not from the run's e_n."""
    class Given(base):
        def dashpot(self, normal, contact, e_n, speed, end):
            return super().dashpot(normal, contact, e, speed, end)
    dashpot = Given(calibration)
    dashpot.calibration = calibration
    dashpot.given_e = e
    return dashpot


class _AppendixB(FixedDashpot):
    """c_n = 2 g sqrt(m k_n), k_n = 2 E* sqrt(R d), g from e by Thornton et al. (2013) eqs. B6-B7; its g also sets the
    tangential dashpot (c_t = 2 g sqrt(m k_t))."""

    def __init__(self, e, e_star):
        self.g = thornton_appendix_b_g(e)
        super().__init__(2.0 * self.g * math.sqrt(2.0 * e_star), 0.5, 0.25, 0.25)

    def dashpot(self, normal, contact, e_n, speed, end):
        fixed = super().dashpot(normal, contact, e_n, speed, end)
        return Dashpot(fixed.c0, fixed.power, self.g)


class _GivenModulus(LinearModulus):
    """k_n = beta E* pi 0.31225 R* with E* given."""

    def __init__(self, e_star, beta):
        super().__init__("wall")
        self.e_star, self.beta = e_star, beta

    def label(self):
        return f"linear(k_n={self.beta:g} E* pi 0.31225 R*, E*={self.e_star:.6g})"

    def stiffness(self, contact, speed):
        return modulus_stiffness(self.e_star, contact.radius, self.beta)


class _GivenMindlinUnloading(MindlinUnloading):
    """k_t = 8 G* a with G* given, rescaled on unloading only."""

    def __init__(self, g_star):
        self.g_star = g_star

    def label(self):
        return f"mindlin-unloading(G*={self.g_star:.6g})"

    def parameter(self, contact, k_n):
        return self.g_star


def parse(text, version=None):
    """A KratosInput of `text`: `NAME value` or `"NAME": value` pairs of Kratos variables."""
    pairs = PAIR_WORD.findall(text)
    if not pairs or PAIR_WORD.sub(" ", text).strip(" \n,{}[]:"):
        refuse("kratos", f"cannot read {text!r} as Kratos variables NAME value (Kratos DEM takes {VOCABULARY})")
    values, law = {}, None
    for name, raw in pairs:
        value = raw.strip('"')
        if name in WORDS:
            if name == "DEM_ROLLING_FRICTION_MODEL_NAME":
                not_modelled(f"Kratos' rolling friction model {value} (a later issue)")
            if value in OTHER_LAWS:
                not_modelled(f"Kratos' {value} as your own input (a later issue)")
            if value not in LAWS:
                refuse("kratos", f"the constitutive law {value} is not registered (Kratos DEM offers "
                                 f"{', '.join(LAWS)} and others)")
            law = value
        elif name in NUMBERS:
            try:
                number = float({"true": 1, "false": 0}.get(value.lower(), value))
            except ValueError:
                refuse("kratos", f"{name} takes a number, got {value!r}")
            if name in NOT_YET and number != 0.0:
                not_modelled(f"Kratos' {NOT_YET[name]} ({name} {value}; a later issue)")
            values[name] = number
        else:
            refuse("kratos", f"Kernel.GetVariable() ERROR: Variable {name} is unknown (Kratos DEM takes {VOCABULARY})")
    if law is not None:
        values["DEM_DISCONTINUUM_CONSTITUTIVE_LAW_NAME"] = law
    missing = [n for n in NEEDS if n not in values]
    if missing:
        refuse("kratos", f"the material or its relation does not have {', '.join(missing)} (read by "
                         f"{law or 'the constitutive law'} and sphere_strategy.py)")
    if values["STATIC_FRICTION"] != values["DYNAMIC_FRICTION"]:
        not_modelled("STATIC_FRICTION != DYNAMIC_FRICTION (friction decaying with the slip speed; a later issue)")
    young, nu, e = values["YOUNG_MODULUS"], values["POISSON_RATIO"], values["COEFFICIENT_OF_RESTITUTION"]
    if young <= 0.0 or not -1.0 < nu <= 0.5:
        raise UserError("kratos input: YOUNG_MODULUS must be > 0 and -1 < POISSON_RATIO <= 0.5")
    if not 0.0 < e <= 1.0:
        raise UserError("kratos input: harness models COEFFICIENT_OF_RESTITUTION in (0, 1] (Kratos' damping from it "
                        "takes its logarithm)")
    if values["STATIC_FRICTION"] < 0.0:
        raise UserError("kratos input: STATIC_FRICTION must be >= 0")
    words = [f"{n} {r.strip(chr(34))}" for n, r in pairs]
    variables = tuple((k, v) for k, v in values.items() if k != "DEM_DISCONTINUUM_CONSTITUTIVE_LAW_NAME")
    return KratosInput("kratos", " ".join(words), tuple(words), mu=values["STATIC_FRICTION"], law=law,
                       variables=variables)


def contact_text(text, path):
    """The variables of a MaterialsDEM.json (its first material and first relation)."""
    import json
    try:
        data = json.loads(text)
        variables = {**data["materials"][0]["Variables"], **data["material_relations"][0]["Variables"]}
    except (ValueError, KeyError, IndexError, TypeError):
        raise UserError(f"--engine-input @{path}: not a MaterialsDEM.json with a material and a relation") from None
    return " ".join(f"{k} {v}" for k, v in variables.items())
