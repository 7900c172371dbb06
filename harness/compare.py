"""`harness compare`: the paper law, each engine's dialect and each engine on one scene; tables, CSV, report."""
import os

import pandas as pd

from .attribution import attribution
from .comparison import agreement, deviation, findings
from .engines import ADAPTERS, INSTALLED, engine_status
from .engines.runner import EngineFailure
from .engines.sweep import precision_gap, run_sweep
from .errors import UserError
from .results import write_csv
from .sliding import sliding_thresholds, threshold_table
from .solver.plan import plan_batch


def requested_engines(text):
    """Engine names from --engines (default: every known engine)."""
    if text is None:
        return list(INSTALLED)
    names = [n.strip() for n in text.split(",") if n.strip()]
    unknown = [n for n in names if n not in INSTALLED]
    if unknown or not names:
        raise UserError(f"unknown engine(s) {', '.join(unknown) or text!r}; known: {', '.join(INSTALLED)}")
    return names


def runnable_statuses(engines, law, scene):
    """Each engine's status for `law`, marked unavailable where the scene asks for what engine inputs lack."""
    statuses = [engine_status(name, law.name) for name in engines]
    unsupported = ("engine inputs do not model gravity" if scene.gravity else
                   "engine inputs use a wall of the sphere's own material" if scene.wall != "same" else None)
    if unsupported:
        statuses = [type(s)(s.name, False, unsupported) if s.available else s for s in statuses]
    return statuses


def summary_lines(frame):
    """Per e_n: achieved e_n range, e_t range, largest kinetic-energy ratio and rows not ok."""
    lines = [f"{'e_n target':>10} {'e_n achieved':>21} {'e_t':>19} {'max KE1/KE0':>12} {'not ok':>6}"]
    for e_n, group in frame.groupby("e_n_target", sort=False):
        lines.append(f"{e_n:10.3f} {group.e_n.min():10.6f}..{group.e_n.max():<9.6f} "
                     f"{group.e_t.min():9.4f}..{group.e_t.max():<8.4f} {group.ke_ratio.max():12.6f} "
                     f"{int((group.status != 'ok').sum()):6d}")
    return lines


def text_table(frame, columns, formats=None):
    """A plain fixed-width table for the terminal."""
    if frame.empty:
        return "  (none)"
    formats = formats or {}
    cells = [[formats.get(c, "{}").format(row[c]) if not isinstance(row[c], float) or c not in formats
              else formats[c].format(row[c]) for c in columns] for _, row in frame.iterrows()]
    widths = [max(len(c), *(len(r[i]) for r in cells)) for i, c in enumerate(columns)]
    def line(values):
        return "  " + "  ".join(v.ljust(w) if c == "note" else v.rjust(w)
                                for v, w, c in zip(values, widths, columns)).rstrip()
    return "\n".join([line(columns)] + [line(r) for r in cells])


def compare(args):
    """Run, write DIR/results.csv (after every batch) and DIR/report.html; 0 when every agreement holds."""
    from .cli import law_from_args, resolution_from_args, scene_from_args
    from .publish import rebuild, save_extras
    from .solver.reference import simulate
    engines = requested_engines(args.engines)
    scene, law, steps = scene_from_args(args), law_from_args(args), resolution_from_args(args)
    out_dir = args.output
    if os.path.exists(out_dir) and not os.path.isdir(out_dir):
        raise UserError(f"output {out_dir} exists and is not a directory")
    statuses = runnable_statuses(engines, law, scene)
    planned = [] if args.converged else [law]
    for status in statuses:
        if status.available:             # bad options or a time step above a stability limit: exit 2 before running
            planned.append(ADAPTERS[status.name].dialect(law.name, engine_options(args, status.name)))
    for each in planned:
        for e_n in scene.e_n:
            plan_batch(each, scene, e_n, steps)
    os.makedirs(out_dir, exist_ok=True)
    results_path = os.path.join(out_dir, "results.csv")
    frames = []

    def keep(frame):
        frames.append(frame)
        write_csv(pd.concat(frames, ignore_index=True), results_path)

    keep(simulate(law, scene, steps_per_contact=steps, converged=args.converged)[0])
    sliding = threshold_table(law.name, sliding_thresholds(law, scene)) if scene.mu > 0 else None
    failures, attributions, dialects, precision = [], {}, {}, None
    for status in statuses:
        if not status.available:
            continue
        adapter = ADAPTERS[status.name]
        options = engine_options(args, status.name)
        dialect = dialects[status.name] = adapter.dialect(law.name, options)
        keep(simulate(dialect, scene, steps_per_contact=steps)[0])
        _, failed = run_sweep(adapter, law, scene, steps, on_frame=keep, options=options)
        failures += failed
        if status.name == "yade" and options.get("precision") == "double" and not failed:
            try:
                precision = precision_gap(adapter, law, scene, steps)
            except EngineFailure as exc:
                precision = {"engine": "yade", "against": "mpfr150", "failed": str(exc)}
        attributions[f"{status.name} dialect -> paper"] = attribution(
            law, dialect, scene, lambda l, s: simulate(l, s, steps_per_contact=steps)[0])
    if len(dialects) == 2:                      # LIGGGHTS against YADE, and which ingredients make the difference
        (first, a), (second, b) = dialects.items()
        attributions[f"{first} dialect -> {second} dialect"] = attribution(
            b, a, scene, lambda l, s: simulate(l, s, steps_per_contact=steps)[0])
    frame = pd.concat(frames, ignore_index=True)
    ran = [s.name for s in statuses if s.available]
    agree = pd.concat([agreement(frame, name) for name in ran], ignore_index=True) if ran else pd.DataFrame()
    devs = pd.concat([deviation(frame, name, name) for name in ran], ignore_index=True) if ran else pd.DataFrame()
    cross = deviation(frame, ran[1], ran[1], against=(ran[0], ran[0])) if len(ran) == 2 else pd.DataFrame()
    found = findings(frame)
    skipped = [(s.name, s.reason) for s in statuses if not s.available]
    save_extras(out_dir, law.name, dict(args.overrides), scene, skipped, attributions, failures, precision,
                normal_histories(law, scene, steps),
                {s.name: engine_options(args, s.name) for s in statuses if s.available}, sliding)
    report = rebuild(out_dir)
    ok = bool(agree["pass"].all()) if not agree.empty else True
    if not args.quiet:
        print(f"{law.name}: paper law on the reference engine, {sum(frame.engine == 'reference')} rows")
        print("\n".join(summary_lines(frame[(frame.engine == "reference") & (frame.dialect == "paper")])))
        if sliding is not None:
            print("\nsliding throughout (paper law: the smallest Psi1* found, and the condition derived for it):")
            print(text_table(sliding, ["e_n_target", "simulated", "derived", "difference", "formula"],
                             {"simulated": "{:.5f}", "derived": "{:.5f}", "difference": "{:+.1e}"}))
        for name, reason in skipped:
            print(f"skipped {name}: {reason}")
        if ran:
            print("\nagreement (engine vs its dialect in the reference, equal dt):")
            print(text_table(agree, ["engine", "metric", "max_rel_diff", "e_n_target", "theta_deg", "tolerance", "pass"],
                             {"max_rel_diff": "{:.2e}", "tolerance": "{:.0e}"}))
            print("\ndeviation (engine vs the paper law):")
            print(text_table(devs, ["engine", "e_n_target", "metric", "max_abs_diff", "theta_deg", "paper",
                                    "engine_value"], {"max_abs_diff": "{:.4g}", "paper": "{:.5g}",
                                                      "engine_value": "{:.5g}"}))
            if not cross.empty:
                print(f"\n{ran[1]} against {ran[0]} (engine runs, same scene and dt):")
                print(text_table(cross, ["e_n_target", "metric", "max_abs_diff", "theta_deg", ran[0], "engine_value"],
                                 {"max_abs_diff": "{:.4g}", ran[0]: "{:.5g}", "engine_value": "{:.5g}"}))
            for name, table in attributions.items():
                print(f"\nattribution ({name}, one ingredient at a time; max change per metric):")
                cols = [c for c in table.columns if c.startswith("d_")]
                print(text_table(table, ["ingredient", "dialect", "target", *cols, "note"],
                                 {c: "{:+.4g}" for c in cols}))
        if precision:
            gaps = ", ".join(f"{k} {v:.1e}" for k, v in precision.items() if k in ("v_n1", "v_t1", "omega1"))
            print(f"\nprecision: YADE double against {precision['against']} on the same impacts and dt "
                  f"(max relative difference): {gaps or precision.get('failed')}")
        if not found.empty:
            print("\nfindings:")
            for _, row in found.iterrows():
                print(f"  {row.engine} ({row.dialect}): {row.kind}: {row.detail}")
        for failure in failures:
            print(f"\n{failure.engine} failed at e_n = {failure.e_n:g}: {failure.message}\n{failure.log_tail}")
        print(f"\nwrote {results_path} and {report}")
    print("agreement: " + ("no engine compared" if not ran else "ok" if ok else "FAILED"))
    return 0 if ok else 1


def normal_histories(law, scene, steps):
    """Force histories of the paper law's normal impact at the scene speed, one per e_n (for the report)."""
    from dataclasses import replace
    from .solver.reference import simulate
    normal = replace(scene, angles_deg=(0.0,), psi1_star=None, v_t=None)
    return simulate(law, normal, steps_per_contact=steps, history_points=400)[1]


def engine_options(args, engine):
    """Options for `engine` (validated by its adapter): --liggghts-option pairs, --yade-precision."""
    if engine == "yade":
        return {"precision": getattr(args, "yade_precision", "double"),
                "linear": getattr(args, "yade_linear", "viscel")}
    return dict(getattr(args, f"{engine}_options", None) or [])
