"""Named contact laws: compositions of normal, damping, end rule, tangential and tangential-dashpot sub-models."""
from dataclasses import dataclass, replace

from ..errors import UserError
from ..solver import codes as C
from .damping import DAMPING_MODELS, KuwabaraKonoDashpot, LinearDashpot, NoDamping, TsujiDashpot
from .normal import ENGINE_NORMAL_MODELS, NORMAL_MODELS, Hertz, LinearSpring, PartiallyLatchingSpring, Stronge, Thornton, WaltonBraun
from .tangential import TANGENTIAL_MODELS, LinearTangential, Mindlin, WaltonBraunTangential
from .tangential_damping import TangentialDashpot

END_RULES = ("tension", "no-tension")
INTEGRATORS = ("paper", "velocity-verlet", "leapfrog")
SLIPS = ("lever", "noratch", "noratch-sphere")
LEVERS = ("0", "0.5", "1")
SUBMODEL_KEYS = ("normal", "damping", "end", "tangential", "tangential-damping", "integrator", "lever", "slip")


@dataclass(frozen=True)
class Law:
    """One contact law: sub-models chosen independently (as LAMMPS pair granular), defaults from the paper."""
    name: str
    normal: object
    damping: object
    end: str
    tangential: object
    tangential_damping: TangentialDashpot = TangentialDashpot("none")
    integrator: str = "paper"            # time stepping: 'paper' (second order) or 'velocity-verlet' (LIGGGHTS)
    lever: float = 0.0                   # lever arm R - lever * alpha for slip and torque (paper 0, LIGGGHTS 1/2)
    slip: str = "lever"                  # slip V_t - lever omega, or YADE's noRatch form with the wall's reference
                                         # radius 1e8 R ('noratch', hertzian wall) or R ('noratch-sphere')
    summary: str = ""
    dialect: str = "paper"               # whose formulas these are: the paper's, or an engine's (MODELS 5)

    def describe(self):
        """Sub-model names as {key: label}, the form `harness models` prints."""
        damping = self.damping.name + (f":{self.damping.calibration}" if self.damping.calibration else "")
        return {"normal": self.normal.label(), "damping": damping, "end": self.end,
                "tangential": self.tangential.label(), "tangential-damping": self.tangential_damping.label(),
                "integrator": self.integrator, "lever": f"R - {self.lever:g} alpha", "slip": self.slip}

    @property
    def provisional(self):
        return self.normal.name in ("stronge", "partially-latching-spring")


PAPER_TANGENTIAL_DASHPOT = TangentialDashpot("normal-ratio")   # c_t = 2 g sqrt(m k_t), g of the normal dashpot

LAWS = {
    "linear-spring-dashpot": Law(
        "linear-spring-dashpot", LinearSpring("duration"), LinearDashpot(), "no-tension", LinearTangential("kappa"),
        PAPER_TANGENTIAL_DASHPOT,
        summary="Walton's linear spring-dashpot as the paper uses it: k_n gives the elastic Hertz contact duration "
                "at V, no tension, g exact (Schwager & Poeschel 2007), k_t/k_n = kappa, tangential dashpot "
                "c_t = 2 g sqrt(m k_t) while sticking"),
    "hertz-mindlin": Law(
        "hertz-mindlin", Hertz(), TsujiDashpot("appendix-b"), "no-tension", Mindlin("rescale"),
        PAPER_TANGENTIAL_DASHPOT,
        summary="Hertz + Tsuji-type dashpot calibrated by Thornton et al. (2013) App. B on the tangent stiffness "
                "2E*a, no tension; Mindlin 8G*a with the eq. 18b unloading rescale; tangential dashpot "
                "c_t = 2 g sqrt(m 8G*a) while sticking"),
    "hertz-kuwabara-kono": Law(
        "hertz-kuwabara-kono", Hertz(), KuwabaraKonoDashpot(), "no-tension", Mindlin("rescale"),
        summary="Hertz + Kuwabara-Kono dashpot (Zhou et al. 1999 form), A calibrated at the scene speed; "
                "Mindlin eq. 18b"),
    "walton-braun": Law(
        "walton-braun", WaltonBraun(), NoDamping(), "no-tension", WaltonBraunTangential("2/7"),
        summary="Walton & Braun (1986) linear hysteretic K2 = K1/e^2, K1 from Hertz's peak overlap at V [prov]; "
                "Walton-Braun tangential k_t0/K1 = 2/7 [prov]"),
    "stronge": Law(
        "stronge", Stronge(), NoDamping(), "no-tension", Mindlin("rescale"),
        summary="PROVISIONAL reconstruction of Stronge's elastic-plastic law (docs/laws.md#stronge); Mindlin eq. 18b"),
    "thornton": Law(
        "thornton", Thornton(), NoDamping(), "no-tension", Mindlin("rescale"),
        summary="Thornton (1997) elastoplastic, p_y calibrated for e_n at the scene speed; Mindlin eq. 18b"),
    "partially-latching-spring": Law(
        "partially-latching-spring", PartiallyLatchingSpring(), NoDamping(), "no-tension", LinearTangential("2/7"),
        summary="PROVISIONAL: Walton-Braun spring with K1 = pi p_y R (Thornton's plastic stiffness), "
                "K2 = K1/e^2 (docs/laws.md#partially-latching-spring); tangential spring 2/7 K1 [prov]"),
}


def get_law(name):
    """Look up a named law; unknown name -> UserError listing the known ones."""
    try:
        return LAWS[name]
    except KeyError:
        raise UserError(f"unknown model {name!r}; known: {', '.join(LAWS)}") from None


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
    if name not in TANGENTIAL_MODELS:
        raise UserError(f"unknown tangential model {name!r}; known: {', '.join(TANGENTIAL_MODELS)}")
    cls = TANGENTIAL_MODELS[name]
    return cls(option) if option else cls()


def _choice(key, spec, allowed):
    if spec not in allowed:
        raise UserError(f"{key} must be one of {', '.join(allowed)}, got {spec!r}")
    return spec


def compose(name, overrides=None):
    """The named law with sub-models replaced, e.g. {'tangential': 'mindlin:total', 'end': 'tension'}; validated."""
    return replace_submodels(get_law(name), overrides)


def replace_submodels(law, overrides, dialect=None):
    """`law` with the given sub-models replaced (same vocabulary as `compose`); `dialect` renames its dialect."""
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
            changes["integrator"] = _choice(key, spec, INTEGRATORS)
        elif key == "lever":
            changes["lever"] = float(_choice(key, spec, LEVERS))
        elif key == "slip":
            changes["slip"] = _choice(key, spec, SLIPS)
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
    if law.normal.code == C.NORMAL_THORNTON_NING and law.integrator != "velocity-verlet":
        raise UserError("the incremental thornton_ning force is defined step by step only with velocity-verlet")
    if law.normal.plastic and law.end != "no-tension":
        raise UserError(f"{law.normal.name} ends contact at zero force; use end no-tension")

