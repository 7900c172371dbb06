"""Every figure of a page also as files a paper can take: DIR/figures/NAME.svg and NAME.pdf, named for what the
figure shows, and the page's figure followed by links to both."""
import os
import re

from markupsafe import Markup, escape

from ..infra.files import write_bytes, write_text

FIGURES = "figures"                 # the folder beside a report that holds its figures' files
LONGEST = 80                        # characters of a file name's stem


def stem(title):
    """A file name for a figure's title: lower case, words joined by '-', '*' dropped (Psi1* -> psi1)."""
    text = re.sub(r"[^a-z0-9_.]+", "-", title.lower().replace("*", "")).strip("-.")
    return text[:LONGEST].rstrip("-.") or "figure"


def filed(directory, figures, folder=FIGURES):
    """[(title, figure)] with each figure (pieces.Figure) written as DIR/folder/NAME.svg and .pdf (NAME from the
    title, or from `(title, figure, name)`); returns [(title, the inline figure and its links)]; a figure of None
    stays None."""
    out, taken = [], set()
    for entry in figures:
        title, figure = entry[0], entry[1]
        if figure is None or not getattr(figure, "pdf", b""):
            out.append((title, figure))
            continue
        name = stem(entry[2] if len(entry) > 2 else title)
        while name in taken:
            name += "-2"
        taken.add(name)
        os.makedirs(os.path.join(directory, folder), exist_ok=True)
        write_text(os.path.join(directory, folder, f"{name}.svg"), figure.svg)
        write_bytes(os.path.join(directory, folder, f"{name}.pdf"), figure.pdf)
        href = f"{escape(folder)}/{escape(name)}"
        out.append((title, Markup(figure) + Markup(f'<p class="figure-files">this figure as <a href="{href}.svg">SVG'
                                                   f'</a> or <a href="{href}.pdf">PDF</a></p>')))
    return out


def one(directory, title, figure, name=None, folder=FIGURES):
    """A single figure filed (filed) and returned with its links."""
    return filed(directory, [(title, figure) + ((name,) if name else ())], folder)[0][1]
