"""`harness cite [DIR]`: BibTeX for harness, the paper and benchmark it uses, and each engine with its versions:
those installed here, or those a compare in DIR ran (harness.infra.citation)."""
from ..infra.citation import bibliography, engine_entry
from ..engines import ENGINES, EXTERNAL
from ..engines.builds import builds
from ..infra.errors import UserError
from .options import EXIT_OK


def installed():
    """{engine: [versions]} of every external engine with a build here."""
    every = {code: [build.version() for build in builds(ENGINES[code])] for code in EXTERNAL}
    return {code: versions for code, versions in every.items() if versions}


def ran(directory):
    """{engine: [versions]} of the engines whose own runs are in a compare's results directory."""
    from ..runs.outputs import kinds, load_comparison
    has_compare, _ = kinds(directory)
    if not has_compare:
        raise UserError(f"{directory} holds a cost study, whose results name no engine version: give a compare's "
                        "directory, or no DIR for the engines installed here")
    rows = load_comparison(directory).results
    rows = rows[rows.engine != "reference"]
    codes = rows.engine.map(lambda name: name.partition("@")[0])
    return {code: sorted({str(v) for v in group.engine_version}) for code, group in rows.groupby(codes, sort=False)}


def main(args):
    if args.directory is None:
        versions, how = installed(), "installed here (harness engines)"
    else:
        versions, how = ran(args.directory), f"as run by harness compare in {args.directory}"
    entries = [engine_entry(code, ENGINES[code].CITATION, listed, how) for code, listed in versions.items()
               if code in ENGINES and ENGINES[code].CITATION]
    print(bibliography(entries), end="")
    return EXIT_OK
