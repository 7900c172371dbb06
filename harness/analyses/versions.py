"""Version against version: for consecutive builds of one engine that ran in a comparison, which metric moved from one
release to the next, by how much and at which impact, and the ingredient of their dialects that moves it most when
switched alone (the pair attribution of the two dialects)."""
import pandas as pd

MOVED = 1e-6        # a metric that changes less between two builds did not move (round-off between builds ~1e-13)


def releases(engines):
    """{engine: [its builds, in the order they ran]} for every engine with two or more builds among `engines`."""
    out = {}
    for name in engines:
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


def version_changes(cross, attribution, engines):
    """One row per metric that moved between consecutive builds of an engine (or one row saying none did): the
    two versions, the largest signed change and where, the ingredients their dialects differ in, and the one that
    alone moves the metric most."""
    rows = []
    for code, names in releases(engines).items():
        for a, b in zip(names, names[1:]):
            table = cross.get((a, b), pd.DataFrame())
            attributed = attribution.get(f"{a} dialect -> {b} dialect")
            differ = ("; ".join(f"{r.ingredient}: {r.dialect} -> {r.target}" for r in attributed.itertuples())
                      if attributed is not None and not attributed.empty else "none")
            pair = {"engine": code, "from_version": a.partition("@")[2], "to_version": b.partition("@")[2]}
            moved = table[table.max_abs_diff > MOVED] if not table.empty else table
            if moved.empty:
                rows.append({**pair, "metric": "", "change": 0.0, "e_n_target": None, "theta_deg": None,
                             "ingredients_differing": differ, "attributed_to": f"no metric moved by more than {MOVED:g}"})
                continue
            for metric, group in moved.groupby("metric", sort=False):
                worst = group.loc[group.max_abs_diff.idxmax()]
                rows.append({**pair, "metric": metric, "change": float(worst.signed),
                             "e_n_target": float(worst.e_n_target), "theta_deg": float(worst.theta_deg),
                             "ingredients_differing": differ, "attributed_to": strongest(attributed, metric)})
    return pd.DataFrame(rows)
