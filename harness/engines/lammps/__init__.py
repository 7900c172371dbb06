"""LAMMPS (29 Sep 2021) as an engine (docs/engines.md): one batched deck per (law, e_n) through `fix wall/gran
granular`, run as a subprocess; its dialects are in dialect.py, its input and output in deck.py."""
import re

from ..base import Engine, split_submodels
from .deck import BINARY_VARIABLE, OBSERVE_DUMP, TEMPLATES, deck, read_batch, render_batch, run_inputs, settings
from .dialect import (COUNTERPARTS, DIALECTS, HISTORY_STYLES, OPTIONS, PAIR_DIALECTS, check_options, dialect, walls,
                      words)


class Lammps(Engine):
    NAME = "lammps"
    EXECUTABLE, PACKAGE, VARIABLE = "lmp", "lammps", BINARY_VARIABLE
    OPTIONS, COUNTERPARTS, DIALECTS, PAIR_DIALECTS = OPTIONS, COUNTERPARTS, DIALECTS, PAIR_DIALECTS
    WITH = {("tangential-damping", "none"): {"with:tangential-damping": "none"}}    # x_gamma_t, dampflag 0 (deck.py)
    KNOWN_CAUSES = {
        ("hertz-mindlin", "e_n off target"):
            "LAMMPS' Tsuji polynomial is 1/sqrt2 of the coefficient that returns e (docs/lammps-dialect.md)",
        ("hertz-kuwabara-kono", "e_n off target"):
            "LAMMPS' wall modulus E/(2(1 - nu)) is (1 + nu) E*; the viscoelastic dashpot's e moves with it "
            "(docs/lammps-dialect.md)",
        ("linear-spring-dashpot", "e_n off target"):
            "the paper's dashpot is calibrated for a force clipped at 0; LAMMPS does not clip (docs/lammps-dialect.md)",
    }
    COLOUR, DASHES = "tab:purple", "-."
    render_batch = staticmethod(render_batch)
    read_batch = staticmethod(read_batch)

    def run_inputs(self, flavour, count, timeout_s, workdir):
        return run_inputs(self.binary(), count, timeout_s, workdir)

    def read_version(self, text):
        """'29Sep2021_update2' (the stable release's own spelling) from the banner of `lmp -h`, '29 Sep 2021 -
        Update 2'."""
        match = re.search(r"Simulator - ([0-9]+) ([A-Za-z]+) ([0-9]+)(?: - Update ([0-9]+))?\s*$", text, re.MULTILINE)
        if not match:
            return "unknown"
        day, month, year, update = match.groups()
        return f"{day}{month}{year}" + (f"_update{update}" if update else "")

    def walls(self, law_name, options=None):
        return walls(law_name, split_submodels(options)[0])

    def composition(self, law_name, options, target):
        return dialect(law_name, options, target)


ENGINE = Lammps()

__all__ = ["BINARY_VARIABLE", "COUNTERPARTS", "DIALECTS", "ENGINE", "HISTORY_STYLES", "OBSERVE_DUMP", "OPTIONS",
           "PAIR_DIALECTS", "TEMPLATES", "check_options", "deck", "dialect", "render_batch", "settings", "walls",
           "words"]
