"""What an engine is to harness: the Engine base class, which carries what every engine shares (its executable, version
and status, its dialects composed from sub-models, batching in scratch directories, failures with their log tails)
and declares every hook a command uses; an engine is a subclass that overrides what differs (docs/engines.md)."""
import copy
import dataclasses
import importlib
import os
import sys
from functools import lru_cache

from ..infra.errors import UserError
from ..infra.programs import which
from .builds import sha256
from .executable import banner, chosen, missing, present
from .protocol import InputRange, Status, check_options as check_declared
from .runner import EngineFailure, read_tail

DOUBLE = "double (IEEE 754 binary64)"


SCENES_BEYOND_IMPACT = ("free-fall", "bounce", "rest", "slide-to-roll", "stack")   # what the four engines run


class Engine:
    """An engine: one subpackage of harness/engines holding a subclass of this, and one line of the registry
    (engines/__init__.py). The defaults are those of an external engine run as a subprocess on batched inputs."""
    NAME = ""                   # its name in the registry, in --engines and in the results' engine column
    DIALECT = None              # the label of its dialects (the results' dialect column) when not NAME
    INPUT_SUFFIX = ".in"        # of the input `harness render` writes
    INPUT_NAME = "in.harness"   # of the input in each batch's own directory
    EXECUTABLE = ""             # its executable's name on PATH
    VARIABLE = ""               # the environment variable naming another executable (a custom build, a test's fake)
    PACKAGE = ""                # the Debian package that installs it
    OPTIONS = {}                # option name -> protocol.Option, surfaced by `--engine-option`
    COUNTERPARTS = {}           # harness law -> the engine's name of its model
    DIALECTS = {}               # harness law -> the sub-models that make the paper law compute what it computes
    PAIR_DIALECTS = {}          # the same between two spheres, for the laws its inputs run against a sphere
    WITH = {}                   # (sub-model key, label) of `--with` -> the engine options whose inputs compute it
    KNOWN_CAUSES = {}           # (law, finding kind) -> the documented cause, printed with the finding
    COLOUR = None               # of its curves in every figure (matplotlib colour)
    CITATION = {}               # the BibTeX fields of the publication its developers ask users to cite (harness cite)
    DASHES = None               # of the curves of its dialect (matplotlib line style)
    VERIFIED = ()               # versions (their start, as `harness engines` prints them) its dialects were checked on
    STARTUP_S = 1.0             # campaign --dry-run estimate: seconds per process start
    RESTITUTION_INPUTS = InputRange(0.01)   # the e calibrate searches its inputs over (docs/calibrate.md)
    CONTACT_LINES = ()          # how the lines of its input that set the contact law begin (calibrate prints them)
    STARTS_APART = ()           # the targets its inputs start a gap apart from and record states at given times for
    SPHERE_STEP_S = 1e-6        # and per sphere-step (docs/performance.md)
    SCENE_KINDS = ()            # the scene kinds beyond impact its inputs run (names of harness.scenes.catalogue)
    START_FRICTION = True       # its set-up's forces of a contact present at step 0 include the tangential force

    @property
    def dialect_label(self):
        return self.NAME if self._binary else self.DIALECT or self.NAME

    def sources(self):
        """The folders of source whose change changes its results (its own subpackage): stored runs are keyed on
        them."""
        return (os.path.dirname(os.path.abspath(sys.modules[type(self).__module__].__file__)),)

    # --- where it is and what it is -----------------------------------------------------------------------------
    _binary = None              # a build's own executable (Engine.at); None: the default build
    origin = ""                 # where a build came from (PATH, the variable, a prefix, a path given)

    @property
    def code(self):
        """Its name in the registry, without a build's `@version`."""
        return self.NAME.partition("@")[0]

    def binary(self):
        """The executable that runs: a build's own, else the path in VARIABLE, else EXECUTABLE on PATH."""
        return self._binary or chosen(self.VARIABLE, self.EXECUTABLE)

    def available(self, flavour=None):
        """It is installed here (in `flavour`, for an engine that has several)."""
        if self._binary:
            return os.access(self._binary, os.X_OK)
        return present(self.VARIABLE, self.EXECUTABLE)

    def default_origin(self):
        """Where the default build comes from: the variable naming it, else PATH (and the package that puts it
        there)."""
        if self.VARIABLE and self.VARIABLE in os.environ:
            return f"${self.VARIABLE}"
        return f"PATH (Debian package {self.PACKAGE})" if self.PACKAGE else "PATH"

    def prefix_binary(self, prefix):
        """The executable of a build installed in its own prefix (tools/install_lammps.sh): PREFIX/bin/EXECUTABLE."""
        return os.path.join(prefix, "bin", self.EXECUTABLE)

    def at(self, binary, origin):
        """This engine run from another executable, as its own engine named `code@version`."""
        build = copy.copy(self)
        build._binary, build.origin = binary, origin
        build.NAME = f"{self.code}@{build.version()}"
        return build

    def executable_file(self):
        """The file whose content is the engine (hashed into every result): the binary itself."""
        return which(self.binary()) or self.binary()

    def build(self):
        """What ran: {version, binary, sha256 of its executable file, origin} (the record of every result)."""
        path = which(self.binary())
        return {"version": self.version(), "binary": path or "",
                "sha256": sha256(self.executable_file()),
                "origin": self.origin or self.default_origin()}

    def dialect_note(self):
        """'' when its dialects were checked on this version, else one line saying which versions they were."""
        version = self.version()
        if not self.VERIFIED or any(version == v or version.startswith(v + ".") for v in self.VERIFIED):
            return ""
        return f"{self.code}'s dialects were checked on {', '.join(self.VERIFIED)}, not on {version}"

    def missing_reason(self, flavour=None):
        """What was looked for, and where, when it is not installed."""
        return missing(self.VARIABLE, self.EXECUTABLE, self.PACKAGE)

    def version(self):
        """Its version, read without writing into the user's directory."""
        return banner_version(self, self.binary())

    def read_version(self, text):
        """Its version from the head of what `EXECUTABLE -h` prints."""
        return "unknown"

    def flavour(self, options):
        """The flavour (arithmetic, build) the options ask for; runs of one flavour share processes."""
        return None

    def arithmetic(self, options):
        """The floating-point arithmetic of a run with these options."""
        return DOUBLE

    def status(self, law_name, options=None):
        """Installed (in the flavour the options ask for), and able to run `law_name` (a verified dialect exists)?"""
        flavour = self.flavour(dict(options or {}))
        if not self.available(flavour):
            return Status(self.NAME, False, self.missing_reason(flavour))
        if not self.supports(law_name):
            return Status(self.NAME, False, f"{self.NAME} has no counterpart of {law_name}")
        return Status(self.NAME, True)

    # --- what it computes ---------------------------------------------------------------------------------------
    def supports(self, law_name):
        """Has a counterpart of the law and a verified dialect of it."""
        return law_name in self.COUNTERPARTS and law_name in self.DIALECTS

    def walls(self, law_name, options=None):
        """The walls its inputs model for the law: 'same' (the sphere's material), and 'other', 'rigid' where they
        can."""
        return ("same",)

    def target_reason(self, law_name, scene, options=None):
        """Why its inputs (with these options) cannot put the sphere against the scene's target (a wall, or a sphere:
        scene.spheres), '' when they can."""
        if scene.spheres and law_name not in self.PAIR_DIALECTS:
            return f"its {law_name} inputs have no sphere target yet"
        return ""

    def check_options(self, law_name, options):
        """The options given, validated against the declared ones: one clear line for a bad one."""
        return check_declared(self.NAME, self.OPTIONS, options)

    def composition(self, law_name, options, target):
        """Its dialect of the law for its own options: the paper law with DIALECTS (PAIR_DIALECTS against a
        sphere) in place of the paper's sub-models."""
        from ..laws import compose, replace_submodels      # the kernels: when a dialect is asked for, not listed
        self.check_options(law_name, options)
        chosen_ = self.PAIR_DIALECTS if target == "sphere" else self.DIALECTS
        return replace_submodels(compose(law_name), chosen_[law_name], self.dialect_label)

    def dialect(self, law_name, options=None, target="wall"):
        """The law as this engine computes it (a harness.laws.Law), for the options given, against a wall or a
        sphere (the two-sphere dialect, reduced to the equivalent wall impact). An option `with:KEY` (with_options)
        replaces sub-model KEY of the dialect, which the engine's inputs then follow."""
        from .user_inputs import INPUT_OPTION
        from ..laws import replace_submodels
        options, submodels = split_submodels(options)
        text = options.pop(INPUT_OPTION, None)
        law = self.input_dialect(law_name, text, target) if text is not None else \
            self.composition(law_name, options, target)
        law = replace_submodels(law, submodels) if submodels else law
        return law if law.dialect == self.dialect_label else dataclasses.replace(law, dialect=self.dialect_label)

    def input_dialect(self, law_name, text, target):
        """What this build computes with a user's own input `text` (--engine-input), named as the law it is compared
        with: its vocabulary's composition for this release (harness.engines.user_inputs)."""
        from .user_inputs import parse
        version = self.version()
        law = parse(self.code, text, version).composition(target, version)
        return dataclasses.replace(law, name=law_name)

    def release_dialect(self, law_name, release):
        """Its dialect of the law against a wall as it was for another release (the same where its formulas do not
        depend on the release)."""
        return self.dialect(law_name)

    def with_options(self, law_name, overrides, options=None, target="wall"):
        """The engine options (those given, and more) that make its inputs compute the law with `overrides` (--with
        KEY=VALUE); a UserError naming the first they cannot: an override maps where WITH declares options for it
        and the dialect with them then carries it (or carries it already)."""
        options = dict(options or {})
        for key, value in overrides.items():
            if self._carries(law_name, options, target, key, value):
                continue
            mapped = self.WITH.get((key, value), {})
            clash = [k for k in mapped if k in options and options[k] != mapped[k]]
            if clash:
                raise UserError(f"--with {key}={value} needs {self.NAME} option {clash[0]}={mapped[clash[0]]}, "
                                f"not {options[clash[0]]}")
            if not mapped or not self._carries(law_name, {**options, **mapped}, target, key, value):
                raise UserError(f"{self.NAME} cannot follow --with {key}={value}: its {law_name} inputs have no "
                                f"setting that computes it (docs/{self.NAME}-dialect.md)")
            options.update(mapped)
        return options

    def _carries(self, law_name, options, target, key, value):
        try:
            dialect = self.dialect(law_name, options, target)
        except UserError:               # options its inputs refuse for this law or target
            return False
        from ..laws import compose, replace_submodels
        wanted = replace_submodels(compose(law_name), {key: value}).describe()[key]
        return dialect.describe()[key] == wanted

    def restitution_inputs(self, law_name):
        """The restitution coefficients its inputs take for the law (InputRange), as calibrate searches them."""
        return self.RESTITUTION_INPUTS

    def contact_lines(self, text):
        """The lines of a rendered input that set the contact law (those CONTACT_LINES begin, indented or not), each
        with the lines that continue it until its brackets close: what a user pastes into an input of their own."""
        lines, out, open_brackets = text.splitlines(), [], 0
        for line in lines:
            if open_brackets > 0 or (line.lstrip().startswith(self.CONTACT_LINES) and self.CONTACT_LINES):
                out.append(line)
                open_brackets = max(open_brackets + sum(line.count(c) for c in "([{")
                                    - sum(line.count(c) for c in ")]}"), 0)
        return out

    def typed_inputs(self, lines):
        """[(name, value)] of what its contact lines set, named as its manual names them."""
        return []

    def precision_runs(self, law, scene, options):
        """Runs of the plan that check its own arithmetic beside a comparison (docs/engines.md), () when none."""
        return ()

    def known_cause(self, law_name, kind):
        """The documented cause of a finding of its dialect, or ''."""
        return self.KNOWN_CAUSES.get((law_name, kind), "")

    def campaign_seconds(self, impacts, steps):
        """A campaign's --dry-run estimate of one run: a process start and its sphere-steps."""
        return self.STARTUP_S + self.SPHERE_STEP_S * impacts * steps

    # --- running it ---------------------------------------------------------------------------------------------
    def render_batch(self, paper_law, scene, spec, options=None, observe=False):
        """The text of the input that runs one run's spec (solver/resolution.py's RunSpec: its impacts, time step, step
        cap and output cadence); an EngineFailure refuses it, with the reason."""
        raise NotImplementedError(f"{self.NAME} renders no input")

    def run_inputs(self, flavour, count, timeout_s, workdir):
        """Run the inputs batch<k>/INPUT_NAME (k < count) of workdir: each batch's wall seconds, or the
        EngineFailure that ended it."""
        raise NotImplementedError(f"{self.NAME} runs no input")

    def read_batch(self, scene, spec, directory, observe=False):
        """The final state of a finished run's spec from `directory`: v_n1, v_t1, omega1 and separated per impact;
        with `observe` also t_contact, f_n_max and overlap_max."""
        raise NotImplementedError(f"{self.NAME} writes no output")

    def run(self, runs):
        """Each run of the plan (one batch: a law, an e_n, every impact) as (results frame, failure or None), each
        told what to run by run.spec; the runs of one flavour share processes, one per core."""
        from .batches import run_grouped        # loaded by runs/before_threads.py; here, not when engines are listed
        return run_grouped(self.NAME, self.build(), runs, self.INPUT_NAME,
                           lambda run: self.render_batch(run.law, run.scene, run.spec, run.options_dict, run.observe),
                           lambda run: self.flavour(run.options_dict), self.run_inputs,
                           lambda run, directory: self.read_batch(run.scene, run.spec, directory, run.observe))

    def run_batch(self, paper_law, scene, spec, timeout_s, workdir, options=None, observe=False):
        """One run's spec alone in `workdir`: (final state as read_batch gives it, wall seconds, log tail)."""
        return self.run_alone(self.render_batch(paper_law, scene, spec, options, observe), options, timeout_s, workdir,
                              lambda directory: self.read_batch(scene, spec, directory, observe))

    def run_alone(self, text, options, timeout_s, workdir, read):
        """Run one input `text` alone in workdir/batch0 through run_inputs (process group, timeout, log tail):
        (read(directory), wall seconds, log tail); an EngineFailure carries the log tail."""
        directory = os.path.join(workdir, "batch0")
        os.makedirs(directory, exist_ok=True)
        with open(os.path.join(directory, self.INPUT_NAME), "w") as handle:
            handle.write(text)
        wall, = self.run_inputs(self.flavour(dict(options or {})), 1, timeout_s, workdir)
        log_tail = read_tail(os.path.join(workdir, "engine.log"))
        if isinstance(wall, EngineFailure):
            raise wall
        try:
            return read(directory), wall, log_tail
        except EngineFailure as exc:
            raise EngineFailure(str(exc), exc.log_tail or log_tail) from None

    # --- scenes beyond one impact (harness run --scene; docs/design.md) -----------------------------------------
    def scene_reason(self, kind, law_name, options=None):
        """Why it cannot run scene `kind` (a catalogue name) for `law_name` with these options, '' when it can."""
        if kind not in self.SCENE_KINDS:
            return f"{self.NAME} runs no {kind} scene yet"
        if not self.supports(law_name):
            return f"{self.NAME} has no counterpart of {law_name}"
        return ""

    def render_scene(self, kind, case, grid, options=None):
        """The text of the input that runs one scene case (harness.studies.scenes.Case) of scene `kind`: the bodies,
        dt, steps, gravity and ceiling of case.variant, the counterpart of its paper law case.variant.law calibrated
        at case.e_n and variant.speed with friction variant.mu, and exactly the scene's effects (gravity only where
        variant.gravity > 0, the wall at z = 0, a ceiling only where variant.ceiling is set, sphere-sphere contacts
        only with several spheres); its output is what read_scene needs and no more. An EngineFailure refuses it."""
        raise NotImplementedError(f"{self.NAME} renders no scene")

    def read_scene(self, kind, case, grid, directory):
        """A finished scene run's harness.solver.system_run.SystemResult for one variant, read from `directory`,
        with the fields the kind's checks read filled as the small-system integrator fills them: `grid` (the times
        asked for), `trace` (1, len(grid), bodies, TRACE: x z vx vz w) at those times, `pairs` (contact_pairs order),
        `events`/`n_events` (bounce: each touch with V_n < 0 the velocity before the contact force acts, each
        parting with V_n > 0 at the end of its step), `final` (1, pairs, overlap F_n F_t) at the end (rest, stack),
        `metrics` (M_STATUS; M_GAIN the largest energy gain after settling for rest, M_STEPS, M_TIME); what the
        kind does not use is NaN. An EngineFailure when the output is missing or short."""
        raise NotImplementedError(f"{self.NAME} writes no scene output")

    def run_scene(self, kind, case, grid, timeout_s, workdir, options=None):
        """One scene case run alone in workdir/batch0 through run_inputs (process group, timeout, log tail):
        (read_scene's SystemResult, wall seconds, log tail); an EngineFailure carries the log tail."""
        return self.run_alone(self.render_scene(kind, case, grid, options), options, timeout_s, workdir,
                              lambda directory: self.read_scene(kind, case, grid, directory))

    def render(self, run):
        """(file name, text) of the input a run would give the engine (harness render); a refusal of its input
        rules is the user's to fix, so it is a UserError."""
        try:
            text = self.render_batch(run.law, run.scene, run.spec, run.options_dict)
        except EngineFailure as exc:
            raise UserError(str(exc)) from None
        return f"{self.NAME}-{run.law.name}-en{run.e_n:g}{self.INPUT_SUFFIX}", text


@lru_cache(maxsize=None)
def banner_version(engine, path):
    """An engine's version from the banner the executable at `path` prints (read once per executable)."""
    return engine.read_version(banner(path, engine.NAME))


WITH_PREFIX = "with:"       # an option `with:KEY`, a --with KEY=VALUE mapped by Engine.with_options, sets a sub-model


def split_submodels(options):
    """(engine options, sub-model replacements) of an engine's options: an option `with:KEY` replaces sub-model KEY
    of its dialect."""
    options = dict(options or {})
    return options, {key[len(WITH_PREFIX):]: options.pop(key) for key in list(options) if key.startswith(WITH_PREFIX)}


class SceneScripts:
    """Scene hooks of an engine whose package's scene.py renders and reads them (`scene_reason`, `render_scene`,
    `read_scene` there, imported only when a scene runs)."""
    SCENE_KINDS = SCENES_BEYOND_IMPACT

    def _scene_module(self):
        return importlib.import_module(f"{type(self).__module__}.scene")

    def scene_reason(self, kind, law_name, options=None):
        """Why it cannot run scene `kind` for `law_name` with these options, '' when it can."""
        return self._scene_module().scene_reason(kind, law_name, options)

    def render_scene(self, kind, case, grid, options=None):
        return self._scene_module().render_scene(kind, case, grid, options)

    def read_scene(self, kind, case, grid, directory):
        return self._scene_module().read_scene(kind, case, grid, directory)
