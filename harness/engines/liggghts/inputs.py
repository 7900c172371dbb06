"""LIGGGHTS 3.8.0's contact inputs as a user writes them (docs/liggghts-dialect.md#your-own-inputs): the `pair_style
gran` words (`model hooke|hertz tangential history|no_history` and the settings limitForce, tangential_damping,
ktToKnUser) followed by the `fix property/global` values the models read (youngsModulus, poissonsRatio,
coefficientRestitution, coefficientFriction, characteristicVelocity), one value each (one atom type), composed of
neutral sub-models with those numbers."""
import math
from dataclasses import dataclass

from ..user_inputs import EngineInput, refuse
from ...infra.errors import not_modelled
from ...infra.errors import UserError
from ...submodels.normal.given import GivenLinear

MODEL_WORDS = ("hooke", "hertz")
OTHER_MODELS = ("hooke/stiffness", "hertz/stiffness", "hooke/hysteresis", "thornton_ning", "edinburgh", "luding")
TANGENTIAL = ("history", "no_history", "off")
SETTINGS = {"limitForce": ("off", "on"), "tangential_damping": ("on", "off"), "ktToKnUser": ("off", "on")}
PROPERTIES = ("youngsModulus", "poissonsRatio", "coefficientRestitution", "coefficientFriction",
              "characteristicVelocity")
NEEDS = {"hertz": PROPERTIES[:4], "hooke": PROPERTIES}
KT_TO_KN_USER = 0.285714286          # the literal LIGGGHTS multiplies by (normal_model_hooke.h)
COMMON = {"end": "tension", "integrator": "velocity-verlet", "coulomb": "spring", "lever": "0.5"}
VOCABULARY = (f"model {', '.join(MODEL_WORDS)}; tangential {', '.join(TANGENTIAL)}; {', '.join(SETTINGS)}; "
              f"{', '.join(PROPERTIES)}")


@dataclass(frozen=True)
class LiggghtsInput(EngineInput):
    """A parsed LIGGGHTS input: its model, tangential model, settings and property values."""
    model: str = "hertz"
    tangential: str = "history"
    settings: tuple = ()
    properties: tuple = ()

    @property
    def values(self):
        return dict(self.properties)

    def law_family(self):
        return "hertz-mindlin" if self.model == "hertz" else "linear-spring-dashpot"

    def other_engines(self, contact):
        """[(engine, text, release)]: the LAMMPS words with the same spring, dashpot and friction numbers on this
        contact (hertz/material Y e nu with damping coeff_restitution and Mindlin NULL; hooke with LIGGGHTS' k_n;
        x_gamma_t the ratio of the two dashpots), for LAMMPS 2024.8.29.3, the first release harness ran with
        coeff_restitution."""
        from ...submodels.calibration import hertz_equivalent_stiffness
        v, settings = self.values, dict(self.settings)
        y, nu, e, mu = (v["youngsModulus"], v["poissonsRatio"], v["coefficientRestitution"],
                        v["coefficientFriction"])
        damped = self.tangential != "off" and settings.get("tangential_damping") != "off"
        kt_kn = KT_TO_KN_USER if settings.get("ktToKnUser") == "on" else 1.0
        if self.model == "hertz":
            e_star, g_star = y / (2.0 * (1.0 - nu * nu)), y / (4.0 * (2.0 - nu) * (1.0 + nu))
            share = 2.0 * math.sqrt(g_star / e_star) if damped else 0.0
            normal = f"hertz/material {y!r} {e!r} {nu!r} damping coeff_restitution"
            spring = f"mindlin NULL {share!r} {mu!r}"
        else:
            k_n = hertz_equivalent_stiffness(y / (2.0 * (1.0 - nu * nu)), contact.radius, contact.mass,
                                             v["characteristicVelocity"])
            share = (1.0 if damped else 0.0)
            normal = f"hooke {k_n!r} {e!r} damping coeff_restitution"
            spring = f"linear_history {kt_kn * k_n!r} {share!r} {mu!r}"
        if self.tangential == "no_history":
            spring = f"linear_nohistory {share!r} {mu!r}"
        elif self.tangential == "off":
            spring = "linear_nohistory 0.0 0.0"
        limit = " limit_damping" if settings.get("limitForce") == "on" else ""
        return [("lammps", f"{normal} tangential {spring}{limit}", "2024.8.29.3")]

    def deck_values(self):
        """What the deck template takes of this input: model, tangential, settings, Y, nu, e, mu and properties."""
        v = self.values
        properties = ([("characteristicVelocity", "scalar", v["characteristicVelocity"])]
                      if self.model == "hooke" else [])
        return dict(model=self.model, tangential=self.tangential, options=sorted(self.settings), E=[v["youngsModulus"]],
                    nu=[v["poissonsRatio"]], e_n=v["coefficientRestitution"], mu=v["coefficientFriction"],
                    properties=properties)

    def composition(self, target, version=None):
        """LIGGGHTS' formulas with these numbers (normal_model_hertz.h, normal_model_hooke.h,
        tangential_model_history.h): Y* = Y/(2(1 - nu^2)), G* = Y/(4(2 - nu)(1 + nu)) of one material mixed with
        itself; hertz F = 4/3 Y* a delta with gamma_n = 2 sqrt(5/6) |beta| sqrt(2 Y* a m) and k_t = 8 G* a; hooke
        k_n = 16/15 sqrt(R) Y* (15 m V_c^2/(16 sqrt(R) Y*))^1/5, gamma_n = 2 g sqrt(m k_n) (g the linear
        oscillator's), k_t = k_n (or 0.285714286 k_n); tangential dashpot with the normal's ratio (hertz) or c_t = c_n
        (hooke)."""
        from ...laws.law import Law, replace_submodels
        from ...submodels.calibration import hertz_equivalent_stiffness, lsd_tension_g
        from ...submodels.damping.fixed import FixedDashpot
        from ...submodels.normal.given import GivenHertz
        from ...submodels.tangential.given import GivenMindlin, GivenViscous
        from ...submodels.tangential.linear import LinearTangential
        from ...submodels.tangential.viscous import ViscousTangential
        from ...submodels.tangential_damping import TangentialDashpot
        v, settings = self.values, dict(self.settings)
        y, nu, e = v["youngsModulus"], v["poissonsRatio"], v["coefficientRestitution"]
        e_star, g_star = y / (2.0 * (1.0 - nu * nu)), y / (4.0 * (2.0 - nu) * (1.0 + nu))
        log_e = math.log(e)
        beta = abs(log_e) / math.sqrt(log_e ** 2 + math.pi ** 2)
        no_history = self.tangential == "no_history"
        if self.model == "hertz":
            normal = GivenHertz(e_star)
            damping = FixedDashpot(math.sqrt(5.0) * beta * math.sqrt(4.0 / 3.0 * e_star), 0.5, 0.25, 0.25)
            tangential = GivenViscous("mindlin", g_star) if no_history else GivenMindlin("total", 8.0 * g_star)
            ratio = math.sqrt(5.0 / 6.0) * beta
        else:
            normal = _HookeStiffness(e_star, v["characteristicVelocity"], hertz_equivalent_stiffness)
            g = lsd_tension_g(e)
            damping = _HookeDashpot(g)
            kt_kn = KT_TO_KN_USER if settings.get("ktToKnUser") == "on" else 1.0
            tangential = ViscousTangential("linear") if no_history else LinearTangential(repr(kt_kn))
            ratio = g if no_history else g / math.sqrt(kt_kn)   # c_t = c_n: 2 g_t sqrt(m k_t) = 2 g sqrt(m k_n)
        if self.tangential == "off" or settings.get("tangential_damping") == "off":
            ratio = 0.0
        overrides = dict(COMMON)
        if settings.get("limitForce") == "on":
            overrides["end"] = "no-tension"
        if target == "sphere":
            overrides.update(geometry="pair", torque="contact-point")
        law = Law("input", normal, damping, "tension", tangential, TangentialDashpot(repr(ratio)),
                  summary=f"LIGGGHTS model {self.model} tangential {self.tangential}")
        return replace_submodels(law, overrides)


class _HookeStiffness(GivenLinear):
    """LIGGGHTS hooke's k_n from Y* and characteristicVelocity V_c, for the contact at hand (its mass and radius)."""

    def __init__(self, e_star, v_c, stiffness_of):
        super().__init__(0.0)
        self.e_star, self.v_c, self.stiffness_of = e_star, v_c, stiffness_of

    def label(self):
        return f"linear(k_n=16/15 R^1/2 Y* (15 m V_c^2/(16 R^1/2 Y*))^1/5, Y*={self.e_star:.6g}, V_c={self.v_c:g})"

    def stiffness(self, contact, speed):
        return self.stiffness_of(self.e_star, contact.radius, contact.mass, self.v_c)


class _HookeDashpot:
    """c_n = 2 g sqrt(m k_n), g the linear oscillator's ratio for e with tension."""
    name, power = "fixed", 0.0

    def __init__(self, g):
        self.g = g
        self.calibration = f"2*{g:.6g}*sqrt(m*k_n)"

    def dashpot(self, normal, contact, e_n, speed, end):
        from ...submodels.damping import Dashpot
        k = normal.parameters(contact, e_n, speed).linear_stiffness
        return Dashpot(2.0 * self.g * math.sqrt(contact.mass * k), 0.0, self.g)


def parse(text, version=None):
    """A LiggghtsInput of `text`: `model M [tangential T] [SETTING on|off]... [PROPERTY VALUE]...`."""
    words = text.split()
    if words[:2] == ["pair_style", "gran"]:
        words = words[2:]
    if words[:1] != ["model"] or len(words) < 2:
        refuse("liggghts", f"Unknown argument or wrong keyword order: {words[0] if words else 'nothing'!r} "
                           f"(LIGGGHTS takes {VOCABULARY})")
    model = words[1]
    if model in OTHER_MODELS:
        not_modelled(f"LIGGGHTS model {model} as your own input (its formulas run through --model; a later issue)")
    if model not in MODEL_WORDS:
        refuse("liggghts", "Invalid model specified (check for typos and enable at least one model)")
    tangential, settings, properties, i = "off", {}, {}, 2
    while i < len(words):
        word = words[i]
        value = words[i + 1] if i + 1 < len(words) else None
        if word == "tangential" and value in TANGENTIAL:
            tangential = value
        elif word in ("cohesion", "rolling_friction", "surface"):
            not_modelled(f"LIGGGHTS' {word} {value} (a later issue)")
        elif word in SETTINGS and value in SETTINGS[word]:
            settings[word] = value
        elif word in PROPERTIES:
            try:
                properties[word] = float(value)
            except (TypeError, ValueError):
                refuse("liggghts", f"{word} takes a number, got {value!r}")
        elif word == "tangential":
            refuse("liggghts", "Invalid model specified (check for typos and enable at least one model)")
        else:
            refuse("liggghts", f"Unknown argument or wrong keyword order: {word!r} (LIGGGHTS takes {VOCABULARY})")
        i += 2
    for name in NEEDS[model]:
        if name not in properties:
            refuse("liggghts", f"Could not locate a fix/property storing value(s) for {name} as requested by "
                               f"model {model}.")
    if not 0.0 <= properties["poissonsRatio"] <= 0.5:
        refuse("liggghts", "0 <= poissonsRatio <= 0.5 required")
    if not 0.05 < properties["coefficientRestitution"] <= 1.0:
        refuse("liggghts", "0.05 < coefficientRestitution <= 1 required")
    if model == "hooke" and properties["characteristicVelocity"] < 1e-2:
        refuse("liggghts", "characteristicVelocity >= 1e-2 required for SI units")
    if properties["youngsModulus"] <= 0 or properties["coefficientFriction"] < 0:
        raise UserError("liggghts input: youngsModulus must be > 0 and coefficientFriction >= 0")
    tokens = tuple(words)
    return LiggghtsInput("liggghts", " ".join(words), tokens, mu=properties["coefficientFriction"], model=model,
                         tangential=tangential, settings=tuple(settings.items()), properties=tuple(properties.items()))


def contact_text(deck, path):
    """The `pair_style gran` words of a LIGGGHTS deck and the first value of each property it reads."""
    words, values = None, {}
    for raw in deck.splitlines():
        line = raw.split("#", 1)[0].split()
        if line[:2] == ["pair_style", "gran"]:
            words = line[2:]
        if "property/global" in line:
            at = line.index("property/global")
            if at + 3 < len(line) and line[at + 1] in PROPERTIES:
                name, style, rest = line[at + 1], line[at + 2], line[at + 3:]
                values[name] = rest[1] if style == "peratomtypepair" and len(rest) > 1 else rest[0]
    if words is None:
        raise UserError(f"--engine-input @{path}: no pair_style gran line in it")
    return " ".join(words + [w for name, value in values.items() for w in (name, value)])
