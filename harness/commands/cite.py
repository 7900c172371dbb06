"""`harness cite`: BibTeX for harness and for the paper and benchmark it uses (harness.citation)."""
from ..citation import bibliography
from .options import EXIT_OK


def main(args):
    print(bibliography(), end="")
    return EXIT_OK
