"""What a notebook shows of a result: a short text (repr) and a small HTML block, the verdict first, then one table
of at most MAX_ROWS rows."""
import html

MAX_ROWS = 12
MAX_LINE = 110


def short_text(kind, lines):
    """<kind line; line; ...>: each line cut at MAX_LINE characters."""
    cut = [line if len(line) <= MAX_LINE else line[:MAX_LINE - 3] + "..." for line in lines]
    return f"<{kind} " + "\n ".join(cut) + ">"


def block(title, verdict, lines, table=None):
    """An HTML block: the title, the verdict in bold, the lines, and `table` (a DataFrame) cut at MAX_ROWS rows."""
    parts = [f"<div><p><b>{html.escape(title)}</b>: <b>{html.escape(verdict)}</b></p>"]
    parts += [f"<p>{html.escape(line)}</p>" for line in lines]
    if table is not None and not table.empty:
        parts.append(table.head(MAX_ROWS).to_html(index=False, float_format=lambda v: f"{v:.4g}", na_rep=""))
        if len(table) > MAX_ROWS:
            parts.append(f"<p>({len(table) - MAX_ROWS} more rows)</p>")
    return "".join(parts) + "</div>"
