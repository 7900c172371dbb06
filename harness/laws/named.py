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
from .law import Law, replace_submodels
from .table import LAWS as TABLE, known_law

PAPER_TANGENTIAL_DASHPOT = TangentialDashpot("normal-ratio")   # c_t = 2 g sqrt(m k_t), g of the normal dashpot,
                                                               # on a sticking spring (docs/laws.md)


def named(name, *submodels):
    """The law `name` of the table composed of `submodels`, with the table's summary."""
    return Law(name, *submodels, summary=TABLE[name].summary)


LAWS = {   # each law of the table (laws/table.py: its name, summary and labels) composed of sub-models
    "linear-spring-dashpot": named(
        "linear-spring-dashpot", LinearSpring("duration"), LinearDashpot(), "no-tension", LinearTangential("kappa"),
        PAPER_TANGENTIAL_DASHPOT),
    "hertz-mindlin": named(
        "hertz-mindlin", Hertz(), TsujiDashpot("appendix-b"), "no-tension", Mindlin("rescale"),
        PAPER_TANGENTIAL_DASHPOT),
    "hertz-kuwabara-kono": named(
        "hertz-kuwabara-kono", Hertz(), KuwabaraKonoDashpot(), "no-tension", Mindlin("rescale")),
    "walton-braun": named(
        "walton-braun", WaltonBraun(), NoDamping(), "no-tension", WaltonBraunTangential("2/7")),
    "stronge": named(
        "stronge", Stronge(), NoDamping(), "no-tension", Mindlin("rescale")),
    "thornton": named(
        "thornton", Thornton(), NoDamping(), "no-tension", Mindlin("rescale")),
    "partially-latching-spring": named(
        "partially-latching-spring", PartiallyLatchingSpring(), NoDamping(), "no-tension", LinearTangential("2/7")),
}



def check_table(laws):
    """The composed laws as the table registers them (the same names in order, labels and provisional flags)."""
    wrong = [name for name, law in laws.items() if name not in TABLE or law.describe() != TABLE[name].describe()
             or law.provisional != TABLE[name].provisional]
    if wrong or tuple(laws) != tuple(TABLE):
        raise ImportError(f"harness.laws.table registers the laws otherwise than they are composed: "
                          f"{wrong or tuple(laws)}")


check_table(LAWS)


def get_law(name):
    """Look up a named law; unknown name -> UserError listing the known ones."""
    return LAWS[known_law(name)]


def compose(name, overrides=None):
    """The named law with sub-models replaced, e.g. {'tangential': 'mindlin:total', 'end': 'tension'}; validated."""
    return replace_submodels(get_law(name), overrides)
