"""k_t/k_n of the springs that take a ratio: 'kappa', 'nu', a fraction or a number."""
from fractions import Fraction

from ...infra.errors import UserError


def parse_ratio(text):
    """'2/7', 'kappa', 'nu' (Poisson's ratio: k_s = nu k_n) or a positive number -> float or the name."""
    if text in ("kappa", "nu"):
        return text
    try:
        value = float(Fraction(str(text)))
    except (ValueError, ZeroDivisionError):
        raise UserError(f"k_t/k_n must be 'kappa', a fraction like 2/7 or a positive number, got {text!r}") from None
    if not 0.0 < value <= 10.0:
        raise UserError(f"k_t/k_n must lie in (0, 10], got {text!r}")
    return value


def ratio_label(kt_kn):
    return kt_kn if isinstance(kt_kn, str) else round(kt_kn, 6)


def ratio_value(kt_kn, contact):
    return {"kappa": contact.kappa, "nu": contact.nu}.get(kt_kn, kt_kn)
