"""`harness cost`: run the accuracy-against-cost ladder, print its tables, write DIR/cost.csv and the report."""
import json
import os
from dataclasses import asdict

import pandas as pd

from .compare import engine_options, requested_engines, runnable_statuses, text_table
from .cost import (COLUMNS, LADDER, METRICS, RAYLEIGH_FRACTION, convergence_orders, cost_table, per_rung,
                   rayleigh_time, recommendations)
from .engines import ADAPTERS
from .errors import UserError
from .publish import COST, COST_RUN, COST_TRUTH
from .results import write_csv


def ladder_from_text(text):
    """--ladder '5,10,20': whole steps per contact >= 1, ascending, no repeats."""
    if text is None:
        return LADDER
    try:
        rungs = tuple(int(part) for part in text.split(",") if part.strip())
    except ValueError:
        raise UserError(f"--ladder takes whole numbers of steps per contact, e.g. 5,10,100; got {text!r}") from None
    if not rungs or min(rungs) < 1 or list(rungs) != sorted(set(rungs)):
        raise UserError(f"--ladder needs ascending whole numbers >= 1 without repeats, got {text!r}")
    return rungs


def save(out_dir, cost, uncertainty, law, scene, overrides, skipped, failures):
    """DIR/cost.csv (per curve, rung and e_n), the truth uncertainties and cost.json (scene, skipped engines); also
    written before the study starts, so `harness report DIR` works on an interrupted one."""
    write_csv(cost, os.path.join(out_dir, COST))
    rows = [{"curve": curve, "e_n_target": e_n, **errs} for curve, per_e in uncertainty.items()
            for e_n, errs in per_e.items()]
    pd.DataFrame(rows).to_csv(os.path.join(out_dir, COST_TRUTH), index=False)
    scene_fields = {k: v for k, v in asdict(scene).items() if k != "extra"}
    with open(os.path.join(out_dir, COST_RUN), "w") as handle:
        json.dump({"model": law.name, "overrides": overrides, "scene": scene_fields, "skipped": skipped,
                   "failures": [vars(f) for f in failures]}, handle, indent=1)


def cost(args):
    """Run the ladder; 0 when every run succeeded or was refused with its reason, 1 when an engine run failed."""
    from .cli import law_from_args, scene_from_args
    from .publish import rebuild
    engines = requested_engines(args.engines)
    scene, law, ladder = scene_from_args(args), law_from_args(args), ladder_from_text(args.ladder)
    out_dir = args.output
    if os.path.exists(out_dir) and not os.path.isdir(out_dir):
        raise UserError(f"output {out_dir} exists and is not a directory")
    statuses = runnable_statuses(engines, law, scene)
    adapters = {s.name: (ADAPTERS[s.name], engine_options(args, s.name)) for s in statuses if s.available}
    for name, (adapter, options) in adapters.items():
        adapter.dialect(law.name, options)                    # bad options: exit 2 before anything runs
    skipped = [(s.name, s.reason) for s in statuses if not s.available]
    os.makedirs(out_dir, exist_ok=True)
    save(out_dir, pd.DataFrame(columns=COLUMNS), {}, law, scene, dict(args.overrides), skipped, [])
    table, failures, uncertainty = cost_table(law, scene, adapters, ladder,
                                              keep=lambda so_far: write_csv(so_far, os.path.join(out_dir, COST)))
    save(out_dir, table, uncertainty, law, scene, dict(args.overrides), skipped, failures)
    report = rebuild(out_dir)
    if not args.quiet:
        print_tables(table, uncertainty, law, scene, ladder, skipped, failures)
        print()
    print(f"wrote {os.path.join(out_dir, COST)} and {report}")
    return 1 if failures else 0


def print_tables(table, uncertainty, law, scene, ladder, skipped, failures):
    t_r = rayleigh_time(scene)
    print(f"{law.name}: accuracy against cost, {len(scene.e_n)} e_n x {len(scene.impacts(scene.e_n[0])[0])} "
          f"impacts; ladder {', '.join(map(str, ladder))} steps per contact, plus {RAYLEIGH_FRACTION:.0%} of the "
          f"Rayleigh time (T_R = {t_r:.4g} s, dt = {RAYLEIGH_FRACTION * t_r:.4g} s)")
    print("errors: max over impacts |x - x*| / max |x*| against the converged reference of the same dialect; "
          "wall time summed over e_n, engine start-up excluded")
    for curve, per_e in uncertainty.items():
        worst = max(errs["err_max"] for errs in per_e.values())
        truth = next(iter(per_e.values())).get("truth", "")
        print(f"  converged reference of the {curve} dialect: {truth}, uncertainty {worst:.1e}"
              + (" (errors below this are not resolved)" if worst > 1e-6 else ""))
    for name, reason in skipped:
        print(f"skipped {name}: {reason}")
    rows = per_rung(table)
    refused = table[table.status == "refused"].drop_duplicates(["engine", "dialect", "rung"])
    print()
    print(text_table(rows, ["engine", "dialect", "rung", "steps_per_contact", "dt", "net_wall_s", "err_e_n", "err_e_t",
                            "err_omega_star", "err_t_contact", "err_f_n_max"],
                     {"steps_per_contact": "{:.4g}", "dt": "{:.3g}", "net_wall_s": "{:.3g}",
                      **{f"err_{m}": "{:.1e}" for m in METRICS}}))
    for _, r in refused.iterrows():
        print(f"  refused: {r.engine}/{r.dialect} at {r.rung}: {r.message}")
    print("\nrecommended time step (coarsest rung within tolerance at every e_n, worst metric, and every finer rung too):")
    rec = recommendations(table)
    cols = [c for c in rec.columns if c.startswith("dt for") or c.startswith("steps/contact")] + ["error at 20% Rayleigh"]
    print(text_table(rec, ["engine", "dialect", *cols], {c: "{:.3g}" for c in cols}))
    print("\norder of convergence (slope of log error against log steps per contact, rungs >= 20; the adaptive "
          "curve: against force evaluations per contact):")
    orders = convergence_orders(table)
    print(text_table(orders, ["engine", "dialect", *METRICS], {m: "{:.2f}" for m in METRICS}))
    for failure in failures:
        print(f"\n{failure.engine} failed at e_n = {failure.e_n:g}: {failure.message}\n{failure.log_tail}")
