"""`harness compile`: every law's kernels compiled into numba's cache now, so that no first run waits for them."""
import time

from ..laws.table import LAWS, known_law
from ..infra.wording import counted
from .options import EXIT_OK


def main(args):
    laws = tuple(known_law(name.strip()) for name in args.laws.split(",")) if args.laws else tuple(LAWS)
    from ..infra.jit import cache_base            # numba: once the laws are known
    from ..views.progress import Progress
    from ..runs.warm_up import compile_laws
    start = time.perf_counter()
    with Progress("compile", quiet=args.quiet, compiling=lambda: 0.0) as progress:    # every step compiles
        seconds = compile_laws(laws, progress)
    print(f"compiled {counted(len(laws), 'law')} in {time.perf_counter() - start:.0f} s ({sum(seconds.values()):.0f} s "
          f"compiling; nothing left to compile where that is 0) into {cache_base()}")
    return EXIT_OK
