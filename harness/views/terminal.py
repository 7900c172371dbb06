"""The terminal view: fixed-width tables and what compare, check, cost and paper print."""
from ..analyses.cost import (MEASURE, METRICS, NOT_RESOLVED, RAYLEIGH_FRACTION, TOLERANCES, WITHIN_NOISE,
                              convergence_orders, per_rung, rayleigh_time, step_times)
from ..analyses.cost_answer import answers, key, notes, recommendations, steps_text, verdict
from ..analyses.causes import MENTION
from ..analyses.physics import Tolerances
from ..analyses.published import GOAL, meets_goal
from ..infra.wording import counted
from .states_view import FORMATS as STATE_FORMATS, SHOWN_COLUMNS as STATE_COLUMNS, first_impacts


def summary_lines(frame):
    """Per e_n: achieved e_n range, e_t range, largest kinetic-energy ratio and rows not ok."""
    lines = [f"{'e_n target':>10} {'e_n achieved':>21} {'e_t':>19} {'max KE1/KE0':>12} {'not ok':>6}"]
    for e_n, group in frame.groupby("e_n_target", sort=False):
        lines.append(f"{e_n:10.3f} {group.e_n.min():10.6f}..{group.e_n.max():<9.6f} "
                     f"{group.e_t.min():9.4f}..{group.e_t.max():<8.4f} {group.ke_ratio.max():12.6f} "
                     f"{int((group.status != 'ok').sum()):6d}")
    return lines


def text_table(frame, columns, formats=None, missing=None):
    """A plain fixed-width table for the terminal; an empty (NaN) number is shown as `missing` says for its column,
    else as '-', never as nan."""
    if frame.empty:
        return "  (none)"
    formats, missing = formats or {}, missing or {}

    def cell(value, column):
        if isinstance(value, float) and value != value:
            return missing.get(column, "-")
        return formats.get(column, "{}").format(value)
    cells = [[cell(row[c], c) for c in columns] for _, row in frame.iterrows()]
    widths = [max(len(c), *(len(r[i]) for r in cells)) for i, c in enumerate(columns)]
    def line(values):
        return "  " + "  ".join(v.ljust(w) if c == "note" else v.rjust(w)
                                for v, w, c in zip(values, widths, columns)).rstrip()
    return "\n".join([line(columns)] + [line(r) for r in cells])


def states_text(states, where="states.csv"):
    """The first impacts' states (states_view.first_impacts) as a fixed-width table, with a line saying where the
    rest is; '' when there are none."""
    shown = first_impacts(states)
    if shown is None:
        return ""
    more = len(states) - len(shown)
    return ("states at the times asked (first impact of each engine):\n" +
            text_table(shown, STATE_COLUMNS, STATE_FORMATS) + (f"\n  ({more} more rows in {where})" if more else ""))


def print_summary(record, comparison, written):
    """What a person reads after compare (about 25 lines): per engine whether it reproduces the paper law on this
    scene (the worst case of each failed check and the ingredient attribution names), whether it agrees with its own
    formulas, its largest deviations from the paper law in physical units, then the findings not said yet, skipped
    engines and failed runs (with their log tails), then where the files are."""
    engines = record["engines"]
    names = [e["engine"] if "@" in e["engine"] else f"{e['engine']} {e['version']}" for e in engines]
    ran = " and ".join(filter(None, [", ".join(names[:-1]), names[-1]])) if names else "no engine"
    print(wrapped(f"{record['model']}: the paper law against {ran}; {len(record['e_n'])} e_n x "
                  f"{counted(record['impacts'] // max(len(record['e_n']), 1), 'impact')}"))
    if engines:
        width = max(18, *(len(name) for name in names))
        tolerances = Tolerances.of(record["tolerances"]).describe()
        print(wrapped(f"does each engine reproduce the paper law on this scene? ({tolerances})"))
        for e, name in zip(engines, names):
            print(wrapped(f"  {name:{width}s} {physics_phrase(e['physics'])}", indent=6))
        print(f"agreement with its own formulas at equal time step (tolerance {engines[0]['tolerance']:.0e}):")
        for e, name in zip(engines, names):
            worst = e["worst"]
            where = ("no impact compared" if not e["compared"] else
                     f"worst {worst['relative']:.1e} in {worst['metric']} at e_n {worst['e_n_target']:g}, "
                     f"{worst['theta_deg']:g} deg")
            state = "agrees" if e["agrees"] else "DISAGREES" if e["compared"] else "not compared"
            print(f"  {name:{width}s} {state:12s} {where}")
        print("largest deviation from the paper law (relative to the incident speed V; the spin as R omega1/V):")
        for e in engines:
            for d in e["deviation"]:
                print(f"  {e['engine']:{max(10, len(e['engine']))}s} {d['metric']:7s} {d['difference']:+11.4g} "
                      f"{d['unit']:6s} {d['relative']:+8.2%} of {d['relative_to']:4s} at e_n {d['e_n_target']:g}, "
                      f"{d['theta_deg']:g} deg")
    print_versions(comparison.versions)
    for engine, build in comparison.builds.items():
        if build.get("note"):
            print(wrapped(f"note: {engine}: {build['note']}"))
    for finding in told_once(record):
        print(wrapped(f"finding: {finding['engine']} ({finding['dialect']}): {finding['kind']}: {finding['detail']}"))
    for skipped in record["skipped"]:
        print(f"skipped {skipped['engine']}: {skipped['reason']}")
    for failure in comparison.failures:
        print(f"{failure.engine} failed at e_n = {failure.e_n:g}: {failure.message}\n{failure.log_tail}")
    if comparison.states is not None:
        print(states_text(comparison.states))
    print(f"wrote {' and '.join(written)} (every table: --verbose, the CSVs and the report)")


def print_versions(versions):
    """Between consecutive builds of an engine (in release order), one line each: the metrics that moved, the largest
    change of each, and the ingredients that alone move them most; FLAGGED where the dialects are identical."""
    if versions.empty:
        return
    print("between versions (engine runs, same scene and dt):")
    for (engine, a, b), rows in versions.groupby(["engine", "from_version", "to_version"], sort=False):
        if not rows.metric.iloc[0]:
            print(f"  {engine} {a} -> {b}: {rows.attributed_to.iloc[0]}")
            continue
        moved = ", ".join(f"status: {r.attributed_to} (first at e_n {r.e_n_target:g}, {r.theta_deg:g} deg)"
                          if r.metric == "status" else
                          f"{r.metric} {r.change:+.3g} (e_n {r.e_n_target:g}, {r.theta_deg:g} deg)"
                          for r in rows.itertuples())
        if rows.flagged.iloc[0]:
            print(wrapped(f"  {engine} {a} -> {b}: {moved}; FLAGGED: the dialects are identical, the binaries differ "
                          "(no ingredient of harness explains it)", indent=6))
            continue
        metrics = rows[rows.metric != "status"]
        causes = sorted({cause.split(" (")[0] for cause in metrics.attributed_to if cause})
        most = f"; moving them most: {', '.join(causes) or 'no single ingredient'}" if len(metrics) else ""
        print(wrapped(f"  {engine} {a} -> {b}: {moved}; ingredients that differ: {rows.ingredients_differing.iloc[0]}"
                      + most, indent=6))


def physics_phrase(physics):
    """'reproduces ...', 'MARGINAL' or 'DEVIATES' with the worst case of each failed check, its size and the
    ingredients that close its miss with their shares, or 'not checked (why)'."""
    if physics["state"] == "reproduces":
        return f"{'reproduces':12s} every check holds on {counted(physics['impacts'], 'impact')}"
    if physics["state"] not in ("marginal", "deviates"):
        return f"{'not checked':12s} {physics['reason']}"
    failed = [c for c in physics["checks"] if not c["passed"]]
    return f"{physics['state'].upper():12s} " + "; ".join(failed_phrase(c) for c in failed)


def failed_phrase(check):
    """'|J_t| 1.587 mu J_n at e_n 0.25, 71 deg (126 of 180 impacts, 587x the tolerance): Coulomb rule (tangential
    dashpot unclipped) 64%, ...': the worst case, its size, and its causes with the share of the miss each closes."""
    if "ingredient" not in check:
        return check["short"]
    if not check["ingredient"]:
        return f"{check['short']}; no ingredient alone or in a pair closes {MENTION:.0%} of it"
    return f"{check['short']}: {check['ingredient']}"


FOLDED = {"Coulomb bound": "coulomb", "Coulomb bound from below": "coulomb", "e_n off target": "e_n",
          "energy gain": "energy",
          "tangential energy gain": "energy"}     # finding kind -> the physics check that says it


def told_once(record):
    """The findings the summary has not said yet: not those a failed physics check of the same engine states, nor
    a dialect's (engine 'reference') that its engine shows too (--verbose and the report list every one)."""
    failing = {e["engine"]: set(e["physics"]["failing"]) for e in record["engines"]}
    shown = {(f["engine"], f["kind"]) for f in record["findings"] if f["engine"] == f["dialect"]}
    return [f for f in record["findings"]
            if FOLDED.get(f["kind"]) not in failing.get(f["dialect"], ())
            and not (f["engine"] == "reference" and (f["dialect"], f["kind"]) in shown)]


def wrapped(text, indent=2):
    """A line wrapped at the terminal's width between words, never cut (the report has the same text whole)."""
    import shutil
    import textwrap
    width = min(max(shutil.get_terminal_size((120, 24)).columns, 60), 160)
    return textwrap.fill(text, width=width, subsequent_indent=" " * indent, break_long_words=False,
                         break_on_hyphens=False)


def verdict_line(record, reference_only=False):
    """The verdicts in one line, the physics first: which engines reproduce the paper law or deviate from it, then
    what agreed with its own formulas, what did not, what did not run."""
    compared = [e for e in record["engines"] if e["compared"]]
    bad = [e for e in compared if not e["agrees"]]
    if bad:
        line = "agreement: FAILED for " + ", ".join(
            f"{e['engine']} (worst {e['worst']['relative']:.1e} in {e['worst']['metric']}, tolerance "
            f"{e['tolerance']:.0e})" for e in bad)
    elif compared:
        line = "agreement: ok for " + ", ".join(e["engine"] for e in compared)
    else:
        line = "agreement: not checked: " + ("the reference alone was asked for" if reference_only else
                                             "no engine ran")
    physics = physics_words(record)
    if physics:
        line = f"{physics}; {line}"
    if record["unavailable"]:
        line += f"; asked for by name and not run: {', '.join(record['unavailable'])}"
    failed = sorted({f["engine"] for f in record["failed"]})
    if failed:
        line += f"; failed runs: {', '.join(failed)}"
    return line


def physics_words(record):
    """'paper law: reproduced by A; marginal in B; deviates in C, D', or '' when no engine was checked."""
    parts = []
    for state, words in (("reproduces", "reproduced by"), ("marginal", "marginal in"), ("deviates", "deviates in"),
                         ("not checked", "not checked in")):
        engines = [e["engine"] for e in record["engines"] if e["physics"]["state"] == state]
        if engines:
            parts.append(f"{words} {', '.join(engines)}")
    return "paper law: " + "; ".join(parts) if any(e["physics"]["state"] != "not checked"
                                                  for e in record["engines"]) else ""


def print_comparison(comparison, written):
    """Every table of the comparison (--verbose), then where its files are."""
    frame, law = comparison.results, comparison.law
    print(f"{law.name}: paper law on the reference engine, {sum(frame.engine == 'reference')} rows")
    print("\n".join(summary_lines(frame[(frame.engine == "reference") & (frame.dialect == "paper")])))
    if comparison.compared:
        print("\ndoes each engine reproduce the paper law on this scene? (causes: the share of the miss each closes)")
        for engine, physics in comparison.physics.items():
            print(wrapped(f"  {engine} {physics_phrase(physics)}", indent=6))
    if comparison.sliding is not None:
        print("\n" + wrapped("sliding throughout (paper law: the smallest Psi1* found, and the condition derived for "
                             "it; '-': none found, or no condition derived):"))
        print(text_table(comparison.sliding, ["e_n_target", "simulated", "derived", "difference", "formula"],
                         {"simulated": "{:.5f}", "derived": "{:.5f}", "difference": "{:+.1e}"}))
    for name, reason in comparison.skipped:
        print(f"skipped {name}: {reason}")
    if comparison.compared:
        print("\nagreement (engine vs its dialect in the reference, equal dt):")
        print(text_table(comparison.agreement, ["engine", "metric", "max_rel_diff", "e_n_target", "theta_deg",
                                                "tolerance", "pass"],
                         {"max_rel_diff": "{:.2e}", "tolerance": "{:.0e}"}))
        print("\ndeviation (engine vs the paper law):")
        print(text_table(comparison.deviation, ["engine", "e_n_target", "metric", "max_abs_diff", "theta_deg", "paper",
                                                "engine_value"], {"max_abs_diff": "{:.4g}", "paper": "{:.5g}",
                                                                  "engine_value": "{:.5g}"}))
        for (a, b), cross in comparison.cross.items():
            if not cross.empty:
                print(f"\n{b} against {a} (engine runs, same scene and dt):")
                print(text_table(cross, ["e_n_target", "metric", "max_abs_diff", "theta_deg", a, "engine_value"],
                                 {"max_abs_diff": "{:.4g}", a: "{:.5g}", "engine_value": "{:.5g}"}))
        for name, table in comparison.attribution.items():
            print(f"\nattribution ({name}, one ingredient at a time; max change per metric):")
            cols = [c for c in table.columns if c.startswith("d_")]
            shown = ["ingredient", "dialect", "target", *(["switched"] if "switched" in table else []), *cols, "note"]
            print(text_table(table, shown, {c: "{:+.4g}" for c in cols}))
    precision = comparison.precision
    if precision:
        gaps = ", ".join(f"{k} {v:.1e}" for k, v in precision.items() if k in ("v_n1", "v_t1", "omega1"))
        print(f"\nprecision: {precision['engine']} double against {precision['against']} on the same impacts and dt "
              f"(max relative difference): {gaps or precision.get('failed')}")
    if not comparison.findings.empty:
        print("\nfindings:")
        for _, row in comparison.findings.iterrows():
            print(wrapped(f"  {row.engine} ({row.dialect}): {row.kind}: {row.detail}", indent=4))
    for failure in comparison.failures:
        print(f"\n{failure.engine} failed at e_n = {failure.e_n:g}: {failure.message}\n{failure.log_tail}")
    if comparison.states is not None:
        print("\n" + states_text(comparison.states))
    print(f"\nwrote {' and '.join(written)}")


def print_cost(table, uncertainty, law, scene, ladder, skipped, failures, verbose=False):
    """What a person reads after cost (at most 40 lines of 120 columns): the measure, the verdict per engine against
    the paper scheme and how each number was found, then skipped, refused and failed runs; with `verbose` every
    table too (cost_tables)."""
    t_r = rayleigh_time(scene)
    width = 118
    def say(text):
        import textwrap
        print(textwrap.fill(text, width=width, subsequent_indent="    ", break_long_words=False))
    say(f"{law.name}: accuracy against cost, {len(scene.e_n)} e_n x "
        f"{counted(len(scene.impacts(scene.e_n[0])[0]), 'impact')}; "
        f"ladder {','.join(map(str, ladder))} steps/contact and {RAYLEIGH_FRACTION:.0%} of the Rayleigh time "
        f"(dt {RAYLEIGH_FRACTION * t_r:.3g} s)")
    say(f"{MEASURE}, its uncertainty ('truth +-') added; time per impact = impact-steps x the curve's time per "
        f"impact-step, timed on copies of the scene's impacts until resolved:")
    found = answers(table)
    print(verdict_table(table, found))
    for note in notes(found, TOLERANCES[:2], verdict_only=True):
        say(f"  {note}")
    times = step_times(table)
    for row in times[times.timing == NOT_RESOLVED].itertuples():
        say(f"  {row.engine} ({row.dialect}): time per impact-step NOT RESOLVED: {row.message}")
    for name, reason in skipped:
        say(f"skipped {name}: {reason}")
    refused = table[table.status == "refused"].drop_duplicates(["engine", "dialect", "rung"])
    if not refused.empty:
        say("refused above a stability limit: " + ", ".join(f"{r.engine}/{r.dialect} at {r.rung}"
                                                             for r in refused.itertuples()))
    for failure in failures:
        say(f"{failure.engine} failed at e_n = {failure.e_n:g}: {failure.message}")
        if verbose:
            print(failure.log_tail)
    if verbose:
        cost_tables(table, uncertainty, found)


def verdict_table(table, found=None):
    """The verdict (analyses.cost_answer.verdict) as a fixed-width table of at most 120 columns."""
    verdicts = verdict(table, found)
    if verdicts.empty:
        return "  (no curve ran)"
    shown = verdicts.assign(**{"s/impact-step": [f"{v:.3g}" if v == v else NOT_RESOLVED
                                                for v in verdicts["s/impact-step"]],
                               "truth uncertainty": [f"{v:.1e}" if v == v else "-"
                                                     for v in verdicts["truth uncertainty"]]})
    for level in ("1%", "0.1%"):
        shown[f"steps/contact for {level}"] = [steps_text(v, how) for v, how in
                                               zip(shown[f"steps/contact for {level}"], shown[f"how for {level}"])]
    for column in ("s/impact for 1%", "x paper for 1%", "s/impact for 0.1%", "x paper for 0.1%", "20% T_R error"):
        shown[column] = [f"{v:.3g}" if v == v else "-" for v in shown[column]]
    names = {"engine": "curve", "s/impact-step": "s/impact-step", "truth uncertainty": "truth +-",
             "steps/contact for 1%": "1%: steps", "s/impact for 1%": "s/impact", "x paper for 1%": "x paper",
             "steps/contact for 0.1%": "0.1%: steps", "s/impact for 0.1%": "s/impact ", "x paper for 0.1%": "x paper ",
             "20% T_R error": "20% T_R error"}
    shown = shown.rename(columns=names)
    return text_table(shown, list(names.values()))


def cost_tables(table, uncertainty, found=None):
    """The cost study's tables (--verbose): errors and times per rung, recommended time steps, orders of
    convergence, each curve's time per impact-step."""
    print()
    print(wrapped(f"{MEASURE}; net_wall_s: the fastest of repeated timings, summed over e_n, engine start-up (timed "
                  f"the same way) excluded; '{WITHIN_NOISE}' where that is not above the timings' spread; rungs "
                  f"'truth N': the levels of the converged reference"))
    for curve, per_e in uncertainty.items():
        worst = max(errs["err_max"] for errs in per_e.values())
        truth = next(iter(per_e.values())).get("truth", "")
        print(f"  converged reference of the {curve} dialect: {truth}, uncertainty {worst:.1e}"
              + (" (errors below this are not resolved)" if worst > 1e-6 else ""))
    rows = per_rung(table)
    rows["net_wall_s"] = [WITHIN_NOISE if timing == WITHIN_NOISE else f"{wall:.3g}"
                          for wall, timing in zip(rows.net_wall_s, rows.timing)]
    refused = table[table.status == "refused"].drop_duplicates(["engine", "dialect", "rung"])
    print()
    print(text_table(rows, ["engine", "dialect", "rung", "steps_per_contact", "dt", "net_wall_s",
                            *(f"err_{m}" for m in METRICS)],
                     {"steps_per_contact": "{:.4g}", "dt": "{:.3g}", **{f"err_{m}": "{:.1e}" for m in METRICS}}))
    for _, r in refused.iterrows():
        print(f"  refused: {r.engine}/{r.dialect} at {r.rung}: {r.message}")
    print("\nrecommended time step (coarsest rung within tolerance at every e_n, worst metric with its truth's "
          "uncertainty, and every finer rung too; how: f its formulas beyond its ladder, ~ extrapolated, <= a bound):")
    rec = recommendations(table, found)
    for tol in TOLERANCES:
        column = f"steps/contact for {key(tol)}"
        rec[column] = [steps_text(v, how) for v, how in zip(rec[column], rec[f"how for {key(tol)}"])]
    cols = [c for c in rec.columns if c.startswith(("dt for", "steps/contact"))] + ["error at 20% Rayleigh"]
    print(text_table(rec, ["engine", "dialect", *cols], {c: "{:.3g}" for c in cols if not c.startswith("steps")}))
    for note in notes(found if found is not None else answers(table)):
        print(wrapped(note, indent=4))
    print("\norder of convergence (slope of log error against log steps per contact, rungs >= 20; the adaptive "
          "curve: against force evaluations per contact):")
    orders = convergence_orders(table)
    print(text_table(orders, ["engine", "dialect", *METRICS], {m: "{:.2f}" for m in METRICS}))


def sliding_summary(sliding, psi_max):
    """`harness paper`'s first table: where each law slides throughout, from simulation and from its derived
    condition, each empty cell said in words."""
    table = text_table(sliding, ["model", "e_n_target", "simulated", "derived", "difference"],
                       {"simulated": "{:.4f}", "derived": "{:.4f}", "difference": "{:+.1e}"},
                       {"simulated": f"none <= {psi_max:g}", "derived": "no condition", "difference": "-"})
    heading = wrapped(f"where each law slides throughout (|F_t| = mu F_n the whole contact): the smallest Psi1* found "
                      f"by simulation, the condition derived for it (docs/laws.md#sliding-throughout) and their "
                      f"difference; 'none <= {psi_max:g}': no Psi1* up to {psi_max:g} slides throughout:")
    return f"{heading}\n{table}"


def published_summary(published):
    """The distances from the paper's published points (analyses/published.py) as a table, and the goal's verdict."""
    table = text_table(published, ["model", "e_n_target", "quantity", "points", "rms", "worst", "psi1_star_at_worst",
                                   "published_at_worst", "reference_at_worst"],
                       {"rms": "{:.3f}", "worst": "{:.3f}", "psi1_star_at_worst": "{:.2f}",
                        "published_at_worst": "{:.3f}", "reference_at_worst": "{:.3f}"})
    outside = published[~meets_goal(published)]
    verdict = (f"every law, e_n and quantity within the goal (worst <= {GOAL['worst']}, RMS <= {GOAL['rms']})"
               if outside.empty else f"{len(outside)} of {len(published)} outside the goal (worst <= "
                                     f"{GOAL['worst']}, RMS <= {GOAL['rms']})")
    return (f"distance from the paper's published points (e_t's x10):\n{table}\n"
            f"largest: RMS {published.rms.max():.3f}, worst {published.worst.max():.3f}; {verdict}")
