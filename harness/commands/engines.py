"""`harness engines`: every engine and every build of it found here, with its version, binary, hash and origin."""
import json

from ..engines import ENGINES, EXTERNAL
from ..engines.builds import DIRECTORY_VARIABLE, builds, directory
from .options import EXIT_OK


def found():
    """[{engine, name, version, binary, sha256, origin, dialect_note}] of every build, and the engines with none
    ({engine, missing})."""
    rows = []
    for code in EXTERNAL:
        engine = ENGINES[code]
        every = builds(engine)
        if not every:
            rows.append({"engine": code, "missing": engine.missing_reason()})
        for build in every:
            rows.append({"engine": code, "name": build.NAME, **build.build(), "dialect_note": build.dialect_note()})
    return rows


def main(args):
    rows = found()
    if args.json:
        print(json.dumps(rows, indent=2))
        return EXIT_OK
    for row in rows:
        if "missing" in row:
            print(f"{row['engine']}: not found ({row['missing']})")
            continue
        print(f"{row['name']}\n    binary  {row['binary']}\n    sha256  {row['sha256']}\n    from    {row['origin']}"
              + (f"\n    note    {row['dialect_note']}" if row["dialect_note"] else ""))
    print(f"\nother builds: prefixes under {directory()} (${DIRECTORY_VARIABLE}; tools/install_lammps.sh, "
          "tools/install_kratos.sh), or a binary of one's own as --engines ENGINE@/path/to/binary")
    return EXIT_OK
