"""What every HTML view is made of: figures as inline SVG (crisp at any zoom) that carry their SVG and PDF files,
and tables of numbers formatted for people (4 significant digits, short exponents, blank where there is no value)."""
import io
import math
import numbers

from markupsafe import Markup

from ..infra.wording import counted, verb


class Figure(Markup):
    """Inline SVG markup that also holds the figure as files: `svg` (a whole SVG document) and `pdf` (bytes)."""
    svg = ""
    pdf = b""


def figure_svg(fig):
    """A matplotlib figure as inline SVG markup (its XML header dropped), its text as text (searchable, smaller and
    faster to write than glyph outlines); it carries the SVG document and a PDF (fonts embedded as TrueType) for
    views.figure_files to write."""
    import matplotlib
    buffer, pdf = io.StringIO(), io.BytesIO()
    with matplotlib.rc_context({"svg.fonttype": "none", "pdf.fonttype": 42}):
        fig.savefig(buffer, format="svg")
        fig.savefig(pdf, format="pdf", metadata={"CreationDate": None})
    text = buffer.getvalue()
    figure = Figure(text[text.index("<svg"):])
    figure.svg, figure.pdf = text, pdf.getvalue()
    return figure


def legend_below(fig, extra=(), fontsize=7):
    """One legend for the whole figure, below its panels, so that it covers no data: each label drawn in any panel
    once, then `extra` handles, in as many columns (at most four) as the figure's width holds; the figure grows by
    its height, so that the panels keep theirs (the figure must use the constrained layout)."""
    handles = {}
    for ax in fig.axes:
        for handle, label in zip(*ax.get_legend_handles_labels()):
            handles.setdefault(label, handle)
    handles = [*handles.values(), *extra]
    for columns in range(min(4, len(handles)), 0, -1):
        legend = fig.legend(handles=handles, loc="outside lower center", ncols=columns, fontsize=fontsize,
                            frameon=False)
        extent = legend.get_window_extent(fig.canvas.get_renderer())
        if columns == 1 or extent.width <= fig.bbox.width:
            fig.set_figheight(fig.get_figheight() + extent.height / fig.dpi)
            return
        legend.remove()


def number(value, digits=4):
    """A number for a person: integers as they are, floats to `digits` significant digits with a short exponent
    (3.47e-8), blank for NaN or None."""
    if value is None or isinstance(value, bool):
        return "" if value is None else str(value)
    if isinstance(value, numbers.Integral):
        return str(value)
    if isinstance(value, numbers.Real):
        value = float(value)
        if math.isnan(value):
            return ""
        text = f"{value:.{digits}g}"
        if "e" in text:
            mantissa, exponent = text.split("e")
            text = f"{mantissa}e{int(exponent)}"
        return text
    return str(value)


def records(table, digits=4):
    """A DataFrame as (columns, rows of formatted cells) for the template."""
    if table is None or table.empty:
        return None
    return list(table.columns), [[number(v, digits) for v in row] for row in table.itertuples(index=False)]


def si(value, unit, digits=4):
    """A quantity with an SI prefix: 7e10 Pa -> '70 GPa', 0.025 m -> '25 mm'."""
    if value == 0 or not math.isfinite(value):
        return f"{number(value, digits)} {unit}"
    for factor, prefix in ((1e9, "G"), (1e6, "M"), (1e3, "k"), (1.0, ""), (1e-3, "m"), (1e-6, "u"), (1e-9, "n")):
        if abs(value) >= factor:
            return f"{number(value / factor, digits)} {prefix}{unit}"
    return f"{number(value, digits)} {unit}"


def checks_headline(passed, checked, none="No check was made."):
    """A verdict in words: how many checks passed and how many failed (`none` where no check was made)."""
    if not checked:
        return none
    if passed == checked:
        return f"Every check passes: {passed} of {checked}."
    return (f"{checked - passed} of {counted(checked, 'check')} {verb(checked - passed, 'fails')}; {passed} "
            f"{verb(passed, 'passes')}.")
