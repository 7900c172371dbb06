"""`harness cite`: BibTeX for harness and for the paper and benchmark it uses (harness.citation)."""
from ..citation import bibliography
from .options import EXIT_OK


def add(sub, describe):
    p = describe(sub, "cite", "harness cite > harness.bib")
    p.set_defaults(func=main)


def main(args):
    print(bibliography(), end="")
    return EXIT_OK
