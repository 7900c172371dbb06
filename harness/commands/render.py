"""`harness render`: an engine's input deck or script for every e_n of the scene, without running it."""
import os

from ..api import options_for
from ..engines import EXTERNAL, get_engine
from ..errors import UserError
from ..files import write_text
from ..plan import engine_runs
from ..request import Request
from .options import (EXIT_OK, add_output_options, add_scene_options, check_entries, check_output_directory,
                      engine_option, keywords)

EXAMPLE = "harness render --model hertz-mindlin --engine liggghts --en 0.5 -o decks/"


def add(sub, describe):
    p = describe(sub, "render", "write an engine's input deck/script for the scene without running it", EXAMPLE)
    p.add_argument("--model", required=True, help="law name (see `harness models`)")
    p.add_argument("--engine", required=True, help=f"the engine whose input to write ({', '.join(EXTERNAL)})")
    p.add_argument("--engine-option", dest="engine_options", type=engine_option, action="append", default=[],
                   metavar="ENGINE:KEY=VALUE", help="an engine's option (see `harness compare --help`)")
    add_scene_options(p)
    p.add_argument("-o", "--output", required=True, metavar="DIR", help="directory for the inputs")
    add_output_options(p)
    p.set_defaults(func=main)


def main(args):
    engine = get_engine(args.engine)
    request = Request.from_keywords(args.model, engines=[args.engine], engine_options=args.engine_options,
                                    **keywords(args))
    if not engine.supports(request.law.name):
        raise UserError(f"{args.engine} has no counterpart of {request.law.name}")
    check_output_directory(args.output)
    texts = [engine.render(run) for run in engine_runs(engine, request.law, request.scene, request.resolution,
                                                       options_for(request, args.engine))]
    check_entries(args.output, [name for name, _ in texts])      # every input checked before any is written
    os.makedirs(args.output, exist_ok=True)
    for name, text in texts:
        write_text(os.path.join(args.output, name), text)
    if not args.quiet:
        print("\n".join(os.path.join(args.output, name) for name, _ in texts))
    print(f"wrote {len(texts)} {args.engine} input(s) to {args.output}")
    return EXIT_OK
