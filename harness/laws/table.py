"""The registration table of the named laws: each law's name, summary and sub-models as `harness models` prints
them, known without compiling anything; laws/named.py composes each law from its compiled sub-models and holds it to
this table, and the kernels load only when a law is run."""
import argparse
from dataclasses import dataclass

from ..infra.errors import UserError

PAPER_STEPPING = {"integrator": "paper", "coulomb": "spring-first", "geometry": "wall", "lever": "R", "slip": "lever",
                  "torque": "lever", "touch": "gap"}     # what every named law integrates with (the paper's scheme)


@dataclass(frozen=True)
class Entry:
    """A named law: its sub-models' labels (Law.describe()'s) and whether the paper's equations are missing."""
    normal: str
    damping: str
    tangential: str
    tangential_damping: str
    summary: str
    end: str = "no-tension"
    provisional: bool = False

    def describe(self):
        """{sub-model key: label}, as Law.describe() gives it."""
        return {"normal": self.normal, "damping": self.damping, "end": self.end, "tangential": self.tangential,
                "tangential-damping": self.tangential_damping, **PAPER_STEPPING}


LAWS = {
    "linear-spring-dashpot": Entry(
        "linear:duration", "linear:exact", "linear(k_t/k_n=kappa)", "normal-ratio",
        "Walton's linear spring-dashpot as the paper uses it: k_n gives the elastic Hertz contact duration at V, no "
        "tension, g exact (Schwager & Poeschel 2007), k_t/k_n = kappa, tangential dashpot c_t = 2 g sqrt(m k_t) while "
        "the spring sticks"),
    "hertz-mindlin": Entry(
        "hertz", "tsuji:appendix-b", "mindlin(rescale)", "normal-ratio",
        "Hertz + Tsuji-type dashpot calibrated by Thornton et al. (2013) App. B on the tangent stiffness 2E*a, no "
        "tension; Mindlin 8G*a with the eq. 18b unloading rescale; tangential dashpot c_t = 2 g sqrt(m 8G*a) while "
        "the spring sticks"),
    "hertz-kuwabara-kono": Entry(
        "hertz", "kuwabara-kono:exact", "mindlin(rescale)", "none",
        "Hertz + Kuwabara-Kono dashpot (Zhou et al. 1999 form), A calibrated at the scene speed; Mindlin eq. 18b"),
    "walton-braun": Entry(
        "walton-braun", "none", "walton-braun(k_t0/k_n=0.285714)", "none",
        "Walton & Braun (1986) linear hysteretic K2 = K1/e^2, K1 from Hertz's peak overlap at V [prov]; "
        "Walton-Braun tangential k_t0/K1 = 2/7 [prov]"),
    "stronge": Entry(
        "stronge", "none", "mindlin(rescale)", "none",
        "PROVISIONAL reconstruction of Stronge's elastic-plastic law (docs/laws.md#stronge); Mindlin eq. 18b",
        provisional=True),
    "thornton": Entry(
        "thornton", "none", "mindlin(rescale)", "none",
        "Thornton (1997) elastoplastic, p_y calibrated for e_n at the scene speed; Mindlin eq. 18b"),
    "partially-latching-spring": Entry(
        "partially-latching-spring", "none", "linear(k_t/k_n=0.285714)", "none",
        "PROVISIONAL: Walton-Braun spring with K1 = pi p_y R (Thornton's plastic stiffness), K2 = K1/e^2 "
        "(docs/laws.md#partially-latching-spring); tangential spring 2/7 K1 [prov]",
        provisional=True),
}


def known_law(name):
    """`name` if it names a law; UserError listing the known ones otherwise."""
    if name not in LAWS:
        raise UserError(f"unknown law {name!r}; known: {', '.join(LAWS)}")
    return name


def law_name(text):
    """A command line's law name, refused by the parser when it names no law (before any kernel loads)."""
    try:
        return known_law(text)
    except UserError as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None
