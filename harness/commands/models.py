"""`harness models`: the laws, their sub-models and the engines that run each."""
import json

from ..engines import ENGINES
from ..laws.table import LAWS
from ..scenes.materials import MATERIALS
from .options import EXIT_OK


def support(law_name):
    """{engine: the engine's model of the law, or None} for every external engine."""
    return {name: (engine.COUNTERPARTS[law_name] if engine.supports(law_name) else None)
            for name, engine in ENGINES.items() if name != "reference"}


def main(args):
    if args.json:
        print(json.dumps([{"name": name, "provisional": law.provisional, "summary": law.summary,
                           "submodels": law.describe(), "engines": {"reference": "paper", **support(name)}}
                          for name, law in LAWS.items()], indent=2))
        return EXIT_OK
    rows = [("law", "normal", "damping", "end", "tangential", "tangential dashpot", "engines")]
    for name, law in LAWS.items():
        d = law.describe()
        engines = ", ".join(["reference"] + [f"{e} ({m})" for e, m in support(name).items() if m])
        rows.append((name + (" [provisional]" if law.provisional else ""), d["normal"], d["damping"], d["end"],
                     d["tangential"], d["tangential-damping"], engines))
    widths = [max(len(row[i]) for row in rows) for i in range(6)]
    for row in rows:
        print("  ".join(cell.ljust(w) for cell, w in zip(row, widths)) + "  " + row[6])
    print("\n[provisional]: the paper defines the law but its equations are not available; harness runs a "
          "reconstruction (docs/laws.md).")
    print("materials: " + ", ".join(MATERIALS) + " (default tcc13: the paper's sphere and wall)")
    return EXIT_OK
