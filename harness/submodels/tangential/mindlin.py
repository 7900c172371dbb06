"""No-slip Mindlin k_t = 8 G* a in three forms: the paper's eq. 18b (rescale on unloading), incremental (not reduced
as a falls) and on the total displacement (docs/laws.md#tangential-laws); each form's kernel is a module of its own
(mindlin_rescale.py, ...)."""
from ...infra.errors import UserError
from ...infra.jit import compiled
from ..base import TangentialModel

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
def stiffness(G, a):
    """k_t = 8 G a (G = G*, or what plays it)."""
    return 8.0 * G * a
