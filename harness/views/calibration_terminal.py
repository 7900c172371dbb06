"""What a person reads after calibrate: the choices with their price on the physics checks and the rule that chose,
what to type per target e_n (every value and the lines to paste), the deviation from the paper law before and after,
what the engine run confirmed, what remains and why, the time-step advice; and, on stderr, what did not run."""
from ..infra.wording import counted
from .terminal import wrapped


def print_calibration(calibration):
    """The calibration on stdout."""
    c, scene = calibration, calibration.scene
    impacts = len(c.frame[c.frame.dialect == "paper"])
    print(f"calibrate {c.law.name} for {c.engine} {c.version}: e_n {', '.join(f'{e:g}' for e in scene.e_n)} x "
          f"{counted(impacts // max(len(scene.e_n), 1), 'impact')}, {c.steps} steps per contact")
    if c.yours:
        print(wrapped(f"your input: {c.yours['text']} (computes "
                      f"{'; '.join(f'{k} {v}' for k, v in c.yours['composition'].items())})", indent=6))
    print_choices(c, impacts)
    print_typed(c)
    print("worst deviation from the paper law over the sweep (v and R omega as fractions of V):")
    for quantity, rows in c.stages.groupby("quantity", sort=False):
        steps = "  ->  ".join(f"{r.stage}: {r.worst:.3g}" for r in rows.itertuples())
        print(wrapped(f"  {quantity:15s} {steps}", indent=6))
    if c.agreement is not None:
        print(f"the engine with these inputs agrees with its formulas to {c.agreement:.1e} of V")
    final = c.physics.get("engine, calibrated") or c.physics.get("formulas, calibrated")
    if final and final["state"] in ("marginal", "deviates"):
        causes = [f"{check['short']} ({check['ingredient'] or 'no single ingredient'})"
                  for check in final["checks"] if not check["passed"]]
        print(wrapped("what no input fixes: " + "; ".join(causes)))
    print_advice(c)


def print_choices(c, impacts):
    """Each choice of options with its price (the checks it fails: worst case, impacts beyond the tolerance), the
    chosen one marked, the rule, and the options this build refuses."""
    print(wrapped(f"choices and their price on the physics checks ({c.tolerances.describe()}):"))
    for choice in c.choices:
        failed = [f"{check['check']}: {check['short']}" for check in choice["price"] if not check["passed"]]
        reached = ("" if choice["targets reached"] == len(c.scene.e_n) else
                   f" [reaches {choice['targets reached']} of {len(c.scene.e_n)} targets]")
        print(wrapped(f"  {'*' if choice['chosen'] else ' '} {choice['options']}{reached}: "
                      f"{'; '.join(failed) or 'every check holds'}", indent=6))
    print(wrapped(f"  * chosen: {c.rule}"
                  + "".join(f"; not in this build: {name}" for name, why in c.refused
                          if "releases harness checked" in why),
                  indent=4))


def print_typed(c):
    """Per target e_n: the e to give the engine, every value its contact lines set, and those lines to paste."""
    typed_at = {t.target: t for t in c.typed}
    print(f"what to type into {c.engine} (the contact lines of each input written; paste them into yours):")
    for row in c.inputs.itertuples():
        if row.input_e != row.input_e:          # NaN: no input reaches it
            print(wrapped(f"  e_n {row.e_n_target:g}: no input reaches it ({row.note})", indent=4))
            continue
        typed = typed_at.get(row.e_n_target)
        values = ", ".join(f"{name} {value}" for name, value in typed.values) if typed else ""
        print(wrapped(f"  e_n {row.e_n_target:g}: e = {row.input_e:.6g} (its normal impact: e_n {row.normal_e_n:.6g})"
                      + (f"; {values}" if values else ""), indent=4))
        for line in typed.lines if typed else ():
            print(f"    {line}")


def print_advice(c):
    """The time step that holds the tolerance, confirmed in the engine where it ran, beside the common rule."""
    advice = c.advice
    rule = f"the 20%-of-Rayleigh rule (dt {advice.rule_dt:.3g} s) errs by {advice.rule_errors['err_max']:.2g}"
    if advice.steps is None:
        print(wrapped(f"time step: no rung up to {int(advice.ladder.steps_per_contact.max())} steps per contact "
                      f"holds {advice.tolerance:g} on every quantity; {rule}"))
        return
    confirmed = c.confirmed
    said = ("" if confirmed is None else
            f"; the engine there errs by {confirmed['err_max']:.2g} ({'holds' if confirmed['meets'] else 'FAILS'})")
    print(wrapped(f"time step for {advice.tolerance:g}: {advice.steps} steps per contact, dt {advice.dt:.3g} s = "
                  f"{advice.fraction_of_rayleigh:.3g} of the Rayleigh time{said}; {rule}"))


def print_not_run(calibration, file):
    """Why the engine did not run, and each failed run with its log tail (stderr)."""
    c = calibration
    if c.skipped:
        print(wrapped(f"calibrate: {c.engine} did not run: {c.skipped}; its inputs were found on its formulas in "
                      f"harness' solver alone, not confirmed in the engine"), file=file)
    for failure in c.failures:
        print(f"calibrate: {failure.engine} failed given e = {failure.e_n:g}: {failure.message}\n{failure.log_tail}",
              file=file)
