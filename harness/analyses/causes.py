"""The causes of a failed physics check, each with its share: over the impacts where the engine fails the check, the
share of the summed miss of its formulas that switching an ingredient to the paper's closes (from the attribution's
rows of every impact). A stepping field switched with others it needs is credited only with what it adds to them.
Where no ingredient alone explains the miss (closes EXPLAINS of it), the one that closes most is tried with each
other ingredient, and with the damping calibration and the end rule together (COUPLED); the combination that
explains it is named."""
import numpy as np

from ..submodels.registry import COULOMB_RULES
from .misses import closed_share, misses_at

MENTION = 0.1            # an ingredient is named when it closes at least this share of the miss
EXPLAINS = 0.9           # an ingredient or a combination explains the miss when it closes at least this share
NAMED = 2                # at most this many ingredients named alone per check
COUPLED = (("damping", "end"),)     # tried together too: a damping calibration is computed for one end rule
BASE = "dialect"         # the attribution rows of the dialect itself, nothing switched
WORDS = {"normal": "normal spring", "damping": "normal damping", "end": "end of contact",
         "tangential": "tangential spring", "tangential-damping": "tangential dashpot", "integrator": "integrator",
         "coulomb": "Coulomb rule", "geometry": "geometry", "lever": "lever arm", "slip": "slip",
         "torque": "torque lever", "touch": "touch rule"}      # each ingredient in words
GLOSS = {("coulomb", name): rule.brief for name, rule in COULOMB_RULES.items() if rule.brief}


def labelled(key, theirs, ours):
    """'Coulomb rule (spring: tangential dashpot unclipped -> spring-first)'."""
    gloss = GLOSS.get((key, theirs))
    return f"{WORDS.get(key, key)} ({theirs}{': ' + gloss if gloss else ''} -> {ours})"


def briefly(key, theirs):
    """'Coulomb rule (tangential dashpot unclipped)', 'end of contact (tension)': what the engine's law does."""
    return f"{WORDS.get(key, key)} ({GLOSS.get((key, theirs), theirs)})"


def units(table, share):
    """[{ingredients, with, switched, share}]: each attribution row measured, its share its own (a row switched with
    others it needs is credited with what it closes beyond them, where they were measured without it), and each
    COUPLED set measured."""
    candidates = []
    for row in table.itertuples():
        name = row.switched
        if name not in share:
            continue
        carried = [k for k in name.split("+") if k != row.ingredient]
        rest = "+".join(carried)
        beyond = bool(carried) and rest in share
        candidates.append({"ingredients": [row.ingredient], "with": carried, "switched": name, "beyond": beyond,
                           "share": share[name] - share[rest] if beyond else share[name],
                           "labels": {row.ingredient: (row.dialect, row.target)}})
    labels = {k: v for u in candidates for k, v in u["labels"].items()}
    for keys in COUPLED:
        name = "+".join(keys)
        if name in share and all(k in labels for k in keys):
            candidates.append({"ingredients": list(keys), "with": [], "switched": name, "beyond": False,
                               "share": share[name], "labels": {k: labels[k] for k in keys}})
    return candidates


def strongest(candidates):
    """The unit that closes most of the miss, or None where none closes any."""
    closing = [u for u in candidates if np.isfinite(u["share"]) and u["share"] > 0.0]
    return max(closing, key=lambda u: u["share"]) if closing else None


def explained_alone(candidates):
    """Whether one unit alone closes EXPLAINS of the miss."""
    return any(np.isfinite(u["share"]) and u["share"] >= EXPLAINS for u in candidates)


def combined(best, other):
    """The switched set of two units together: 'coulomb+end'."""
    return set(best["switched"].split("+")) | set(other["switched"].split("+"))


def check_causes(check, failing, table, rows, paper, tolerances, gravity=0.0):
    """[cause, ...] of one failed check: `failing` the engine's failing impacts (IMPACT columns), `table` the
    attribution table, `rows` its rows of every impact (column `switched`), `paper` the paper law's rows. The units
    (an ingredient, or a COUPLED set) that close at least MENTION of the miss, the largest share first (NAMED at
    most), then, where none explains it alone, the strongest with the other unit that together explain it (the
    fewest ingredients first). A cause: ingredients, with (the stepping fields switched with it), share, explains,
    phrase (with the labels of both laws), brief (what the engine's law does)."""
    if table is None or table.empty or rows is None or rows.empty or "switched" not in table:
        return []
    miss = {name: misses_at(group, paper, failing, tolerances, gravity)[check][0]
            for name, group in rows.groupby("switched", sort=False)}
    if BASE not in miss:
        return []
    base = miss.pop(BASE)
    share = {name: closed_share(base, values) for name, values in miss.items()}
    candidates = units(table, share)
    named = [cause(u) for u in sorted((u for u in candidates if np.isfinite(u["share"]) and u["share"] >= MENTION),
                                      key=lambda u: -u["share"])[:NAMED]]
    best = strongest(candidates)
    if best is None or explained_alone(candidates):
        return named
    measured = {frozenset(name.split("+")): name for name in share}
    together = [(share[measured[keys]], other) for other in candidates if other is not best
                for keys in [frozenset(combined(best, other))]
                if keys in measured and share[measured[keys]] >= EXPLAINS]
    if together:
        s, other = max(together, key=lambda pair: (-len(pair[1]["ingredients"]), pair[0]))
        shown = {k for c in named for k in c["ingredients"]}
        named.append({"ingredients": best["ingredients"] + other["ingredients"], "with": best["with"] + other["with"],
                      "share": s, "explains": True, "phrase": f"{words(best, shown)} with {words(other, shown)}",
                      "brief": f"{words(best, WORDS)} with {words(other, WORDS)}"})
    return named


def words(unit, shown):
    """A unit in words, the labels of both laws given for the ingredients not in `shown`."""
    return " and ".join(WORDS.get(k, k) if k in shown else labelled(k, *unit["labels"][k]) for k in unit["ingredients"])


def cause(unit):
    """A unit named alone: 'Coulomb rule (...)', 'integrator (...), beyond its Coulomb rule', 'normal damping (...)
    and end of contact (...)'."""
    full = " and ".join(labelled(k, *unit["labels"][k]) for k in unit["ingredients"])
    brief = " and ".join(briefly(k, unit["labels"][k][0]) for k in unit["ingredients"])
    carried = " and ".join(WORDS.get(k, k) for k in unit["with"])
    said = f"{'beyond' if unit['beyond'] else 'with'} its {carried}" if carried else ""
    return {"ingredients": unit["ingredients"], "with": unit["with"], "share": unit["share"],
            "explains": bool(unit["share"] >= EXPLAINS), "phrase": f"{full}, {said}" if said else full,
            "brief": f"{brief} {said}" if said else brief}


def phrase(causes, key="phrase"):
    """'Coulomb rule (spring: tangential dashpot unclipped -> spring-first) 64%, end of contact (tension ->
    no-tension) 41%, Coulomb rule with end of contact 100%', or '' (key 'brief': each cause in a few words)."""
    return ", ".join(f"{c[key]} {percent(c['share'])}" for c in causes)


def percent(share):
    """A share as a whole percentage; below 1% but above 0 as '<1%'."""
    return "<1%" if 0.0 < share < 0.005 else f"{share:.0%}"
