"""What every command shares: the exit codes, argument types, the scene and resolution options, engine options, and
the keywords they become (the Python API's names, harness.runs.request)."""
import argparse
import math
import os
import re
import sys

from ..infra.errors import UserError
from ..runs.keywords import repeats
from ..infra.files import refuse_unless_regular

EXIT_OK, EXIT_DISAGREE, EXIT_USAGE, EXIT_ENGINE, EXIT_INTERNAL, EXIT_INTERRUPTED = 0, 1, 2, 3, 4, 130
EXIT_CODES = """exit codes:
  0  done; every engine compared agrees with its own formulas
  1  an engine disagrees with its own formulas (with `compare --require paper`, also: an engine deviates from
     the paper law), `check` found a metric outside tolerance, a closed-form check of `run --scene` failed, or
     a `stability` verdict failed
  2  bad input (one line on stderr says which); nothing was run
  3  an engine could not run (missing, mis-set, crashed, timed out: what and why is printed) while it was asked
     for by name or had runs that failed, or nothing was compared
  4  an internal error of harness (a bug: the traceback is printed)
  130 interrupted (Ctrl-C), 143 terminated (SIGTERM), 129 hung up (SIGHUP): engines stopped, temporary files
     removed, finished results kept
  141 its output was closed before it was all printed (`harness ... | head`): ended quietly, files kept"""

BENCHMARK_EXIT_CODES = """exit codes:
  0  done; every check made passes at the suite's published values, and every engine asked for by name ran
  1  a check fails: a quantity off its published value by more than its tolerance (the CSV and the page say
     which, and what caused it)
  2  bad input (one line on stderr says which); nothing was run
  3  no check failed, but an engine could not run (missing, crashed, timed out: what and why is printed) while it
     was asked for by name or had runs that failed, or no check was made
  4  an internal error of harness (a bug: the traceback is printed)
  130 interrupted (Ctrl-C), 143 terminated (SIGTERM), 129 hung up (SIGHUP): engines stopped, temporary files
     removed"""


class Parser(argparse.ArgumentParser):
    """argparse that reports a usage error as one line and exit code 2, and reads -1e4 as a number, not an option."""

    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        self._negative_number_matcher = re.compile(r"^-(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$")

    def error(self, message):
        raise UserError(message)

    def parse_known_args(self, args=None, namespace=None):
        """As argparse, but an option that takes one value given twice is refused (argparse keeps the last)."""
        args = list(sys.argv[1:] if args is None else args)
        seen = set()
        for word in args:
            if word == "--":
                break
            action = self._option_string_actions.get(word.split("=", 1)[0]) if word.startswith("--") else None
            if action is None or isinstance(action, (argparse._AppendAction, argparse._CountAction,
                                                     argparse._SubParsersAction)):
                continue
            if action.dest in seen:
                self.error(f"{word.split('=', 1)[0]} given more than once")
            seen.add(action.dest)
        return super().parse_known_args(args, namespace)


def number(text):
    """A finite float of normal size (the scene validates ranges): a subnormal one (0 < |x| < 2.2e-308) has lost
    digits already and overflows whatever divides by it."""
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a number: {text!r}") from None
    if not math.isfinite(value):
        raise argparse.ArgumentTypeError(f"not a finite number: {text!r}")
    if 0.0 < abs(value) < sys.float_info.min:
        raise argparse.ArgumentTypeError(f"not a number of normal size (0 or at least {sys.float_info.min:.3g} in "
                                         f"magnitude): {text!r}")
    return value


def number_list(text):
    """Comma-separated finite floats: '0.9,0.5,0.1' (an empty item is refused: '0.5,,0.9' is a typo)."""
    parts = text.split(",")
    if any(part.strip() == "" for part in parts):
        return _empty(text)
    values = tuple(number(part) for part in parts)
    repeated = repeats(values)
    if repeated:
        raise argparse.ArgumentTypeError(f"{', '.join(f'{v:g}' for v in repeated)} given more than once: {text!r}")
    return values


def _empty(text):
    raise argparse.ArgumentTypeError(f"empty list or list item: {text!r}")


MAX_ANGLES = 100000


def angle_list(text):
    """'A,B,C' or 'A:B:STEP' (inclusive of B when it falls on the grid), degrees."""
    if ":" not in text:
        return number_list(text)
    parts = text.split(":")
    if len(parts) != 3:
        raise argparse.ArgumentTypeError(f"angle range must be A:B:STEP, got {text!r}")
    start, stop, step = (number(p) for p in parts)
    if step <= 0 or stop < start:
        raise argparse.ArgumentTypeError(f"angle range needs STEP > 0 and B >= A, got {text!r}")
    if stop > start and step > stop - start:
        raise argparse.ArgumentTypeError(f"angle range {text!r} holds {start:g} alone (STEP beyond B - A); give "
                                         f"--angles {start:g} or a smaller STEP")
    count = (stop - start) / step + 1e-9 + 1       # inf when B - A overflows: refused as too many
    if count > MAX_ANGLES:
        raise argparse.ArgumentTypeError(f"angle range has too many angles ({count:.3g}; at most {MAX_ANGLES})")
    return tuple(round(start + i * step, 12) for i in range(int(count)))


def submodel(text):
    """KEY=VALUE sub-model override, e.g. tangential=mindlin:total."""
    key, sep, value = text.partition("=")
    if not sep or not key or not value:
        raise argparse.ArgumentTypeError(f"expected KEY=VALUE, got {text!r}")
    return key.strip(), value.strip()


def engine_option(text):
    """ENGINE:KEY=VALUE, e.g. liggghts:limitForce=on."""
    engine, sep, rest = text.partition(":")
    key, sep2, value = rest.partition("=")
    if not (sep and sep2 and engine and key and value):
        raise argparse.ArgumentTypeError(f"expected ENGINE:KEY=VALUE, got {text!r}")
    return engine.strip(), key.strip(), value.strip()


def add_scene_options(parser, resolution=True):
    """Options that describe the scene, the law's sub-models, the engines' options and (unless the command sets its
    own) the time step."""
    from ..scenes.scene import DEFAULT_EN     # numpy's: when a command with a scene is parsed, not for `harness --help`
    g = parser.add_argument_group("scene")
    g.add_argument("--en", type=number_list, default=DEFAULT_EN, metavar="LIST",
                   help="target normal restitution coefficients, e.g. 0.9,0.5,0.1 (default: the paper's "
                        f"{','.join(f'{e:g}' for e in DEFAULT_EN)})")
    where = g.add_mutually_exclusive_group()
    where.add_argument("--angles", type=angle_list, metavar="A,B,..|A:B:STEP",
                       help="impact angles from the normal in degrees (default 1:89:2, 45 angles)")
    where.add_argument("--psi", type=number_list, metavar="LIST",
                       help="the paper's normalised impact angles Psi1* = 2 V_t/(mu (1 + e_n) V_n) at normal speed V_n")
    where.add_argument("--vt", type=number_list, metavar="LIST", help="tangential speeds V_t [m/s] at normal speed V_n")
    g.add_argument("--mu", type=number, help="friction coefficient (default: the material's)")
    g.add_argument("--material", default="tcc13",
                   help="material preset (see `harness models`); default tcc13, the paper's sphere and wall")
    for name, unit in (("radius", "m"), ("E", "Pa"), ("nu", "-"), ("rho", "kg/m^3")):
        g.add_argument(f"--{name}", type=number, help=f"override the material's {name} [{unit}]")
    speed = g.add_mutually_exclusive_group()
    speed.add_argument("--speed", type=number, metavar="V",
                       help="impact speed [m/s]: the resultant with --angles, the normal speed with --psi or --vt "
                            "(default 5, the paper's)")
    speed.add_argument("--normal-speed", type=number, metavar="V",
                       help="hold the normal speed V_n [m/s] fixed, V_t = V_n tan(angle) (Kratos' way of drawing the "
                            "paper's figures)")
    g.add_argument("--omega0", type=number, default=0.0, help="initial spin omega_y [rad/s] (default 0)")
    g.add_argument("--gravity", type=number, default=0.0, help="gravity towards the wall [m/s^2] (default 0)")
    g.add_argument("--wall", default="same", metavar="same|rigid|MATERIAL|E=PA,nu=R",
                   help="wall of the same material (the paper's case), rigid, a preset material, or E and nu")
    t = parser.add_argument_group("target (default: the wall)")
    t.add_argument("--target", default="wall", choices=("wall", "sphere"),
                   help="what the sphere hits: the wall, or a sphere at rest (the sweep's velocities are then the "
                        "relative ones; the results add each body's velocities after the collision)")
    t.add_argument("--target-radius", type=number, metavar="M", help="the target sphere's radius (default: the "
                   "projectile's)")
    t.add_argument("--target-material", default="same", metavar="same|MATERIAL|E=PA,nu=R,rho=KG_M3",
                   help="the target sphere's material (default: the projectile's)")
    t.add_argument("--target-omega", type=number, default=0.0, metavar="RAD_S",
                   help="the target sphere's spin about the same axis as --omega0 (default 0)")
    t.add_argument("--target-fixed", action="store_true", help="the target sphere neither moves nor turns")
    g.add_argument("--with", dest="overrides", type=submodel, action="append", default=[], metavar="KEY=VALUE",
                   help="replace one sub-model: normal=, damping=, end=, tangential=, tangential-damping= "
                        "(e.g. --with tangential=mindlin:incremental)")
    if not resolution:
        return
    res = parser.add_argument_group("resolution")
    how = res.add_mutually_exclusive_group()
    how.add_argument("--steps-per-contact", type=int, metavar="N",
                     help="time step = estimated contact time / N (default 1000)")
    how.add_argument("--dt", type=number, metavar="SECONDS",
                     help="one time step in seconds for every law and e_n (refused above the stability limit)")
    how.add_argument("--converged", action="store_true",
                     help="integrate the exact limit: results within ~1e-6 of the h -> 0 solution")


def add_start_options(parser):
    """--gap and --at-times: where each impact starts, and the times its state is recorded at (states.csv)."""
    g = parser.add_argument_group("start and states during contact")
    g.add_argument("--gap", type=number, default=0.0, metavar="METRES",
                   help="distance between the surfaces at t = 0: the sphere approaches from there (default 0: it "
                        "starts touching)")
    g.add_argument("--at-times", dest="at_times", type=number_list, default=(), metavar="T1,T2,...",
                   help="times [s] from the start at which each impact's state (overlap, forces, velocities) is "
                        "written to states.csv")


def add_output_options(parser, json=False, verbose=False):
    """--quiet (and --verbose, --json where a command has them), meaning the same in every command."""
    out = parser.add_argument_group("output")
    out.add_argument("--quiet", action="store_true",
                     help="print only the last line (the outcome and where the files are), no progress")
    if verbose:
        out.add_argument("--verbose", action="store_true", help="print every table, not only the summary")
    if json:
        out.add_argument("--json", action="store_true", help="print one JSON summary on stdout and nothing else there")


def add_engine_options(parser):
    """--engines and --engine-option, as every engine declares its options (docs/engines.md)."""
    from ..engines import ENGINES
    declared = "; ".join(f"{name}:{key}={'|'.join(o.values)}" for name, engine in ENGINES.items()
                         for key, o in engine.OPTIONS.items())
    parser.add_argument("--engines", default=None, metavar="LIST",
                        help=f"comma-separated engines of {', '.join(ENGINES)} (default: every engine that supports "
                             "the law; `reference` alone runs the reference solver only)")
    parser.add_argument("--engine-option", dest="engine_options", type=engine_option, action="append", default=[],
                        metavar="ENGINE:KEY=VALUE", help=f"an engine's option, repeatable: {declared}")
    add_engine_input(parser)


def add_engine_input(parser):
    """--engine-input ENGINE=TEXT (harness.engines.user_inputs)."""
    parser.add_argument("--engine-input", dest="engine_inputs", action="append", default=[], metavar="ENGINE=TEXT",
                        help="your own contact input as the engine takes it, repeatable: lammps='hooke 1e6 0.5 "
                             "tangential linear_history 2.8e5 0.5 0.4' (the words after pair_coeff * *, or a "
                             "classic style and its arguments), or ENGINE=@FILE (the contact lines of a deck)")


def engines_from(text):
    """--engines LIST -> tuple of names (None: the default); an empty item ('liggghts,') is refused as a typo, names
    are checked by the request (known, each once)."""
    if text is None:
        return None
    names = tuple(n.strip() for n in text.split(","))
    if not any(names):
        raise UserError(f"--engines needs at least one engine name, got {text!r}")
    if not all(names):
        raise UserError(f"--engines has an empty item (a stray comma?): {text!r}")
    return names


def keywords(args, resolution=True):
    """The options as the API's keywords (harness.runs.request.Request.from_keywords)."""
    out = dict(en=args.en, angles=args.angles, psi=args.psi, vt=args.vt, mu=args.mu, material=args.material,
               radius=args.radius, E=args.E, nu=args.nu, rho=args.rho, speed=args.speed,
               normal_speed=args.normal_speed, omega0=args.omega0, gravity=args.gravity, wall=args.wall,
               target=args.target, target_radius=args.target_radius, target_material=args.target_material,
               target_omega=args.target_omega, target_fixed=args.target_fixed,
               overrides=tuple(args.overrides))
    if hasattr(args, "gap"):
        out.update(gap=args.gap, at_times=args.at_times)
    if resolution:
        out.update(steps_per_contact=args.steps_per_contact, dt=args.dt, converged=args.converged)
    if hasattr(args, "engines"):
        out.update(engines=engines_from(args.engines), engine_options=args.engine_options)
    if getattr(args, "engine_inputs", None):
        out.update(engine_input=args.engine_inputs)
    return out


def check_output_file(path):
    """A results file the user names: a new path or a regular file, in a directory that exists and is writable."""
    if not path:
        raise UserError("the output path is empty")
    directory = os.path.dirname(os.path.abspath(path))
    if not os.path.isdir(directory):
        raise UserError(f"cannot write {path}: directory {directory} does not exist")
    refuse_unless_regular(path)
    writable(directory, path)


def check_output_directory(path, what="output directory"):
    """An output directory the user names: an existing, writable directory, or a new one below a writable one."""
    if not path:
        raise UserError(f"the {what} is empty")
    if os.path.lexists(path) and not os.path.isdir(path):
        raise UserError(f"{what.split()[0]} {path} exists and is not a directory")
    existing = os.path.abspath(path)
    while not os.path.isdir(existing):
        if os.path.lexists(existing):
            raise UserError(f"cannot create {path}: {existing} exists and is not a directory")
        existing = os.path.dirname(existing)
    writable(existing, path)


def check_store(path):
    """--store STORE: a directory (a campaign store) or a new one below a writable directory."""
    if path is not None:
        check_output_directory(path, "store directory")


def check_entries(directory, files=(), directories=()):
    """Before anything is written into DIR: each of its entries a command would write or read back is absent or a
    regular file (each of `directories` absent or a directory), so that no refusal comes after other files were
    written and no FIFO is ever opened."""
    if not os.path.isdir(directory):
        return
    for name in files:
        refuse_unless_regular(os.path.join(directory, name))
    for name in directories:
        path = os.path.join(directory, name)
        if os.path.lexists(path) and (os.path.islink(path) or not os.path.isdir(path)):
            raise UserError(f"will not write into {path}: it is not a directory")


def check_results_directory(directory):
    """A compare's or cost study's -o DIR: a directory whose entries (the tables, run records and report that
    `compare`, `cost` and `report` write or read, the lock, the partial runs, the figures' folder) may all be
    written."""
    from ..infra.lock import LOCK
    from ..runs.outputs import DIRECTORY_FILES
    from ..runs.partial import PARTIAL
    from ..views.figure_files import FIGURES
    check_output_directory(directory)
    check_entries(directory, DIRECTORY_FILES + (LOCK,), (PARTIAL, FIGURES))


def writable(directory, path):
    """Refuse, in one line, a directory this process cannot create files in (read-only, /proc, permissions)."""
    import tempfile
    try:
        with tempfile.TemporaryFile(dir=directory):
            pass
    except OSError as exc:
        raise UserError(f"cannot write {path}: {directory} is not writable ({exc.strerror})") from None
