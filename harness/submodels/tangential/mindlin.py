"""No-slip Mindlin k_t = 8 G* a in three forms: the paper's eq. 18b (rescale on unloading), incremental (not reduced
as a falls) and on the total displacement (docs/laws.md#tangential-laws)."""
import math

from ...errors import UserError
from ...jit import compiled
from ..base import TangentialModel
from .state import T_AUX1

FORMS = {"rescale": "mindlin:rescale", "incremental": "mindlin:incremental", "total": "mindlin:total"}


class Mindlin(TangentialModel):
    """No-slip Mindlin k_t = 8 G* a: 'rescale' = paper eq. 18b, 'incremental' (F_s - k_t dd), 'total' (-k_t xi)."""
    name = "mindlin"
    FORMS, DEFAULT_FORM = FORMS, "rescale"          # form -> kernel

    def __init__(self, form=None):
        form = form or self.DEFAULT_FORM
        if form not in self.FORMS:
            raise UserError(f"{self.name} form must be one of {', '.join(self.FORMS)}, got {form!r}")
        self.form, self.kernel = form, self.FORMS[form]

    def label(self):
        return f"{self.name}({self.form})"

    def parameter(self, contact, k_n):
        return contact.G_star


@compiled
def stiffness(p1, a):
    """k_t = 8 G* a (p1 = G*)."""
    return 8.0 * p1 * a


@compiled
def incremental(f_s, dd, a_mid, a, a_old, p1, mu, n_new, n_old, st, scratch, midpoint):
    """F_s - 8 G* a dd, not reduced as a falls."""
    return f_s - stiffness(p1, a_mid) * dd


@compiled
def rescale(f_s, dd, a_mid, a, a_old, p1, mu, n_new, n_old, st, scratch, midpoint):
    """Paper eq. 18b: on unloading (a < a_old) F_s <- F_s a/a_old, split around the increment -8 G* a dd."""
    if a >= a_old:
        return f_s - 8.0 * p1 * a_mid * dd
    half = math.sqrt(a / a_old)
    return (f_s * half - 8.0 * p1 * a_mid * dd) * half


@compiled
def total(f_s, dd, a_mid, a, a_old, p1, mu, n_new, n_old, st, scratch, midpoint):
    """F = -8 G* a xi, xi the total tangential displacement."""
    st[T_AUX1] += dd
    return -8.0 * p1 * a * st[T_AUX1]


@compiled
def total_after_cap(f_s, p1, a, st):
    """Keep the total displacement consistent with a capped force: xi = -F/k_t."""
    k_t = 8.0 * p1 * a
    st[T_AUX1] = -f_s / k_t if k_t > 0.0 else 0.0
