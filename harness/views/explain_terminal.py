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
    if x.advice:
        lines.append(f"calibrate's advice: for {x.nearest[0][0]} at this e_n, give {x.engine.partition('@')[0]}:")
        lines += [f"  {line.strip()}" for line in x.advice]
    if x.agreement is not None:
        lines.append(f"{x.engine} ran it: worst {x.agreement:.2g} of V from its dialect")
    return lines


def print_explanation(x, quiet=False):
    lines = explanation_lines(x)
    print("\n".join(lines[-1:] if quiet else lines))
