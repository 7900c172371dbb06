"""The campaign report: one HTML page over a whole store, data first: where each engine agrees with its formulas
(worst relative difference per law and scene), and how far it deviates from the paper law, as maps of the e_t
difference over e_n x impact angle per engine and law (the worst over the other dimensions of the matrix)."""
import html

import numpy as np
import pandas as pd

from ..analyses.agreement import AGREEMENT_TOLERANCE, agreement
from ..files import write_text

SCENE = ["model", "radius", "E", "nu", "rho", "mu", "omega0", "steps_per_contact"]


def scenes(table):
    """The store's rows grouped by comparison: one law on one scene at one resolution (speed from the impacts)."""
    speed = np.round(np.hypot(table.v_n0, table.v_t0), 9)
    return table.assign(speed=speed).groupby(SCENE + ["speed"], sort=True, dropna=False)


def agreement_table(table):
    """Per engine, law and scene: the worst relative difference from its formulas at equal dt."""
    rows = []
    for key, group in scenes(table):
        for engine in sorted(set(group.engine) - {"reference"}):
            worst = agreement(group, engine).max_rel_diff.max()
            rows.append({**dict(zip(SCENE + ["speed"], key)), "engine": engine, "worst": worst,
                         "agrees": bool(worst <= AGREEMENT_TOLERANCE)})
    return pd.DataFrame(rows)


def deviation_maps(table, metric="e_t"):
    """{(engine, law): e_n x angle table of the largest |engine - paper law| in `metric`}."""
    maps = {}
    for _, group in scenes(table):
        paper = group[(group.engine == "reference") & (group.dialect == "paper")]
        for engine in sorted(set(group.engine) - {"reference"}):
            mine = group[(group.engine == engine) & (group.dialect == engine) & (group.status == "ok")]
            pairs = mine.merge(paper, on=["e_n_target", "theta_deg"], suffixes=("", "_paper"))
            if pairs.empty:
                continue
            pairs = pairs.assign(diff=(pairs[metric] - pairs[metric + "_paper"]).abs())
            grid = pairs.pivot_table(index="e_n_target", columns="theta_deg", values="diff", aggfunc="max")
            key = (engine, group.model.iloc[0])
            maps[key] = grid if key not in maps else np.fmax(maps[key], grid.reindex_like(maps[key]))
    return maps


def _cell(value, high):
    if not np.isfinite(value):
        return "<td></td>"
    shade = int(255 - 155 * min(1.0, value / high)) if high > 0 else 255
    return f'<td style="background: rgb(255,{shade},{shade})">{value:.3g}</td>'


def _map_html(title, grid):
    high = float(np.nanmax(grid.to_numpy())) if grid.size else 0.0
    head = "".join(f"<th>{a:g}</th>" for a in grid.columns)
    body = "".join(f"<tr><th>{e:g}</th>{''.join(_cell(v, high) for v in row)}</tr>"
                   for e, row in zip(grid.index, grid.to_numpy()))
    return (f"<h3>{html.escape(title)}</h3><table><tr><th>e_n \\ angle [deg]</th>{head}</tr>{body}</table>")


def write_campaign_report(table, path, name):
    """Write the page to `path` from the store's table; returns the path."""
    failed = table[table.status == "failed"]
    agree = agreement_table(table) if not table.empty else pd.DataFrame()
    parts = [f"<h1>Campaign {html.escape(name)}</h1>",
             f"<p>{len(table)} rows, {table.task_key.nunique()} tasks; laws: {', '.join(sorted(table.model.unique()))}; "
             f"engines: {', '.join(sorted(table.engine.unique()))}; {failed.task_key.nunique()} failed tasks.</p>",
             "<h2>Agreement of each engine with its formulas (worst relative difference, tolerance "
             f"{AGREEMENT_TOLERANCE:g})</h2>", agree.to_html(index=False, float_format=lambda v: f"{v:.3g}")
             if not agree.empty else "<p>(no engine ran)</p>",
             "<h2>Deviation from the paper law: |e_t(engine) - e_t(paper)|, worst over the matrix</h2>"]
    parts += [_map_html(f"{engine}, {law}", grid) for (engine, law), grid in sorted(deviation_maps(table).items())]
    if not failed.empty:
        parts.append("<h2>Failed tasks</h2>")
        for key, group in failed.groupby("task_key"):
            parts.append(f"<p><b>{html.escape(group.engine.iloc[0])} {html.escape(group.model.iloc[0])} e_n "
                         f"{group.e_n_target.iloc[0]:g}</b>: {html.escape(group.message.iloc[0])}</p>"
                         f"<pre>{html.escape(group.log_tail.iloc[0])}</pre>")
    style = ("<style>body{font-family:sans-serif;margin:2em}table{border-collapse:collapse}td,th{border:1px solid "
             "#ccc;padding:2px 6px;text-align:right}</style>")
    return write_text(path, f"<!doctype html><html><head><meta charset='utf-8'><title>Campaign {html.escape(name)}"
                            f"</title>{style}</head><body>{''.join(parts)}</body></html>")
