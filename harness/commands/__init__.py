"""The command line: one thin module per command; bad input ends in one line on stderr and exit code 2."""
import argparse
import errno
import os
import signal
import sys
import time

from ..infra.errors import EngineMissing, UserError
from ..infra.programs import absolute_path
from ..infra.version import __version__
from .options import EXIT_CODES, EXIT_ENGINE, EXIT_INTERNAL, EXIT_INTERRUPTED, EXIT_USAGE, Parser
from .stopping import Stopped, stop_behind, stop_on_signals

EXIT_CLOSED_OUTPUT = 128 + signal.SIGPIPE


COMMANDS = {   # name -> (its module, its summary): the parser lists every command, parsers.MODULE_parser builds the
    #            chosen one's options and harness.commands.MODULE runs it
    "models": ("models", "the laws, their sub-models and the engines that support each"),
    "scenes": ("scenes", "every scene kind: its parameters, the effects it needs and its closed-form checks"),
    "engines": ("engines", "every engine and build found here (pick one with --engines ENGINE@VERSION)"),
    "run": ("run", "simulate one law over a scene with the reference solver, write a results CSV"),
    "compare": ("compare", "the paper law against each engine and its dialect; tables, results.csv, report.html"),
    "calibrate": ("calibrate", "the engine inputs that bring an engine nearest the paper law on a scene, and the time "
                               "step a tolerance needs"),
    "cost": ("cost", "accuracy against time: a ladder of steps per contact for the paper law, each engine's dialect "
                     "and each engine; cost.csv and the report"),
    "stability": ("stability", "the largest stable time step per hard case or scene and engine, by bisection, beside "
                               "the step 1e-3 accuracy needs and a fifth of the Rayleigh time; stability.csv"),
    "paper": ("paper", "the paper's figure set: Psi2*, Omega*, e_t against Psi1* per law at its e_n, contact duration "
                       "and peak force against e_n, where each law slides throughout"),
    "benchmark": ("benchmark", "a published verification suite (Chung & Ooi 2011's eight tests) on the reference and "
                               "the engines: every quantity against its closed form"),
    "compile": ("compile", "compile every kernel the commands use into the numba cache now, so that no first run "
                           "waits for it"),
    "explain": ("explain", "what your own engine input computes: achieved e_n, e_t, Omega* and contact time, the "
                           "paper law it is nearest, the same law in other inputs, and calibrate's advice"),
    "render": ("render", "write an engine's input deck/script for the scene without running it"),
    "report": ("report", "rebuild DIR/report.html from a compare or cost directory (DIR/scene.html from a scene "
                         "run's), simulating nothing"),
    "check": ("check", "recompute the baseline matrix; exit 1 listing every metric outside tolerance"),
    "baseline": ("check", "rewrite the committed baseline matrix on purpose"),
    "campaign": ("campaign", "run a matrix of comparisons from a TOML file into a Parquet store that resumes"),
    "query": ("query", "one read-only SQL query over a campaign store (DuckDB; the store is the view `results`)"),
    "cite": ("cite", "print BibTeX for harness, the paper it follows, the benchmark it runs and the engines, with "
                     "their versions installed or run"),
}


def describe(sub, name, example, exit_codes=EXIT_CODES):
    """A sub-command whose --help carries its summary, an example and its exit codes (the common ones unless a
    command gives its own)."""
    summary = COMMANDS[name][1]
    return sub.add_parser(name, help=summary, description=summary[0].upper() + summary[1:] + ".",
                          epilog=f"example:\n  {example}\n\n{exit_codes}",
                          formatter_class=argparse.RawDescriptionHelpFormatter)


def chosen_command(argv):
    """The command a command line names: its first word that is not an option (harness' own options take no
    value), or None."""
    return next((word for word in argv if not word.startswith("-")), None)


def build_parser(chosen=None):
    """The parser: the commands in `chosen` (None: every one) built in full (parsers.py: their options alone, never
    their modules), the others by name and summary alone, so that `harness --help`, `--version` and a typo build no
    command's options, and `harness COMMAND --help` imports none of its implementation."""
    from ..engines import EXTERNAL
    from . import parsers
    parser = Parser(prog="harness", formatter_class=argparse.RawDescriptionHelpFormatter,
                    description="Cross-validate DEM contact force models against the literature (Thornton, Cummins "
                                f"& Cleary 2013) and against the engines {', '.join(EXTERNAL)}.",
                    epilog=f"example:\n  harness compare --model hertz-mindlin\n\n{EXIT_CODES}")
    parser.add_argument("--version", action="version", version=f"harness {__version__}")
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND", parser_class=Parser)
    full = {module for name, (module, _) in COMMANDS.items() if chosen is None or name in chosen}
    loaded = set()
    for name, (module, summary) in COMMANDS.items():
        if module not in full:
            sub.add_parser(name, help=summary, add_help=False)
        elif module not in loaded:          # a module's parser adds every command it holds (check and baseline)
            loaded.add(module)
            getattr(parsers, f"{module}_parser")(sub, describe)
    return parser


def show_log(quiet):
    """harness' log (what it is doing that takes time, e.g. compiling) as `harness: ...` lines on stderr."""
    import logging
    log = logging.getLogger("harness")
    if not log.handlers:
        handler = logging.StreamHandler(sys.stderr)
        handler.setFormatter(logging.Formatter("harness: %(message)s"))
        log.addHandler(handler)
        log.propagate = False
    log.setLevel(logging.WARNING if quiet else logging.INFO)


def what_was_kept(args, since):
    """Where the finished results of an interrupted command are, if it wrote any."""
    output = getattr(args, "output", None) if args is not None else None
    if not output:
        return "nothing had been written yet"
    paths = [output] if os.path.isfile(output) else [os.path.join(output, name) for name in
                                                      (os.listdir(output) if os.path.isdir(output) else [])]
    written = [p for p in paths if os.path.isfile(p) and os.path.getmtime(p) >= since]
    return f"finished results were kept in {output}" if written else "nothing had been written yet"


def disk_full(exc):
    """What ran out, in words: the device's space, or the user's quota."""
    what = "no space left on the device" if exc.errno == errno.ENOSPC else "disk quota exceeded"
    return f"{what} (writing {exc.filename})" if exc.filename else what


def output_closed():
    """Whether the reader of stdout or stderr has gone (`harness ... | head`): its pipe reports an error. If so,
    both are pointed at /dev/null, so that nothing more is said, not even by the interpreter's flush at exit."""
    import select
    poller, descriptors = select.poll(), []
    for stream in (sys.stdout, sys.stderr):
        try:
            descriptors.append(stream.fileno())
        except (AttributeError, OSError, ValueError):      # not a file (a test's capture): not a closed pipe
            continue
        poller.register(descriptors[-1], select.POLLOUT)
    if not any(events & (select.POLLERR | select.POLLHUP) for _, events in poller.poll(0)):
        return False
    devnull = os.open(os.devnull, os.O_WRONLY)
    for descriptor in descriptors:
        os.dup2(devnull, descriptor)
    os.close(devnull)
    return True


def interrupted(stop, args, since):
    """The one line and exit code of a command stopped by Ctrl-C (130), SIGTERM (143) or SIGHUP (129)."""
    signum = stop.signum if isinstance(stop, Stopped) else signal.SIGINT
    how = {signal.SIGTERM: "terminated", signal.SIGHUP: "hung up"}.get(signum, "interrupted")
    print(f"harness: {how}; engines stopped, {what_was_kept(args, since)}", file=sys.stderr)
    return EXIT_INTERRUPTED if signum == signal.SIGINT else 128 + signum


def main(argv=None):
    """Parse, run one command, return its exit code; a user's mistake is one line and 2, Ctrl-C is 130, a closed
    output ends it quietly with 141 (128 + SIGPIPE, as a shell reports a Unix tool stopped by its closed pipe)."""
    args, since = None, time.time() - 1.0
    if sys.stdout is None:          # started with stdout closed (`harness cite >&-`): what it says would be lost
        if sys.stderr is not None:
            print("harness: error: stdout is closed: what harness says would be lost", file=sys.stderr)
        return EXIT_USAGE
    raise_lost_stop, restore_signals = stop_on_signals()
    try:
        with absolute_path():           # for the programs libraries run by name: none from the working directory
            argv = sys.argv[1:] if argv is None else argv
            args = build_parser({chosen_command(argv)}).parse_args(argv)
            from ..engines.runner import sweep_stale
            sweep_stale()
            show_log(quiet=getattr(args, "quiet", False))
            code = args.func(args)
        raise_lost_stop()               # a stop lost in the command's last moments, before its timer raised it
        return code
    except KeyboardInterrupt as exc:
        return interrupted(exc, args, since)
    except EngineMissing as exc:
        print(f"harness: error: {exc}", file=sys.stderr)
        return EXIT_ENGINE
    except UserError as exc:
        if stop_behind(exc):
            return interrupted(stop_behind(exc), args, since)
        print(f"harness: error: {exc}", file=sys.stderr)
        return EXIT_USAGE
    except Exception as exc:                            # a bug of harness: never exit 1, which means disagreement
        if stop_behind(exc):
            return interrupted(stop_behind(exc), args, since)
        if isinstance(exc, BrokenPipeError) and output_closed():
            return EXIT_CLOSED_OUTPUT
        if isinstance(exc, OSError) and exc.errno in (errno.ENOSPC, errno.EDQUOT):
            print(f"harness: error: {disk_full(exc)}; every file is whole (written in full or not at all), "
                  f"{what_was_kept(args, since)}", file=sys.stderr)
            return EXIT_ENGINE
        if isinstance(exc, OSError) and exc.filename:   # the file system refused a path the user gave
            print(f"harness: error: cannot use {exc.filename}: {exc.strerror}", file=sys.stderr)
            return EXIT_USAGE
        import traceback
        traceback.print_exc()
        print(f"harness: internal error (exit {EXIT_INTERNAL}); please report it with the traceback above",
              file=sys.stderr)
        return EXIT_INTERNAL
    finally:
        restore_signals()
