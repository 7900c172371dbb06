"""The named laws: each law of the paper as a composition of sub-models, with the paper's defaults."""
from ..submodels.damping.kuwabara_kono import KuwabaraKonoDashpot
from ..submodels.damping.linear import LinearDashpot
from ..submodels.damping.none import NoDamping
from ..submodels.damping.tsuji import TsujiDashpot
from ..submodels.normal.hertz import Hertz
from ..submodels.normal.linear import LinearSpring
from ..submodels.normal.partially_latching_spring import PartiallyLatchingSpring
from ..submodels.normal.stronge import Stronge
from ..submodels.normal.thornton import Thornton
from ..submodels.normal.walton_braun import WaltonBraun
from ..submodels.tangential.linear import LinearTangential
from ..submodels.tangential.mindlin import Mindlin
from ..submodels.tangential.walton_braun import WaltonBraunTangential
from ..submodels.tangential_damping import TangentialDashpot
from ..errors import UserError
from .law import Law, replace_submodels

PAPER_TANGENTIAL_DASHPOT = TangentialDashpot("normal-ratio")   # c_t = 2 g sqrt(m k_t), g of the normal dashpot,
                                                               # on a sticking spring (docs/laws.md)

LAWS = {
    "linear-spring-dashpot": Law(
        "linear-spring-dashpot", LinearSpring("duration"), LinearDashpot(), "no-tension", LinearTangential("kappa"),
        PAPER_TANGENTIAL_DASHPOT,
        summary="Walton's linear spring-dashpot as the paper uses it: k_n gives the elastic Hertz contact duration "
                "at V, no tension, g exact (Schwager & Poeschel 2007), k_t/k_n = kappa, tangential dashpot "
                "c_t = 2 g sqrt(m k_t) while the spring sticks"),
    "hertz-mindlin": Law(
        "hertz-mindlin", Hertz(), TsujiDashpot("appendix-b"), "no-tension", Mindlin("rescale"),
        PAPER_TANGENTIAL_DASHPOT,
        summary="Hertz + Tsuji-type dashpot calibrated by Thornton et al. (2013) App. B on the tangent stiffness "
                "2E*a, no tension; Mindlin 8G*a with the eq. 18b unloading rescale; tangential dashpot "
                "c_t = 2 g sqrt(m 8G*a) while the spring sticks"),
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
        raise UserError(f"unknown law {name!r}; known: {', '.join(LAWS)}") from None


def compose(name, overrides=None):
    """The named law with sub-models replaced, e.g. {'tangential': 'mindlin:total', 'end': 'tension'}; validated."""
    return replace_submodels(get_law(name), overrides)
