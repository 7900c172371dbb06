"""What every HTML view is made of: figures as embedded PNG and tables as formatted cells."""
import base64
import io


def figure_png(fig):
    """Encode a matplotlib figure as a base64 PNG data string."""
    buffer = io.BytesIO()
    fig.savefig(buffer, format="png", dpi=90, bbox_inches="tight")
    return base64.b64encode(buffer.getvalue()).decode("ascii")


def records(table):
    """A DataFrame as (columns, rows of formatted cells) for the template."""
    if table is None or table.empty:
        return None
    def cell(value):
        if isinstance(value, float):
            return f"{value:.6g}"
        return str(value)
    return list(table.columns), [[cell(v) for v in row] for row in table.itertuples(index=False)]
