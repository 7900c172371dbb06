"""`harness scenes`: every scene kind with its parameters, the effects it needs and its closed-form checks."""
import json

from ..scenes.catalogue import EFFECT_WORDS, EFFECTS_CHOSEN, SCENES
from .options import EXIT_OK


def effects_in_words(kind):
    """The effects a scene needs, or which of them each value of the parameter that chooses gives."""
    if kind.NAME not in EFFECTS_CHOSEN:
        return ", ".join(sorted(kind.EFFECTS))
    parameter, chosen = EFFECTS_CHOSEN[kind.NAME]
    return " or ".join(f"{', '.join(sorted(effects))} ({parameter} = {value})" for value, effects in chosen.items())


def described(kind):
    """A scene kind as data: its name, summary, whether a command runs it, parameters, effects and checks."""
    parameter, chosen = EFFECTS_CHOSEN.get(kind.NAME, (None, {}))
    return {"name": kind.NAME, "summary": kind.SUMMARY, "runs": kind.RUNS,
            "parameters": [{"name": p.name, "default": p.default, "unit": p.unit, "meaning": p.meaning,
                            "allowed": p.allowed()} for p in kind.PARAMETERS],
            "effects": sorted(kind.EFFECTS),
            "effects_chosen_by": parameter and {"parameter": parameter,
                                                "effects": {str(v): sorted(e) for v, e in chosen.items()}},
            "checks": [{"name": c.name, "quantity": c.quantity, "equation": c.equation, "tolerance": c.tolerance,
                        "tolerance_is": "relative" if c.relative else "absolute", "source": c.source}
                       for c in kind.CHECKS]}


def main(args):
    if args.json:
        print(json.dumps([described(kind) for kind in SCENES.values()], indent=2))
        return EXIT_OK
    for kind in SCENES.values():
        print(f"{kind.NAME}: {kind.SUMMARY}" + ("" if kind.RUNS else " [described: no command runs it yet]"))
        print(f"  effects: {effects_in_words(kind)}")
        for p in kind.PARAMETERS:
            print(f"  {p.name} = {p.default} [{p.unit}]  {p.meaning} ({p.allowed()})")
        for c in kind.CHECKS:
            print(f"  check {c.name}: {c.quantity}; {c.equation}, within {c.tolerance:g} "
                  f"({'relative' if c.relative else 'absolute'}); {c.source}")
    print("\neffects: what a scene asks a simulation for (" + ", ".join(EFFECT_WORDS) + ")")
    return EXIT_OK
