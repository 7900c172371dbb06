"""How every sentence harness prints counts and compares: a count with its noun in the right number ("1 impact",
"3 impacts"), a verb agreeing with it, and a signed amount said as more or less, never as "-0.2 more"."""

IRREGULAR = {"has": "have", "is": "are", "was": "were", "does": "do"}


def plural(count, noun, many=None):
    """The noun for `count` of it: 'impact' for 1, 'impacts' otherwise (or `many`)."""
    return noun if count == 1 else many or noun + "s"


def counted(count, noun, many=None):
    """'1 impact', '0 impacts', '3 impacts'."""
    return f"{count} {plural(count, noun, many)}"


def verb(count, singular):
    """A verb agreeing with `count` of its subject: verb(1, 'ends') == 'ends', verb(2, 'ends') == 'end'."""
    if count == 1:
        return singular
    if singular in IRREGULAR:
        return IRREGULAR[singular]
    return singular[:-2] if singular.endswith(("sses", "ches", "shes", "xes")) else singular[:-1]


def more_or_less(amount, unit="", digits=3):
    """A signed difference as an amount and a direction: 0.006 -> '0.006 more', (-19, '%') -> '19% less'."""
    return f"{abs(amount):.{digits}g}{unit} {'less' if amount < 0 else 'more'}"
