"""LAMMPS' contact inputs as a user writes them (docs/lammps-dialect.md#your-own-inputs): the words after `pair_coeff
* *` of `pair_style granular` (the same words `fix wall/gran granular` takes), or a classic style and its arguments
(`gran/hooke/history kn kt gamman gammat xmu dampflag`), parsed with LAMMPS' vocabulary and refusals per release, and
composed of neutral sub-models: what the release computes with them against a wall and between two spheres."""
import math
from dataclasses import dataclass

from ..user_inputs import EngineInput, Flag, refuse
from ...infra.errors import not_modelled
from ...infra.errors import UserError
from ...submodels.calibration import polynomial_tsuji_A
from .versions import NEWEST, holds, nearest, spelled

NORMAL_ARGUMENTS = {"hooke": ("k_n", "damp"), "hertz": ("k_n", "damp"), "hertz/material": ("E", "damp", "nu"),
                    "dmt": ("E", "damp", "nu", "gamma"), "jkr": ("E", "damp", "nu", "gamma")}
COHESIVE = ("dmt", "jkr")
DAMPING_MODELS = ("velocity", "mass_velocity", "viscoelastic", "tsuji", "coeff_restitution")
TANGENTIAL_ARGUMENTS = {"linear_nohistory": ("x_gamma_t", "mu"), "linear_history": ("k_t", "x_gamma_t", "mu"),
                        "mindlin": ("k_t", "x_gamma_t", "mu"), "mindlin_rescale": ("k_t", "x_gamma_t", "mu"),
                        "mindlin/force": ("k_t", "x_gamma_t", "mu"),
                        "mindlin_rescale/force": ("k_t", "x_gamma_t", "mu")}
MINDLIN_FORMS = {"mindlin": "total", "mindlin_rescale": "total-rescale", "mindlin/force": "force",
                 "mindlin_rescale/force": "force-rescale"}
KEYWORDS = ("damping", "tangential", "rolling", "twisting", "limit_damping", "cutoff", "heat", "synchronized_verlet")
CLASSIC = ("gran/hooke", "gran/hooke/history", "gran/hertz/history")
CLASSIC_ARGUMENTS = ("kn", "kt", "gamman", "gammat", "xmu", "dampflag")
VOCABULARY = (f"normal {', '.join(NORMAL_ARGUMENTS)}; {', '.join(KEYWORDS)}; or a classic style "
              f"{', '.join(CLASSIC)}")
INGREDIENTS = {              # what differs by release in reading an input (pair_granular.cpp, granular_model.cpp)
    # the words in any order, negative coefficients taken (2021/22); the normal model first, negatives refused (2023+)
    "strict": (((2021, 9, 29, 2), (2022, 6, 23, 4), False), ((2023, 8, 2, 3), NEWEST, True)),
    # damping coeff_restitution (gran_sub_mod_damping.cpp, GranSubModDampingCoeffRestitution)
    "coeff_restitution": (((2021, 9, 29, 2), (2023, 8, 2, 3), False), ((2024, 8, 29, 3), NEWEST, True)),
    # fix wall/gran hooke|hooke/history|hertz/history: its own formulas (fix_wall_gran.cpp), then rebuilt from
    # sub-models (granular_model.cpp, define_classic_model): x_gamma_t = gammat/gamman, the spring k a xi
    "classic-wall": (((2021, 9, 29, 2), (2022, 6, 23, 4), "own"), ((2023, 8, 2, 3), (2023, 8, 2, 3), "shifted"),
                     ((2024, 8, 29, 3), NEWEST, "sub-models")),
    # a granular wall of hertz/material: E/(2(1 - nu)) and Mindlin NULL E(2 - nu)(1 + nu)/4 (fix_wall_gran.cpp), then
    # the pair's E/(2(1 - nu^2)) and 2E/((2 - nu)(1 + nu)) (gran_sub_mod.cpp)
    "wall-moduli": (((2021, 9, 29, 2), (2022, 6, 23, 4), "wall"), ((2023, 8, 2, 3), NEWEST, "pair")),
    # a sphere at gap 0 against a wall: in contact, then not (fix_wall_gran.cpp; gran_sub_mod_normal.cpp, touch)
    "touch": (((2021, 9, 29, 2), (2022, 6, 23, 4), "gap"), ((2023, 8, 2, 3), NEWEST, "overlap")),
}
COMMON = {"end": "tension", "integrator": "velocity-verlet", "coulomb": "total", "lever": "0"}
PAIR = {**COMMON, "geometry": "pair", "torque": "contact-point"}


def number(word, name, model):
    """A coefficient as LAMMPS reads it: a float, else its own refusal."""
    try:
        value = float(word)
    except ValueError:
        refuse("lammps", f"Expected floating point parameter instead of {word!r} in input script or data file "
                         f"({model} {name})")
    if not math.isfinite(value):
        refuse("lammps", f"{model} {name} must be a finite number, got {word!r}")
    return value


@dataclass(frozen=True)
class LammpsInput(EngineInput):
    """A parsed LAMMPS input: `style` 'granular' or a classic style; `values` {name: number or 'NULL'}; for granular
    the chosen normal, damping and tangential models and limit_damping."""
    style: str = "granular"
    normal: str = ""
    damping: str = "viscoelastic"
    tangential: str = ""
    limit_damping: bool = False
    values: tuple = ()          # ((name, value), ...)

    @property
    def named(self):
        return dict(self.values)

    def law_family(self):
        """The paper law nearest in form: a linear spring, Hertz with a Tsuji-type or Kuwabara-Kono dashpot."""
        if self.style in CLASSIC:
            return "linear-spring-dashpot" if "hooke" in self.style else "hertz-kuwabara-kono"
        if self.normal == "hooke":
            return "linear-spring-dashpot"
        return "hertz-kuwabara-kono" if self.damping == "viscoelastic" else "hertz-mindlin"

    def alternatives(self):
        """The classic style as granular words and the granular words as a classic style, where the forms match:
        hooke + mass_velocity + linear_history|linear_nohistory and hertz + viscoelastic + mindlin."""
        v, limit = self.named, (" limit_damping" if self.limit_damping else "")
        if self.style in CLASSIC:
            share = v["gammat"] / v["gamman"] if v["gamman"] else 0.0
            normal, damping, tangential = {
                "gran/hooke": ("hooke", "mass_velocity", f"linear_nohistory {share!r} {v['xmu']!r}"),
                "gran/hooke/history": ("hooke", "mass_velocity", f"linear_history {v['kt']!r} {share!r} {v['xmu']!r}"),
                "gran/hertz/history": ("hertz", "viscoelastic", f"mindlin {v['kt']!r} {share!r} {v['xmu']!r}"),
            }[self.style]
            return [f"{normal} {v['kn']!r} {v['gamman']!r} damping {damping} tangential {tangential}{limit}"]
        forms = {("hooke", "mass_velocity", "linear_history"): "gran/hooke/history",
                 ("hooke", "mass_velocity", "linear_nohistory"): "gran/hooke",
                 ("hertz", "viscoelastic", "mindlin"): "gran/hertz/history"}
        style = forms.get((self.normal, self.damping, self.tangential))
        if style is None or v.get("k_t") == "NULL":
            return []
        k_t = v.get("k_t", 2.0 / 7.0 * v["k_n"])
        return [f"{style} {v['k_n']!r} {k_t!r} {v['damp']!r} {v['x_gamma_t'] * v['damp']!r} {v['mu']!r} 1{limit}"]

    def deck_style(self):
        """(pair_style words, pair_coeff words, fix wall/gran words) of a deck, the user's own words."""
        if self.style == "granular":
            return ("granular",), self.tokens, ("granular",) + self.tokens
        return (self.style,) + self.tokens, (), (self.style[len("gran/"):],) + self.tokens

    def check_release(self, version):
        """Refusals of release `version` (its own words), and the values it takes but that are unphysical."""
        strict = holds(INGREDIENTS["strict"], version)
        near = spelled(nearest(version))
        if self.style == "granular":
            if strict and self.tokens[0] not in NORMAL_ARGUMENTS:
                refuse("lammps", f"Illegal model type {self.tokens[0]} (LAMMPS {near}: the normal model comes first)")
            if self.damping == "coeff_restitution" and not holds(INGREDIENTS["coeff_restitution"], version):
                refuse("lammps", f"Illegal model type coeff_restitution (LAMMPS {near} has no damping "
                                 "coeff_restitution: it came in 2024.8.29.3 of the releases harness checked)")
            if strict:
                negative = [n for n, v in self.values if v != "NULL" and v < 0 and n not in ("nu",)]
                if negative:
                    model = self.normal if negative[0] in NORMAL_ARGUMENTS[self.normal] else self.tangential
                    refuse("lammps", f"Illegal {model} model: {negative[0]} {self.named[negative[0]]:g} < 0 "
                                     f"(LAMMPS {near} refuses negative coefficients)")
        return self

    def flags(self, version=None):
        """Values LAMMPS takes but that are unphysical: they run, flagged."""
        out = []
        v = self.named
        for name in ("damp", "x_gamma_t", "gamman", "gammat"):
            if isinstance(v.get(name), float) and v[name] < 0:
                out.append(Flag(name, f"{name} {v[name]:g} < 0: a negative dashpot adds energy"))
        if self.damping in ("tsuji", "coeff_restitution") and v.get("damp", 0.0) > 1.0:
            out.append(Flag("e", f"e {v['damp']:g} > 1: the dashpot adds energy"))
        for name in ("k_n", "E", "k_t", "kn", "kt", "mu", "xmu"):
            if isinstance(v.get(name), float) and v[name] < 0:
                out.append(Flag(name, f"{name} {v[name]:g} < 0 is unphysical"))
        return tuple(out)

    def composition(self, target, version=None):
        """The neutral sub-models that compute what LAMMPS `version` computes with this input against a wall or a
        sphere (docs/lammps-dialect.md#your-own-inputs)."""
        self.check_release(version)
        if self.style in CLASSIC:
            return classic_composition(self, target, version)
        return granular_composition(self, target, version)


def parse(text, version=None):
    """A LammpsInput of `text`: the words after `pair_coeff * *` (granular) or a classic style with its arguments."""
    words = text.split()
    if words[:1] == ["pair_coeff"]:
        words = words[3:]
    elif words[:1] == ["pair_style"]:
        words = words[1:]
    if not words:
        refuse("lammps", f"no contact words in {text!r}; LAMMPS takes: {VOCABULARY}")
    if words[0] == "granular":
        words = words[1:]
    if words and words[0] in CLASSIC:
        return parse_classic(text, words)
    return parse_granular(text, words)


def parse_classic(text, words):
    style, args = words[0], words[1:]
    limit = "limit_damping" in args
    args = [a for a in args if a != "limit_damping"]
    if len(args) != len(CLASSIC_ARGUMENTS):
        refuse("lammps", f"Illegal pair_style command: {style} takes {' '.join(CLASSIC_ARGUMENTS)} [limit_damping], "
                         f"got {len(args)} numbers")
    values = {}
    for name, word in zip(CLASSIC_ARGUMENTS, args):
        values[name] = "NULL" if word == "NULL" and name in ("kt", "gammat") else number(word, name, style)
    kn, gamman, xmu, flag = values["kn"], values["gamman"], values["xmu"], values["dampflag"]
    values["kt"] = 2.0 / 7.0 * kn if values["kt"] == "NULL" else values["kt"]
    values["gammat"] = 0.5 * gamman if values["gammat"] == "NULL" else values["gammat"]
    if flag not in (0.0, 1.0):
        refuse("lammps", f"Illegal pair_style command: dampflag is 0 or 1, got {args[5]}")
    if flag == 0.0:
        values["gammat"] = 0.0
    if min(kn, values["kt"], gamman, values["gammat"], xmu) < 0 or xmu > 10000:
        refuse("lammps", "Illegal pair_style command: kn, kt, gamman, gammat and xmu must be >= 0 and xmu <= 10000")
    return LammpsInput("lammps", text, tuple(_token(w) for w in words[1:]), mu=xmu, style=style,
                       limit_damping=limit, values=tuple(values.items()))


def _token(word):
    """A word as the deck gets it: an integer (LAMMPS reads dampflag as one), a float, or the word itself."""
    if word.lstrip("+-").isdigit():
        return int(word)
    try:
        return float(word)
    except ValueError:
        return word


def parse_granular(text, words):
    """The granular sub-model words, each block as LAMMPS reads it (pair_granular.cpp, PairGranular::coeff)."""
    values, chosen, i = {}, {}, 0
    while i < len(words):
        word = words[i]
        if word in NORMAL_ARGUMENTS:
            if word in COHESIVE:
                not_modelled(f"LAMMPS' cohesive normal model {word} (surface energy; a later issue)")
            i = _take(words, i, NORMAL_ARGUMENTS[word], values, word, null=())
            chosen["normal"] = word
        elif word == "damping":
            model = words[i + 1] if i + 1 < len(words) else ""
            if model not in DAMPING_MODELS:
                refuse("lammps", f"Illegal model type {model or 'missing'}: LAMMPS' damping models are "
                                 f"{', '.join(DAMPING_MODELS)}")
            chosen["damping"], i = model, i + 2
        elif word == "tangential":
            model = words[i + 1] if i + 1 < len(words) else ""
            if model not in TANGENTIAL_ARGUMENTS:
                refuse("lammps", f"Illegal model type {model or 'missing'}: LAMMPS' tangential models are "
                                 f"{', '.join(TANGENTIAL_ARGUMENTS)}")
            null = ("k_t",) if model.startswith("mindlin") else ()
            i = _take(words, i + 1, TANGENTIAL_ARGUMENTS[model], values, model, null=null)
            chosen["tangential"] = model
        elif word in ("rolling", "twisting"):
            model = words[i + 1] if i + 1 < len(words) else ""
            if model != "none":
                not_modelled(f"LAMMPS' {word} {model} ({word} resistance; a later issue)")
            i += 2
        elif word == "limit_damping":
            chosen["limit_damping"], i = True, i + 1
        elif word in ("cutoff", "heat", "synchronized_verlet"):
            not_modelled(f"LAMMPS' {word} keyword")
        else:
            refuse("lammps", f"Illegal model type {word}: LAMMPS takes {VOCABULARY}")
    if "normal" not in chosen:
        refuse("lammps", "Must specify normal granular model")
    if "tangential" not in chosen:
        refuse("lammps", "Must specify tangential granular model")
    if chosen["tangential"].startswith("mindlin") and values["k_t"] == "NULL" and chosen["normal"] != "hertz/material":
        refuse("lammps", "Must either specify tangential stiffness or material properties for normal model for the "
                         "Mindlin tangential style")
    damping = chosen.get("damping", "viscoelastic")
    if damping == "coeff_restitution" and values["damp"] == 0.0:
        refuse("lammps", "damping coeff_restitution with e = 0: LAMMPS takes ln 0 and its force is not a number")
    return LammpsInput("lammps", text, tuple(_token(w) for w in words), mu=values["mu"], normal=chosen["normal"],
                       damping=damping, tangential=chosen["tangential"],
                       limit_damping=chosen.get("limit_damping", False), values=tuple(values.items()))


def _take(words, i, names, values, model, null):
    """Read the coefficients `names` of `model` after words[i] into `values`; the index after them."""
    args = words[i + 1:i + 1 + len(names)]
    if len(args) < len(names) or any(a in KEYWORDS or a in NORMAL_ARGUMENTS for a in args):
        refuse("lammps", f"Illegal {model} model: it takes {' '.join(names)}")
    for name, word in zip(names, args):
        values[name] = "NULL" if word == "NULL" and name in null else number(word, name, model)
    return i + 1 + len(names)


def effective_modulus(given, target, version):
    """E* of hertz/material's one E and nu: E/(2(1 - nu^2)), or a wall's E/(2(1 - nu)) in 2021/22."""
    e, nu = given["E"], given["nu"]
    if target == "wall" and holds(INGREDIENTS["wall-moduli"], version) == "wall":
        return e / (2.0 * (1.0 - nu))
    return e / (2.0 * (1.0 - nu * nu))


def mindlin_null(given, target, version):
    """k_t/a of Mindlin NULL: 8 G* = 2E/((2 - nu)(1 + nu)), or a wall's E(2 - nu)(1 + nu)/4 in 2021/22."""
    e, nu = given["E"], given["nu"]
    if target == "wall" and holds(INGREDIENTS["wall-moduli"], version) == "wall":
        return e * (2.0 - nu) * (1.0 + nu) / 4.0
    return 2.0 * e / ((2.0 - nu) * (1.0 + nu))


def restitution_factor(model, normal, e):
    """tsuji: Tsuji's polynomial A(e); coeff_restitution: -2 ln e/sqrt(pi^2 + ln^2 e) (hooke) or -sqrt5 ln e/sqrt(pi^2 +
    ln^2 e) (gran_sub_mod_damping.cpp)."""
    if model == "tsuji":
        return polynomial_tsuji_A(e)
    log_e = math.log(e)
    return (-2.0 if normal == "hooke" else -math.sqrt(5.0)) * log_e / math.sqrt(math.pi ** 2 + log_e ** 2)


def granular_composition(given_input, target, version):
    """pair_style granular / fix wall/gran granular: the normal spring with its numbers, the dashpot eta_n (velocity
    damp; mass_velocity damp m; viscoelastic damp m a; tsuji and coeff_restitution c(e) sqrt(m k_sec)), the
    tangential model with eta_t = x_gamma_t eta_n, the Coulomb cap on spring plus dashpot."""
    from ...laws.given import given_law
    v = given_input.named
    normal = given_input.normal
    if normal == "hooke":
        spring, stiffness, spring_power = ("linear", v["k_n"]), v["k_n"], 0.0       # k_sec = k_n
    else:
        e_star = 0.75 * v["k_n"] if normal == "hertz" else effective_modulus(v, target, version)
        spring, stiffness, spring_power = ("hertz", e_star), 4.0 / 3.0 * e_star, 0.25    # k_sec = 4/3 E* a
    damping = given_input.damping
    if damping == "velocity":
        dashpot = (v["damp"], 0.0, 0.0, 0.0)
    elif damping == "mass_velocity":
        dashpot = (v["damp"], 1.0, 0.0, 0.0)
    elif damping == "viscoelastic":
        dashpot = (v["damp"], 1.0, 0.5, 0.5)
    else:                                   # c sqrt(m k_sec): k_sec = k (hooke) or k R^1/2 alpha^1/2
        dashpot = (restitution_factor(damping, normal, v["damp"]) * math.sqrt(stiffness), 0.5,
                   spring_power, spring_power)
    tangential = given_input.tangential
    share = v["x_gamma_t"]
    if tangential == "linear_history":
        friction = ("linear", v["k_t"], 0.0)
    elif tangential == "linear_nohistory":
        friction = ("viscous", 1.0, 2.0 * dashpot[3])     # c_t = prefactor sqrt(k), k = 1 or R^1/2 alpha^1/2
    else:
        k = mindlin_null(v, target, version) if v["k_t"] == "NULL" else v["k_t"]
        friction = ("mindlin:" + MINDLIN_FORMS[tangential], k, 0.5)
    overrides = dict(PAIR if target == "sphere" else {**COMMON, "touch": holds(INGREDIENTS["touch"], version)})
    if given_input.limit_damping:
        overrides["end"] = "no-tension"
    return given_law(spring, dashpot, friction, ("share", share), overrides,
                     f"LAMMPS damping {damping} with tangential {tangential}")


def classic_composition(given_input, target, version):
    """gran/hooke, gran/hooke/history, gran/hertz/history (pair_gran_*.cpp; fix_wall_gran.cpp to 2022): F_n = p (kn
    delta - m gamman v_n), p = 1 or a; F_t = -p (kt xi + m gammat v_t) capped at xmu |F_n| (gran/hooke: the dashpot
    alone). A wall from 2023.8.2.3 is rebuilt from sub-models (granular_model.cpp, define_classic_model): the spring
    kt a xi reset to xi = -F/kt, x_gamma_t = gammat/gamman (0/0 without normal damping)."""
    from ...laws.given import given_law
    v = given_input.named
    style = given_input.style
    kn, kt, gamman, gammat = v["kn"], v["kt"], v["gamman"], v["gammat"]
    hertz = style == "gran/hertz/history"
    spring = ("hertz", 0.75 * kn) if hertz else ("linear", kn)
    dashpot = (gamman, 1.0, 0.5, 0.5) if hertz else (gamman, 1.0, 0.0, 0.0)
    wall = holds(INGREDIENTS["classic-wall"], version) if target == "wall" else "own"
    nan = "x_gamma_t = gammat/gamman is 0/0 without normal damping (granular_model.cpp, define_classic_model)"
    if style == "gran/hooke":
        if wall == "shifted":
            not_modelled(f"LAMMPS {spelled(nearest(version))}'s gran/hooke wall, which takes its friction from "
                         "gammat/gamman (granular_model.cpp, define_classic_model)")
        friction = ("viscous", 1.0, 0.0, nan if wall == "sub-models" else "")
    elif wall == "own":
        friction = ("mindlin:total", kt, 0.5) if hertz else ("linear", kt, 0.0)
    else:
        friction = ("contact-radius", kt, 0.0, nan)
    overrides = ({**COMMON, "touch": holds(INGREDIENTS["touch"], version)} if target == "wall" else
                 {**COMMON, "geometry": "pair"})       # the classic pair styles' torque from the full radii
    if given_input.limit_damping:
        overrides["end"] = "no-tension"
    share = ("share", gammat / gamman) if gamman else ("per-mass", gammat)        # m gammat p = (gammat/gamman) c_n
    return given_law(spring, dashpot, friction, share, overrides, f"LAMMPS {style}")


WALL_STYLES = ("xplane", "yplane", "zplane", "zcylinder", "region")


def contact_text(deck, path):
    """The contact words of a LAMMPS deck: a classic `pair_style gran/...` line, else the `pair_coeff` of `pair_style
    granular`, else a `fix ... wall/gran` line (its words up to the wall style); comments and `&` continuations
    read as LAMMPS reads them."""
    lines, joined = [], ""
    for raw in deck.splitlines():
        line = raw.split("#", 1)[0].rstrip()
        if line.endswith("&"):
            joined += line[:-1] + " "
            continue
        lines.append((joined + line).split())
        joined = ""
    granular = False
    for words in lines:
        if words[:1] == ["pair_style"] and len(words) > 1:
            if words[1] in CLASSIC:
                return " ".join(words[1:])
            granular = words[1] == "granular"
        if granular and words[:1] == ["pair_coeff"] and len(words) > 3:
            return " ".join(words[3:])
    for words in lines:
        if words[:1] == ["fix"] and "wall/gran" in words:
            rest = words[words.index("wall/gran") + 1:]
            end = next((i for i, w in enumerate(rest) if w in WALL_STYLES), len(rest))
            rest = rest[:end]
            return " ".join(rest[1:] if rest[:1] == ["granular"] else ["gran/" + rest[0]] + rest[1:] if rest else [])
    raise UserError(f"--engine-input @{path}: no pair_style gran/..., pair_coeff of pair_style granular or fix "
                    "wall/gran line in it")
