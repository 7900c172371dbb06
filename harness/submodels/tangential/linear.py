"""Linear tangential spring: dF_t = -k_t V_s dt, k_t = q k_n, capped by Coulomb (docs/laws.md#tangential-laws)."""

from ...infra.jit import compiled
from ..base import TangentialModel
from .ratio import parse_ratio, ratio_label, ratio_value

NAME = "linear"
SUMMARY = "dF_t = -k_t V_s dt, k_t constant"
SLOTS = ("k_t",)
ADAPTIVE = True


class LinearTangential(TangentialModel):
    """dF_t = -k_t V_s dt, k_t = ratio k_n (2/7: equal periods; kappa: Mindlin's initial ratio, the paper's)."""
    name, kernel, constant_stiffness = "linear", NAME, True

    def __init__(self, kt_kn="2/7"):
        self.kt_kn = parse_ratio(kt_kn)

    def label(self):
        return f"linear(k_t/k_n={ratio_label(self.kt_kn)})"

    def parameter(self, contact, k_n):
        return ratio_value(self.kt_kn, contact) * k_n


@compiled
def stiffness(k_t, a):
    """k_t: constant."""
    return k_t


@compiled
def spring(k_t, f_s, dd, a_mid, a, a_old, mu, n_new, n_old, st, scratch, midpoint):
    """F_s - k_t dd."""
    return f_s - k_t * dd
