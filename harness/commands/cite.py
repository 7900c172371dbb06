"""`harness cite`: BibTeX for harness and for the paper and benchmark it uses (harness.citation)."""
from ..citation import bibliography
from .options import EXIT_OK


def add(sub, describe):
    p = describe(sub, "cite", "print BibTeX for harness, the paper it follows and the benchmark it runs",
                 "harness cite > harness.bib")
    p.set_defaults(func=main)


def main(args):
    print(bibliography(), end="")
    return EXIT_OK
