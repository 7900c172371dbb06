"""Spring-less friction: F_t = -sign(V_s) min(c_t |V_s|, mu F_n), c_t from k_t = k_n or 8 G* a (
'tangential no_history'); needs a tangential-damping rule."""
import math

from ...infra.errors import UserError
from ...infra.jit import compiled
from ..base import TangentialModel

FORMS = {"linear": "viscous:linear", "mindlin": "viscous:mindlin"}


class ViscousTangential(TangentialModel):
    """No spring: F_t = -sign(V_s) min(c_t |V_s|, mu F_n) with the tangential dashpot's c_t computed from k_t =
    k_n ('linear') or 8 G* a ('mindlin'), no spring history. Needs a tangential-damping rule."""
    name = "viscous"

    def __init__(self, form="linear"):
        if form not in FORMS:
            raise UserError(f"viscous tangential form must be one of {', '.join(FORMS)}, got {form!r}")
        self.form, self.kernel = form, FORMS[form]
        self.constant_stiffness = form == "linear"

    def label(self):
        return f"viscous({self.form})"

    def parameter(self, contact, k_n):
        return k_n if self.form == "linear" else contact.G_star


@compiled
def friction(k_t, c_factor, slip, limit):
    """F = -sign(V_s) min(c_t |V_s|, mu F_n), c_t = c_factor sqrt(k_t)."""
    c_t = c_factor * math.sqrt(k_t)
    force = c_t * abs(slip)
    if force > limit:
        force = limit
    return -force if slip > 0.0 else force
