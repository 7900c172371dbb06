"""Jinja rendering for engine inputs: StrictUndefined, and only checked numbers and fixed words reach the text."""
import math
import re
from numbers import Real
from pathlib import Path

import jinja2

from .citation import doc_link
from .wording import counted

REPORT_TEMPLATES = Path(__file__).resolve().parent.parent / "data" / "templates"     # the top-level templates/
WORD = re.compile(r"[A-Za-z0-9][A-Za-z0-9_/.-]*")


class RenderError(ValueError):
    """A value that is not a finite number, or a name outside the fixed vocabulary, was about to enter a deck."""


def num(value):
    """A finite real number as its shortest exact text (repr); anything else is refused."""
    if isinstance(value, bool) or not isinstance(value, Real):
        raise RenderError(f"refusing to render non-number {value!r}")
    value = float(value)
    if not math.isfinite(value):
        raise RenderError(f"refusing to render non-finite {value!r}")
    return repr(value)


def count(value):
    """A non-negative integer (step counts, loop bounds)."""
    if isinstance(value, bool) or not isinstance(value, int) or value < 0:
        raise RenderError(f"refusing to render {value!r} as a count")
    return str(value)


def word(value):
    """A keyword from the adapters' fixed sets: letters, digits and _ / . -, nothing else (no spaces, quotes, newlines
    or $)."""
    if not isinstance(value, str) or not WORD.fullmatch(value):
        raise RenderError(f"refusing to render {value!r} as a keyword")
    return value


def token(value):
    """A word of a user's engine input: an integer, a finite number (num) or a keyword (word)."""
    if isinstance(value, int) and not isinstance(value, bool):
        return str(value)
    return word(value) if isinstance(value, str) else num(value)


def environment(directory=REPORT_TEMPLATES, autoescape=False):
    env = jinja2.Environment(loader=jinja2.FileSystemLoader(str(directory)), undefined=jinja2.StrictUndefined,
                             autoescape=autoescape, keep_trailing_newline=True)
    env.filters["num"] = num
    env.filters["word"] = word
    env.filters["count"] = count
    env.filters["token"] = token
    env.filters["counted"] = counted
    env.globals["doc"] = doc_link
    return env


def render(directory, template, **values):
    """Render an engine's template from its own directory (not autoescaped: decks and scripts are not HTML)."""
    return environment(directory).get_template(template).render(**values)
