"""Kratos Multiphysics' DEMApplication as an engine (docs/engines.md, docs/kratos-dialect.md): one Python script per
run, run by the python of a venv that holds the KratosMultiphysics and KratosDEMApplication wheels. Its 'executable'
is that interpreter: a build is a prefix <engines directory>/kratos-<release>/ (tools/install_kratos.sh) whose
bin/python imports Kratos, or the interpreter HARNESS_KRATOS_PYTHON names; its dialects are in dialect.py, its input
and output in script.py, the interpreter's probe in venv.py."""
import os

from ...infra.programs import from_variable, which
from ..base import Engine, SceneScripts
from ..builds import directory, prefix_binaries, sha256
from .dialect import COUNTERPARTS, DIALECTS, PAIR_DIALECTS
from .script import INPUT, TEMPLATES, read_batch, render_batch, run_inputs, script, typed
from .venv import PYTHON_VARIABLE, probe


class Kratos(SceneScripts, Engine):
    NAME = "kratos"
    STARTS_APART = ("wall",)
    INPUT_SUFFIX, INPUT_NAME = ".py", INPUT
    EXECUTABLE, VARIABLE = "python", PYTHON_VARIABLE      # a prefix's bin/python; another interpreter
    COUNTERPARTS, DIALECTS, PAIR_DIALECTS = COUNTERPARTS, DIALECTS, PAIR_DIALECTS
    COLOUR, DASHES = "tab:brown", (0, (5, 1, 1, 1))
    CITATION = {"key": "dadvand2010", "type": "article",
                "title": "An object-oriented environment for developing finite element codes for multi-disciplinary "
                         "applications",
                "author": "Dadvand, Pooyan and Rossi, Riccardo and O{\\~n}ate, Eugenio",
                "journal": "Archives of Computational Methods in Engineering", "volume": "17", "number": "3",
                "pages": "253--297", "year": "2010", "doi": "10.1007/s11831-010-9045-2"}
    STARTUP_S, SPHERE_STEP_S = 0.6, 7.5e-6      # bench_kratos.py: ~0.3 ms a step for 45 spheres
    CONTACT_LINES = ("MATERIALS = {", "RELATION = {")
    render_batch, read_batch = staticmethod(render_batch), staticmethod(read_batch)
    def binary(self):
        """The interpreter that runs: a build's own, else HARNESS_KRATOS_PYTHON, else the newest prefix's python
        ('' when there is none)."""
        if self._binary:
            return self._binary
        if self.VARIABLE in os.environ:
            return from_variable(self.VARIABLE, "")
        found = prefix_binaries(self)
        return found[-1][1] if found else ""

    def available(self, flavour=None):
        """Its interpreter is there and imports KratosMultiphysics and its DEMApplication."""
        return bool(probe(self.binary()).get("dem"))

    def missing_reason(self, flavour=None):
        """What was looked for, and where, when no interpreter here imports Kratos."""
        binary = self.binary()
        if not binary:
            return (f"no Kratos venv {directory()}/kratos-<release>/bin/python (bash tools/install_kratos.sh, or "
                    f"bash tools/setup.sh)")
        if self.VARIABLE in os.environ and not self._binary:
            what = "does not import" if which(binary) else "is not an executable file that imports"
            return f"{self.VARIABLE}={binary!r} {what} KratosMultiphysics' DEMApplication"
        return f"{binary} does not import KratosMultiphysics' DEMApplication (bash tools/install_kratos.sh)"

    def default_origin(self):
        """$HARNESS_KRATOS_PYTHON, or the prefix whose python runs."""
        if self.VARIABLE in os.environ:
            return f"${self.VARIABLE}"
        return f"prefix {os.path.dirname(os.path.dirname(self.binary()))}"

    def version(self):
        """The installed KratosMultiphysics distribution's version ('10.4.4'), 'unknown' where it cannot be read."""
        return probe(self.binary()).get("version") or "unknown"

    def executable_file(self):
        """The DEMApplication's compiled library (libKratosDEMCore.so, its contact laws), else the interpreter."""
        return probe(self.binary()).get("library") or self.binary()

    def build(self):
        """What ran: the installed version, the DEMApplication's library with its SHA-256, where the build is."""
        library = self.executable_file()
        return {"version": self.version(), "binary": library, "sha256": sha256(library),
                "origin": self.origin or self.default_origin()}

    def walls(self, law_name, options=None):
        """Any wall: a rigid face carries its own YOUNG_MODULUS and POISSON_RATIO, mixed with the sphere's as harness
        mixes them (InitializeContactWithFEM); rigid is a face RIGID_SCALE times stiffer than the sphere. A user's own
        input (the option `input`) gives the wall its one material."""
        return ("same",) if "input" in dict(options or {}) else ("same", "other", "rigid")

    def target_reason(self, law_name, scene, options=None):
        """Its pair dialects hold for a free target of the projectile's moduli (any size, density or spin): a held
        target still lends its mass to Kratos' damping, m* = m1 m2/(m1 + m2), and unequal moduli move each lever to
        R_i - d E_j/(E_i + E_j) (docs/kratos-dialect.md, measured there)."""
        reason = super().target_reason(law_name, scene)
        if reason or not scene.spheres:
            return reason
        projectile, target = scene.spheres
        if target.fixed:
            return "its damping takes a held target's mass (m* = m1 m2/(m1 + m2)): no dialect for a frozen target yet"
        if "input" in dict(options or {}):
            return ""                       # a user's own input gives both spheres its YOUNG_MODULUS and POISSON_RATIO
        if (target.E, target.nu) != (projectile.E, projectile.nu):
            return ("its lever arms split the overlap by the moduli (R_i - d E_j/(E_i + E_j)): no dialect for a "
                    "target of other moduli yet")
        return ""

    def run_inputs(self, flavour, count, timeout_s, workdir):
        return run_inputs(self.binary(), count, timeout_s, workdir)

    def typed_inputs(self, lines):
        return typed(lines)


ENGINE = Kratos()

__all__ = ["COUNTERPARTS", "DIALECTS", "ENGINE", "PAIR_DIALECTS", "PYTHON_VARIABLE", "TEMPLATES", "script"]
