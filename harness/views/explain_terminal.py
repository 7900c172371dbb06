"""What `harness explain` prints: an Explanation (studies/explain.py) as lines."""
import math


def explanation_lines(x):
    """The lines of an Explanation: the input and its composition, what it achieves, the nearest paper law, the same
    law in other inputs, calibrate's advice and, when run, the engine against its dialect."""
    sweep = x.sweep
    lines = [f"{x.engine} input: {x.text}",
             "computes (neutral sub-models): " + "; ".join(f"{k} {v}" for k, v in x.composition.items())]
    lines += [f"flagged: {flag}" for flag in x.flags]
    t_c = f"{x.t_contact * 1e3:.4g} ms" if math.isfinite(x.t_contact) else "n/a"
    lines.append(f"at normal incidence: e_n {x.e_n:.4f}, contact time {t_c}")
    oblique = sweep[sweep.theta_deg > 0]
    if len(oblique):
        lines.append(f"over {len(sweep)} impacts, {sweep.theta_deg.min():g} to {sweep.theta_deg.max():g} deg: e_t "
                     f"{oblique.e_t.min():.4f} to {oblique.e_t.max():.4f}, Omega* {oblique.omega_star.min():.4f} to "
                     f"{oblique.omega_star.max():.4f}")
    lines += x.notes
    for i, (law, distance) in enumerate(x.nearest):
        lead = "nearest paper law" if i == 0 else "then"
        lines.append(f"{lead}: {law} at e_n {min(max(x.e_n, 0.01), 1.0):.4g} and the input's stiffness, worst "
                     f"difference {distance:.2%} of V in rebound velocity or R omega")
    for engine, text in x.translations:
        lines.append(f"the same law in {engine}: {text}")
    lines += [nearest_line(n) for n in x.nearest_inputs]
    if x.advice:
        lines.append(f"calibrate's advice: for {x.nearest[0][0]} at this e_n, give {x.engine.partition('@')[0]}:")
        lines += [f"  {line.strip()}" for line in x.advice]
    if x.agreement is not None:
        lines.append(f"{x.engine} ran it: worst {x.agreement:.2g} of V from its dialect")
    return lines


def nearest_line(n):
    """One other engine's nearest input: no input of it tried computes this law, how far the nearest is, and why."""
    engine = n.engine.split()[0]
    line = (f"no {engine} input harness tried computes this law; nearest, {n.engine}: {n.text} (worst difference "
            f"{n.distance:.2%} of V")
    if n.ingredient is None:
        return line + ")"
    mine, theirs = n.labels
    return line + f"; its {n.ingredient}, {theirs} for {mine}, makes {n.share:.0%} of it)"


def explanation_record(x):
    """The Explanation as JSON-ready data (`harness explain --json`): what the lines say, in numbers."""
    oblique = x.sweep[x.sweep.theta_deg > 0]
    return {"engine": x.engine, "input": x.text, "composition": x.composition, "flags": x.flags, "e_n": x.e_n,
            "t_contact": x.t_contact if math.isfinite(x.t_contact) else None,
            "e_t": [float(oblique.e_t.min()), float(oblique.e_t.max())] if len(oblique) else None,
            "omega_star": [float(oblique.omega_star.min()), float(oblique.omega_star.max())] if len(oblique) else None,
            "nearest_paper_laws": [{"law": law, "distance": d} for law, d in x.nearest],
            "same_law": [{"engine": engine, "input": text} for engine, text in x.translations],
            "nearest_inputs": [{"engine": n.engine, "input": n.text, "distance": n.distance, "ingredient": n.ingredient,
                                "labels": list(n.labels) if n.labels else None, "share": n.share}
                               for n in x.nearest_inputs],
            "advice": [line.strip() for line in x.advice], "agreement": x.agreement, "notes": x.notes}


def print_explanation(x, quiet=False):
    lines = explanation_lines(x)
    print("\n".join(lines[-1:] if quiet else lines))
