"""Command line: `harness models | run | compare`; bad input ends in one line on stderr and exit code 2."""
import argparse
import json
import math
import sys

from . import __version__
from .errors import UserError

EXIT_OK, EXIT_DISAGREE, EXIT_USAGE = 0, 1, 2


class Parser(argparse.ArgumentParser):
    """argparse that reports a usage error as one line and exit code 2."""

    def error(self, message):
        raise UserError(message)


def number(text):
    """A finite float (the scene validates ranges)."""
    try:
        value = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a number: {text!r}") from None
    if not math.isfinite(value):
        raise argparse.ArgumentTypeError(f"not a finite number: {text!r}")
    return value


def number_list(text):
    """Comma-separated finite floats: '0.9,0.5,0.1'."""
    return tuple(number(part) for part in text.split(",") if part.strip() != "") or _empty(text)


def _empty(text):
    raise argparse.ArgumentTypeError(f"empty list: {text!r}")


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
    count = int(math.floor((stop - start) / step + 1e-9)) + 1
    if count > 100000:
        raise argparse.ArgumentTypeError(f"angle range has too many angles ({count})")
    return tuple(round(start + i * step, 12) for i in range(count))


def submodel(text):
    """KEY=VALUE sub-model override, e.g. tangential=mindlin:total."""
    key, sep, value = text.partition("=")
    if not sep or not key or not value:
        raise argparse.ArgumentTypeError(f"expected KEY=VALUE, got {text!r}")
    return key.strip(), value.strip()


def add_scene_options(parser, resolution=True):
    """Options that describe the scene (and, unless the command sets its own, the time step)."""
    from .scene import DEFAULT_EN
    g = parser.add_argument_group("scene")
    g.add_argument("--en", type=number_list, default=DEFAULT_EN, metavar="LIST",
                   help="target normal restitution coefficients, e.g. 0.9,0.5,0.1 (default %(default)s)")
    where = g.add_mutually_exclusive_group()
    where.add_argument("--angles", type=angle_list, metavar="A,B,..|A:B:STEP",
                       help="impact angles from the normal in degrees (default 1:89:2, 45 angles)")
    where.add_argument("--psi", type=number_list, metavar="LIST",
                       help="the paper's normalised impact angles Psi1* = 2 V_t/(mu (1 + e_n) V_n) at normal speed V_n")
    where.add_argument("--vt", type=number_list, metavar="LIST",
                       help="tangential speeds V_t [m/s] at normal speed V_n")
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
    g.add_argument("--wall", default="same", metavar="same|rigid|MATERIAL",
                   help="wall of the same material (the paper's case), rigid, or a preset material")
    g.add_argument("--with", dest="overrides", type=submodel, action="append", default=[], metavar="KEY=VALUE",
                   help="replace one sub-model: normal=, damping=, end=, tangential=, tangential-damping= "
                        "(e.g. --with tangential=mindlin:total --with end=tension)")
    g.add_argument("--liggghts-option", dest="liggghts_options", type=submodel, action="append", default=[],
                   metavar="KEY=VALUE", help="LIGGGHTS contact options: limitForce=on|off, tangential_damping=on|off, "
                   "ktToKnUser=on|off, tangential=history|no_history (deck and dialect follow them)")
    g.add_argument("--yade-linear", choices=("viscel", "cundall-strack"), default="viscel",
                   help="YADE law for linear-spring-dashpot: ViscEl (default) or elastic CundallStrack")
    g.add_argument("--yade-precision", choices=("double", "long-double", "float128", "mpfr150"), default="double",
                   help="YADE flavour (arithmetic) to run; inputs go in as exact decimal strings")
    if not resolution:
        return
    res = parser.add_argument_group("resolution")
    how = res.add_mutually_exclusive_group()
    how.add_argument("--steps-per-contact", type=int, default=1000, metavar="N",
                     help="time step = estimated contact time / N (default 1000)")
    how.add_argument("--dt", type=number, metavar="SECONDS",
                     help="one time step in seconds for every law and e_n (refused above the stability limit)")
    how.add_argument("--converged", action="store_true",
                     help="refine until results change < 1e-7 (relative to V), i.e. ~1e-7 from the exact solution")


def scene_from_args(args):
    """Build the validated Scene from parsed options."""
    from .scene import from_material
    angles = args.angles
    if args.psi is None and angles is None and args.vt is None:
        from .scene import DEFAULT_ANGLES
        angles = DEFAULT_ANGLES
    speed, speed_is = args.speed, "resultant"
    if args.normal_speed is not None:
        speed, speed_is = args.normal_speed, "normal"
    from .scene import DEFAULT_SPEED
    return from_material(args.material, radius=args.radius, E=args.E, nu=args.nu, rho=args.rho, mu=args.mu,
                         speed=DEFAULT_SPEED if speed is None else speed, speed_is=speed_is, e_n=tuple(args.en),
                         angles_deg=angles, psi1_star=args.psi, v_t=args.vt, omega0=args.omega0,
                         gravity=args.gravity, **wall_from_args(args.wall))


def wall_from_args(text):
    """--wall same|rigid|MATERIAL -> Scene wall fields."""
    if text in ("same", "rigid"):
        return {"wall": text}
    from .materials import get_material
    mat = get_material(text)
    return {"wall": "other", "wall_E": mat.E, "wall_nu": mat.nu}


def law_from_args(args):
    from .laws import compose
    return compose(args.model, dict(args.overrides))


def resolution_from_args(args):
    """--steps-per-contact N (a whole number >= 1) or --dt SECONDS (> 0), as plan_batch takes it."""
    from .solver.plan import FixedTimeStep
    if getattr(args, "dt", None) is not None:
        if not args.dt > 0.0:
            raise UserError(f"--dt must be a positive number of seconds, got {args.dt:g}")
        return FixedTimeStep(args.dt)
    if args.steps_per_contact < 1:
        raise UserError(f"--steps-per-contact must be >= 1, got {args.steps_per_contact}")
    return args.steps_per_contact


def simulate_from_args(args):
    from .solver.reference import simulate
    resolution = resolution_from_args(args)
    scene = scene_from_args(args)
    law = law_from_args(args)
    frame, _ = simulate(law, scene, steps_per_contact=resolution, converged=args.converged)
    return law, scene, frame


def support(law_name):
    """{engine: its model name or None} for every known engine (the support matrix)."""
    from .engines import ADAPTERS, INSTALLED
    return {name: (ADAPTERS[name].MODELS[law_name] if name in ADAPTERS and ADAPTERS[name].supports(law_name)
                   else None) for name in INSTALLED}


def cmd_models(args):
    from .laws import LAWS
    from .materials import MATERIALS
    if args.json:
        print(json.dumps([{"name": law.name, "provisional": law.provisional, "summary": law.summary,
                           "submodels": law.describe(), "engines": {"reference": "paper", **support(law.name)}}
                          for law in LAWS.values()], indent=2))
        return EXIT_OK
    rows = [("law", "normal", "damping", "end", "tangential", "tangential dashpot", "engines")]
    for law in LAWS.values():
        d = law.describe()
        engines = ", ".join(["reference"] + [f"{e} ({m})" for e, m in support(law.name).items() if m])
        rows.append((law.name + (" [provisional]" if law.provisional else ""), d["normal"], d["damping"], d["end"],
                     d["tangential"], d["tangential-damping"], engines))
    widths = [max(len(row[i]) for row in rows) for i in range(6)]
    for row in rows:
        print("  ".join(cell.ljust(w) for cell, w in zip(row, widths)) + "  " + row[6])
    print("\n[provisional]: the paper defines the law but its equations are not available; harness runs a "
          "reconstruction (docs/laws.md).")
    print("materials: " + ", ".join(MATERIALS) + " (default tcc13: the paper's sphere and wall)")
    return EXIT_OK


def cmd_run(args):
    from .results import write_csv
    check_output_file(args.output)
    law, scene, frame = simulate_from_args(args)
    write_csv(frame, args.output)
    if not args.quiet:
        bad = int((frame.status != "ok").sum())
        print(f"{law.name}: {len(frame)} impacts -> {args.output}" + (f" ({bad} not ok)" if bad else ""))
    return EXIT_OK


def check_output_file(path):
    import os
    directory = os.path.dirname(os.path.abspath(path))
    if not os.path.isdir(directory):
        raise UserError(f"cannot write {path}: directory {directory} does not exist")
    if os.path.isdir(path):
        raise UserError(f"cannot write {path}: it is a directory")


def cmd_render(args):
    """Write the engine input for every e_n of the scene without running it."""
    import os
    from .engines import ADAPTERS
    from .engines.runner import EngineFailure
    from .solver.codes import P_MAXSTEPS
    from .solver.plan import plan_batch
    if args.engine not in ADAPTERS:
        raise UserError(f"unknown engine {args.engine!r}; known: {', '.join(ADAPTERS)}")
    adapter = ADAPTERS[args.engine]
    scene, law = scene_from_args(args), law_from_args(args)
    if not adapter.supports(law.name):
        raise UserError(f"{args.engine} has no counterpart of {law.name}")
    if os.path.exists(args.output) and not os.path.isdir(args.output):
        raise UserError(f"output {args.output} exists and is not a directory")
    from .compare import engine_options
    options = engine_options(args, args.engine)
    dialect = adapter.dialect(law.name, options)
    texts = []
    for e_n in scene.e_n:
        batch = plan_batch(dialect, scene, e_n, resolution_from_args(args))
        name = f"{args.engine}-{law.name}-en{e_n:g}{adapter.INPUT_SUFFIX}"
        try:
            texts.append((name, adapter.render_batch(law, scene, batch, int(batch.params[:, P_MAXSTEPS].max()),
                                                     options)))
        except EngineFailure as exc:
            raise UserError(str(exc)) from None
    os.makedirs(args.output, exist_ok=True)
    for name, text in texts:
        with open(os.path.join(args.output, name), "w") as handle:
            handle.write(text)
    if not args.quiet:
        print("\n".join(os.path.join(args.output, name) for name, _ in texts))
    return EXIT_OK


def cmd_baseline(args):
    from .baseline import update
    if not args.update:
        raise UserError("baseline rewrites the committed expectations only with --update")
    frame, skipped = update(args.baseline)
    for line in skipped:
        print(f"skipped {line}")
    print(f"wrote {len(frame)} rows to {args.baseline}")
    return EXIT_OK


def cmd_check(args):
    from .baseline import check
    from .compare import text_table
    failures, skipped = check(args.baseline)
    for line in skipped:
        print(f"skipped {line}")
    if failures.empty:
        print("check: every metric within tolerance")
        return EXIT_OK
    print(f"check: {len(failures)} metric(s) outside tolerance")
    print(text_table(failures, list(failures.columns), {"baseline": "{:.10g}", "now": "{:.10g}",
                                                        "rel_diff": "{:.2e}", "tolerance": "{:.0e}"}))
    return EXIT_DISAGREE


def cmd_report(args):
    from .publish import rebuild
    print(f"wrote {rebuild(args.directory)}")
    return EXIT_OK


def cmd_paper(args):
    """The paper's figure set: paper.csv, paper-normal.csv, paper-sliding.csv and paper.html in DIR."""
    import os
    from .laws import LAWS
    from .paper import figure_set
    from .paper_report import NORMAL, OBLIQUE, SLIDING, write_paper_report
    from .results import write_csv
    laws = tuple(LAWS) if args.laws is None else tuple(n.strip() for n in args.laws.split(",") if n.strip())
    unknown = [n for n in laws if n not in LAWS]
    if unknown or not laws:
        raise UserError(f"unknown law(s) {', '.join(unknown) or args.laws!r}; known: {', '.join(LAWS)}")
    if args.steps_per_contact < 100:
        raise UserError(f"--steps-per-contact must be >= 100 for the paper's figures, got {args.steps_per_contact}")
    if os.path.exists(args.output) and not os.path.isdir(args.output):
        raise UserError(f"output {args.output} exists and is not a directory")
    report = (lambda what: None) if args.quiet else (lambda what: print(f"  done: {what}", file=sys.stderr))
    oblique, normal, sliding = figure_set(laws, args.steps_per_contact, progress=report)
    os.makedirs(args.output, exist_ok=True)
    write_csv(oblique, os.path.join(args.output, OBLIQUE))
    for table, name in ((normal, NORMAL), (sliding, SLIDING)):
        write_csv(table, os.path.join(args.output, name))
    path = write_paper_report(args.output, oblique, normal, sliding, "harness " + " ".join(sys.argv[1:]))
    if not args.quiet:
        print(text_table(sliding, ["model", "e_n_target", "simulated", "derived", "difference"],
                         {"simulated": "{:.4f}", "derived": "{:.4f}", "difference": "{:+.1e}"}))
    print(f"wrote {path}")
    return EXIT_OK


def text_table(frame, columns, formats):
    from .compare import text_table as table
    return table(frame, columns, formats)


def cmd_compare(args):
    from .compare import compare
    return compare(args)


def cmd_cost(args):
    from .cost_command import cost
    return cost(args)


def build_parser():
    parser = Parser(prog="harness", description="Cross-validate DEM contact force models against the literature "
                    "(Thornton, Cummins & Cleary 2013) and against LIGGGHTS and YADE.")
    parser.add_argument("--version", action="version", version=f"harness {__version__}")
    sub = parser.add_subparsers(dest="command", required=True, parser_class=Parser)
    p = sub.add_parser("models", help="laws, their sub-models and the engines that support each")
    p.add_argument("--json", action="store_true", help="machine-readable list")
    p.set_defaults(func=cmd_models)
    p = sub.add_parser("run", help="simulate one law over a scene with the reference engine, write a results CSV")
    p.add_argument("--model", required=True, help="law name (see `harness models`)")
    add_scene_options(p)
    p.add_argument("-o", "--output", required=True, help="results CSV to write")
    p.add_argument("--quiet", action="store_true", help="print nothing on success")
    p.set_defaults(func=cmd_run)
    p = sub.add_parser("render", help="write the engine's input deck/script for the scene without running it")
    p.add_argument("--model", required=True, help="law name (see `harness models`)")
    p.add_argument("--engine", required=True, help="liggghts")
    add_scene_options(p)
    p.add_argument("-o", "--output", required=True, metavar="DIR", help="directory for the inputs")
    p.add_argument("--quiet", action="store_true", help="print nothing on success")
    p.set_defaults(func=cmd_render)
    p = sub.add_parser("report", help="rebuild DIR/report.html from a compare directory, simulating nothing")
    p.add_argument("directory", metavar="DIR")
    p.set_defaults(func=cmd_report)
    p = sub.add_parser("baseline", help="rewrite the committed baseline matrix (reference/ by default)")
    p.add_argument("--update", action="store_true", help="required: rewriting expectations is deliberate")
    p.add_argument("--baseline", default="reference", metavar="DIR", help="baseline directory (default %(default)s)")
    p.set_defaults(func=cmd_baseline)
    p = sub.add_parser("check", help="recompute the baseline matrix; exit 1 listing every metric outside tolerance")
    p.add_argument("--baseline", default="reference", metavar="DIR", help="baseline directory (default %(default)s)")
    p.set_defaults(func=cmd_check)
    p = sub.add_parser("cost", help="accuracy against time: a ladder of steps per contact for the reference, each "
                                    "engine's dialect and each engine; cost.csv and the report")
    p.add_argument("--model", required=True, help="law name (see `harness models`)")
    p.add_argument("--engines", default=None, help="comma-separated engines (default: all that support the law)")
    add_scene_options(p, resolution=False)
    p.add_argument("--ladder", default=None, metavar="LIST",
                   help="steps per contact to try (default 5,10,20,50,100,200,500,1000,5000)")
    p.add_argument("-o", "--output", default="harness-out", metavar="DIR", help="output directory (default %(default)s)")
    p.add_argument("--quiet", action="store_true", help="print only where the files are")
    p.set_defaults(func=cmd_cost)
    p = sub.add_parser("paper", help="the paper's figure set: Psi2*, Omega*, e_t against Psi1* per law at its e_n, "
                                     "contact duration and peak force against e_n, where each law slides throughout")
    p.add_argument("--laws", default=None, metavar="LIST", help="comma-separated laws (default: every law)")
    p.add_argument("--steps-per-contact", type=int, default=2000, metavar="N", help="resolution (default 2000)")
    p.add_argument("-o", "--output", default="harness-paper", metavar="DIR", help="output directory (default %(default)s)")
    p.add_argument("--quiet", action="store_true", help="print only where the page is")
    p.set_defaults(func=cmd_paper)
    p = sub.add_parser("compare", help="reference vs every available engine; tables, results.csv, report.html")
    p.add_argument("--model", required=True, help="law name (see `harness models`)")
    p.add_argument("--engines", default=None, help="comma-separated engines (default: all that support the law)")
    add_scene_options(p)
    p.add_argument("-o", "--output", default="harness-out", metavar="DIR", help="output directory (default %(default)s)")
    p.add_argument("--quiet", action="store_true", help="print only the verdict")
    p.set_defaults(func=cmd_compare)
    return parser


def main(argv=None):
    try:
        args = build_parser().parse_args(argv)
        return args.func(args)
    except UserError as exc:
        print(f"harness: error: {exc}", file=sys.stderr)
        return EXIT_USAGE
    except KeyboardInterrupt:
        print("harness: interrupted; finished results were kept", file=sys.stderr)
        return 130


if __name__ == "__main__":
    sys.exit(main())
