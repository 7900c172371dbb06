"""Version against version: for consecutive builds of one engine that ran in a comparison, which metric moved from one
release to the next, by how much and at which impact, and the ingredient of their dialects that moves it most when
switched alone (the pair attribution of the two dialects)."""
import pandas as pd

from ..infra.releases import in_release_order

MOVED = 1e-6        # a metric that changes less between two builds did not move (round-off between builds ~1e-13)


def releases(engines):
    """{engine: [its builds, in release order]} for every engine with two or more builds among `engines`."""
    out = {}
    for name in in_release_order(engines):
        code, at, _ = name.partition("@")
        if at:
            out.setdefault(code, []).append(name)
    return {code: names for code, names in out.items() if len(names) > 1}


def strongest(attribution, metric):
    """'ingredient (from -> to)' of the attribution row that alone changes `metric` most, or ''."""
    column = f"d_{metric}"
    if attribution is None or attribution.empty or column not in attribution:
        return ""
    values = attribution[column].abs()
    if values.isna().all():
        return ""
    row = attribution.loc[values.idxmax()]
    return f"{row.ingredient} ({row.dialect} -> {row.target}: {row[column]:+.4g})"


IDENTICAL = "none: the dialects are identical, the binaries differ"


def differing(attribution, a, b):
    """(the ingredients the dialects of builds a and b differ in, 'key: a's -> b's; ...', IDENTICAL when none does,
    'unknown: ...' when no attribution between them was measured; the attribution of a's dialect switched towards
    b's, or None): from the attribution measured either way."""
    forward, backward = attribution.get(f"{a} dialect -> {b} dialect"), attribution.get(f"{b} dialect -> {a} dialect")
    if forward is not None:
        pairs = [(r.ingredient, r.dialect, r.target) for r in forward.itertuples()]
    elif backward is not None:
        pairs = [(r.ingredient, r.target, r.dialect) for r in backward.itertuples()]
    else:
        return f"unknown: no attribution between {a}'s and {b}'s dialects was measured", None
    text = "; ".join(f"{ingredient}: {ours} -> {theirs}" for ingredient, ours, theirs in pairs)
    return text or IDENTICAL, forward


def status_changes(results, a, b):
    """(status in a, status in b, impacts, first impact) of each change of status between the engine rows of builds
    a and b at the same impacts (e.g. ok -> non-finite), which no metric's difference shows."""
    keys = ["e_n_target", "theta_deg"]
    rows = [results[(results.engine == name) & (results.dialect == name)][keys + ["status"]] for name in (a, b)]
    pairs = rows[0].merge(rows[1], on=keys, suffixes=("_a", "_b"))
    changed = pairs[pairs.status_a != pairs.status_b]
    return [(sa, sb, len(group), group.iloc[0]) for (sa, sb), group in changed.groupby(["status_a", "status_b"],
                                                                                          sort=False)]


def version_changes(results, cross, attribution, engines):
    """One row per metric that moved between consecutive builds of an engine, in release order, and per change of
    status (metric 'status', e.g. 3 impacts ok in one and non-finite in the next), or one row saying nothing did: the
    two versions, the largest signed change and where, the ingredients their dialects differ in, and the one that
    alone moves the metric most; `flagged` where something changed between identical dialects (only the binaries
    differ, which no ingredient of harness explains)."""
    rows = []
    for code, names in releases(engines).items():
        for a, b in zip(names, names[1:]):
            table = cross.get((a, b), pd.DataFrame())
            differ, attributed = differing(attribution, a, b)
            pair = {"engine": code, "from_version": a.partition("@")[2], "to_version": b.partition("@")[2],
                    "ingredients_differing": differ, "flagged": differ == IDENTICAL}
            moved = table[table.max_abs_diff > MOVED] if not table.empty else pd.DataFrame(columns=["metric"])
            statuses = status_changes(results, a, b)
            if moved.empty and not statuses:
                rows.append({**pair, "metric": "", "change": 0.0, "e_n_target": None, "theta_deg": None,
                             "attributed_to": f"no metric moved by more than {MOVED:g}", "flagged": False})
                continue
            for metric, group in moved.groupby("metric", sort=False):
                worst = group.loc[group.max_abs_diff.idxmax()]
                cause = ("the binaries: the dialects are identical" if differ == IDENTICAL else
                         strongest(attributed, metric) if attributed is not None else
                         f"not attributed: no attribution from {a}'s dialect towards {b}'s was measured")
                rows.append({**pair, "metric": metric, "change": float(worst.signed),
                             "e_n_target": float(worst.e_n_target), "theta_deg": float(worst.theta_deg),
                             "attributed_to": cause})
            for before, after, count, first in statuses:
                rows.append({**pair, "metric": "status", "change": float("nan"),
                             "e_n_target": float(first.e_n_target), "theta_deg": float(first.theta_deg),
                             "attributed_to": f"{count} impacts {before} in {a.partition('@')[2]}, {after} in "
                                              f"{b.partition('@')[2]}"})
    columns = ["engine", "from_version", "to_version", "metric", "change", "e_n_target", "theta_deg",
               "ingredients_differing", "attributed_to", "flagged"]
    return pd.DataFrame(rows, columns=columns)
