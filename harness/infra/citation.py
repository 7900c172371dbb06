"""How to cite harness and the sources it uses: BibTeX for harness itself (version and date of harness.infra.version),
for Thornton, Cummins & Cleary (2013), the paper its laws and figures follow, for Chung & Ooi (2011), the benchmark
`harness benchmark chung-ooi` runs, and for each engine (its Engine.CITATION) with the versions installed or run;
and the project's address, from which a shared report links the docs."""
from .version import RELEASED, __version__

PROJECT_URL = "https://github.com/harness-dem/harness"
DOCS_URL = f"{PROJECT_URL}/blob/main/docs/"


def doc_url(page):
    """The absolute address of a page of docs/ (with its #anchor), so that a shared report's links work."""
    return DOCS_URL + page


def doc_link(page):
    """A report's link to a page of docs/: <a href="the absolute address">docs/PAGE</a>."""
    from markupsafe import Markup, escape
    return Markup(f'<a href="{escape(doc_url(page))}">docs/{escape(page)}</a>')


SOFTWARE = {"key": "harness", "type": "software", "title": "harness: cross-validation of DEM contact force models",
            "author": "{The harness developers}", "version": __version__, "year": RELEASED[:4],
            "date": RELEASED, "url": PROJECT_URL}
SOURCES = (
    {"key": "thornton2013", "type": "article",
     "title": "An investigation of the comparative behaviour of alternative contact force models during inelastic "
              "collisions",
     "author": "Thornton, Colin and Cummins, Sharen J. and Cleary, Paul W.", "journal": "Powder Technology",
     "volume": "233", "pages": "30--46", "year": "2013", "doi": "10.1016/j.powtec.2012.08.012"},
    {"key": "chung2011", "type": "article",
     "title": "Benchmark tests for verifying discrete element modelling codes at particle impact level",
     "author": "Chung, Y. C. and Ooi, J. Y.", "journal": "Granular Matter", "volume": "13", "number": "5",
     "pages": "643--656", "year": "2011", "doi": "10.1007/s10035-011-0277-0"},
)


def bibtex(entry):
    """One BibTeX entry: @type{key, field = {value}, ...}."""
    fields = ",\n".join(f"  {name} = {{{value}}}" for name, value in entry.items() if name not in ("key", "type"))
    return f"@{entry['type']}{{{entry['key']},\n{fields}\n}}\n"


def engine_entry(name, citation, versions, how):
    """An engine's entry: its publication, with a note naming the engine, its versions and how they were used."""
    return {**citation, "note": f"{name} {', '.join(versions)}, {how}"}


def bibliography(engines=()):
    """BibTeX of harness, of every source it uses, and of the engine entries given (engine_entry)."""
    return "\n".join(bibtex(entry) for entry in (SOFTWARE, *SOURCES, *engines))
