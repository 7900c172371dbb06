"""The campaign report: one HTML page over a whole store, data first: each metric (e_n, e_t, Omega*) and each
engine's deviation from the paper law against each swept parameter, as figures (also SVG and PDF files) over tables
that `harness query` reproduces with the SQL shown; where each engine agrees with its formulas (worst relative
difference per law and scene); maps of the e_t difference over e_n x impact angle per engine and law; each table
drawn from campaign.page's data under the command that prints it."""
import html
import os

import numpy as np
import pandas as pd

from ..analyses.agreement import AGREEMENT_TOLERANCE
from ..infra.citation import doc_link
from ..infra.files import write_text
from .drawing import draw_all
from .figure_files import filed
from .pieces import figure_svg, legend_below
from ..infra.wording import counted

def figures_folder(path):
    """The folder, beside the page, of its figures' files: STORE-figures for STORE.html."""
    return os.path.basename(path)[:-len(".html")] + "-figures"


KEY_STEPS = 6       # swatches of a map's colour key, from 0 to the map's largest value


def _shade(value, high):
    """The background of a map's cell: white at 0, deepening to rgb(255,100,100) at the map's largest value."""
    shade = int(255 - 155 * min(1.0, value / high)) if high > 0 else 255
    return f"rgb(255,{shade},{shade})"


def _cell(value, high):
    if not np.isfinite(value):
        return "<td></td>"
    return f'<td style="background: {_shade(value, high)}">{value:.3g}</td>'


def _key_html(high):
    """The colour key under a map: swatches from 0 to its largest value, each with the value it stands for."""
    values = np.linspace(0.0, high, KEY_STEPS) if high > 0 else [0.0]
    swatches = "".join(f'<span class="swatch" style="background: {_shade(v, high)}">{v:.3g}</span>' for v in values)
    return f'<p class="key">colour key (white 0, red the largest of this map): {swatches}</p>'


def _largest(frame):
    """The largest value of a map (0 for an empty one)."""
    grid = frame.set_index("e_n_target").to_numpy(float)
    return float(np.nanmax(grid)) if grid.size and np.isfinite(grid).any() else 0.0


def _map_html(frame):
    """A map's table, e_n down and the impact angles across, each cell shaded by its share of the largest."""
    grid, high = frame.set_index("e_n_target"), _largest(frame)
    head = "".join(f"<th>{html.escape(str(a))}</th>" for a in grid.columns)
    body = "".join(f"<tr><th>{e:g}</th>{''.join(_cell(v, high) for v in row)}</tr>"
                   for e, row in zip(grid.index, grid.to_numpy(float)))
    return f"<table><tr><th>e_n_target</th>{head}</tr>{body}</table>"


def _queried(what, sql, store, body, attributes=""):
    """A table of the page under the `harness query` command that prints it."""
    command = f'harness query {store} "{sql}"'
    return (f"<p>{what}: <code>{html.escape(command)}</code></p>"
            f"<div class='query'{attributes} data-sql='{html.escape(sql)}'>{body}</div>")


def _positions(values):
    """x positions of a parameter's values: the numbers themselves, or 0, 1, ... for words (with their ticks)."""
    if pd.api.types.is_numeric_dtype(values):
        return values.astype(float).to_numpy(), None
    order = sorted(values.astype(str).unique())
    return values.astype(str).map(order.index).to_numpy(float), order


def _axes(count, width=3.4):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, count, figsize=(width * count, 3.4), squeeze=False, layout="constrained")
    return plt, fig, axes[0]


def metric_figure(table, parameter, label, metric, metric_label):
    """`metric` against `parameter`, one panel per e_n: per law, engine and dialect the mean over the other
    dimensions of the matrix (line) and their range (band)."""
    groups = list(table.groupby("e_n_target", sort=True))
    plt, fig, axes = _axes(len(groups))
    for ax, (e_n, group) in zip(axes, groups):
        for (model, engine, dialect), rows in group.groupby(["model", "engine", "dialect"], sort=True):
            x, ticks = _positions(rows[parameter])
            order = np.argsort(x)
            line, = ax.plot(x[order], rows[f"mean_{metric}"].to_numpy()[order], marker="o", ms=3,
                            label=f"{model}, {engine} ({dialect})")
            ax.fill_between(x[order], rows[f"min_{metric}"].to_numpy()[order], rows[f"max_{metric}"].to_numpy()[order],
                            color=line.get_color(), alpha=0.15, lw=0)
            if ticks:
                ax.set_xticks(range(len(ticks)), ticks)
        ax.set(xlabel=label, ylabel=metric_label, title=f"e_n = {e_n:g}")
        ax.grid(alpha=0.3)
    legend_below(fig, fontsize=6.5)
    svg = figure_svg(fig)
    plt.close(fig)
    return svg


def deviation_figure(table, parameter, label):
    """Each engine's worst deviation from the paper law against `parameter`: one panel per metric, one line per law,
    engine and e_n."""
    from ..studies.campaign.sweeps import DEVIATION_METRICS
    plt, fig, axes = _axes(len(DEVIATION_METRICS))
    for ax, (column, words) in zip(axes, DEVIATION_METRICS.items()):
        for (model, engine, e_n), rows in table.groupby(["model", "engine", "e_n_target"], sort=True):
            x, ticks = _positions(rows[parameter])
            order = np.argsort(x)
            ax.plot(x[order], rows[f"worst_{column}"].to_numpy()[order], marker="o", ms=3,
                    label=f"{model}, {engine}, e_n {e_n:g}")
            if ticks:
                ax.set_xticks(range(len(ticks)), ticks)
        ax.set(xlabel=label, title=words)
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("worst over the other dimensions")
    legend_below(fig, fontsize=6.5)
    svg = figure_svg(fig)
    plt.close(fig)
    return svg


def _table_html(frame):
    return frame.to_html(index=False, float_format=lambda v: f"{v:.4g}", classes="sweep")


def sweep_sections(sweeps, directory, folder, store):
    """The HTML of each swept parameter: its figures (filed as SVG and PDF) over the tables and their SQL."""
    from ..studies.campaign.sweeps import METRICS
    calls, entries = [], []
    for sweep in sweeps:
        for metric, words in METRICS.items():
            entries.append((sweep, f"{words} against {sweep.label}", f"{metric}-vs-{sweep.parameter}"))
            calls.append((metric_figure, (sweep.table, sweep.parameter, sweep.label, metric, words)))
        if not sweep.deviation.empty:
            entries.append((sweep, f"deviation from the paper law against {sweep.label}",
                            f"deviation-vs-{sweep.parameter}"))
            calls.append((deviation_figure, (sweep.deviation, sweep.parameter, sweep.label)))
    drawn = filed(directory, [(title, svg, name) for (_, title, name), svg in zip(entries, draw_all(calls))], folder)
    parts = []
    for sweep in sweeps:
        parameter = html.escape(sweep.parameter)
        parts.append(f"<h2 id='against-{parameter}'>Against {html.escape(sweep.label)}</h2>")
        parts += [f"<figure data-parameter='{parameter}'>{svg}<figcaption>{html.escape(title)}</figcaption></figure>"
                  for (owner, _, _), (title, svg) in zip(entries, drawn) if owner is sweep]
        for sql, frame, what in ((sweep.sql, sweep.table, "each metric's mean and range over the other dimensions"),
                                 (sweep.deviation_sql, sweep.deviation, "each engine's worst deviation from the paper "
                                                                        "law")):
            if not frame.empty:
                parts.append(_queried(what, sql, store, _table_html(frame), f" data-parameter='{parameter}'"))
    return parts


def write_campaign_report(table, path, name, data=None, store=""):
    """Write the page to `path` from the store's table and what it shows (campaign.page.page_data), the figures'
    files in STORE-figures/ beside it; returns the path."""
    failed = table[table.status == "failed"]
    agreement, maps = (data.agreement, data.maps) if data is not None else (None, [])
    parts = [f"<h1>Campaign {html.escape(name)}</h1>",
             f"<p>{counted(len(table), 'row')}, {counted(table.task_key.nunique(), 'task')}; "
             f"laws: {', '.join(sorted(table.model.unique()))}; "
             f"engines: {', '.join(sorted(table.engine.unique()))}; "
             f"{counted(failed.task_key.nunique(), 'failed task')} "
             f"(what each part shows: {doc_link('campaigns.md')}).</p>",
             "<p>Swept: " + (", ".join(html.escape(s.label) for s in data.sweeps) if data is not None and data.sweeps
                             else "no scene parameter") + ".</p>",
             *sweep_sections(data.sweeps if data is not None else (), os.path.dirname(os.path.abspath(path)),
                             figures_folder(path), store),
             "<h2>Agreement of each engine with its formulas (worst relative difference, tolerance "
             f"{AGREEMENT_TOLERANCE:g})</h2>",
             _queried("per engine, law and scene", agreement.sql, store,
                      agreement.frame.to_html(index=False, float_format=lambda v: f"{v:.3g}"))
             if agreement is not None and not agreement.frame.empty else "<p>(no engine ran)</p>",
             "<h2>Deviation from the paper law over e_n x impact angle: |e_t(engine) - e_t(paper)|, the worst over the "
             "other dimensions</h2>"]
    parts += [f"<h3>{html.escape(shown.title)}</h3>" + _queried("the map", shown.sql, store, _map_html(shown.frame))
              + _key_html(_largest(shown.frame)) for shown in maps]
    if not failed.empty:
        parts.append("<h2>Failed tasks</h2>")
        if data is not None and data.failures is not None:
            parts.append(_queried("each failed engine, law and e_n", data.failures.sql, store,
                                  data.failures.frame.to_html(index=False)))
        for key, group in failed.groupby("task_key"):
            parts.append(f"<p><b>{html.escape(group.engine.iloc[0])} {html.escape(group.model.iloc[0])} e_n "
                         f"{group.e_n_target.iloc[0]:g}</b>: {html.escape(group.message.iloc[0])}</p>"
                         f"<pre>{html.escape(group.log_tail.iloc[0])}</pre>")
    style = ("<style>body{font-family:sans-serif;margin:2em}table{border-collapse:collapse}td,th{border:1px solid "
             "#ccc;padding:2px 6px;text-align:right}.swatch{display:inline-block;padding:2px 8px;border:1px solid "
             "#ccc}</style>")
    return write_text(path, f"<!doctype html><html><head><meta charset='utf-8'><title>Campaign {html.escape(name)}"
                            f"</title>{style}</head><body>{''.join(parts)}</body></html>")
