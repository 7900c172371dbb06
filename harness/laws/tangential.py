"""Tangential sub-models (all capped by Coulomb |F_t| <= mu F_n) and their kernel parameter (MODELS 3)."""
from fractions import Fraction

from ..errors import UserError
from ..solver import codes as C

MINDLIN_FORMS = {"rescale": C.TANGENTIAL_MINDLIN_RESCALE, "incremental": C.TANGENTIAL_MINDLIN_INCREMENTAL,
                 "total": C.TANGENTIAL_MINDLIN_TOTAL}


def parse_ratio(text):
    """'2/7', 'kappa', 'nu' (Poisson's ratio: YADE CundallStrack) or a positive number -> float or the name."""
    if text in ("kappa", "nu"):
        return text
    try:
        value = float(Fraction(str(text)))
    except (ValueError, ZeroDivisionError):
        raise UserError(f"k_t/k_n must be 'kappa', a fraction like 2/7 or a positive number, got {text!r}") from None
    if not 0.0 < value <= 10.0:
        raise UserError(f"k_t/k_n must lie in (0, 10], got {text!r}")
    return value


class LinearTangential:
    """dF_t = -k_t V_s dt, k_t = ratio k_n (2/7: equal periods; kappa: Mindlin's initial ratio), capped."""
    name, code = "linear", C.TANGENTIAL_LINEAR

    def __init__(self, kt_kn="2/7"):
        self.kt_kn = parse_ratio(kt_kn)

    def label(self):
        return f"linear(k_t/k_n={self.kt_kn if isinstance(self.kt_kn, str) else round(self.kt_kn, 6)})"

    def parameter(self, contact, k_n):
        ratio = {"kappa": contact.kappa, "nu": contact.nu}.get(self.kt_kn, self.kt_kn)
        return ratio * k_n


class Mindlin:
    """No-slip Mindlin k_t = 8 G* a: 'rescale' = paper eq. 18b, 'incremental' (YADE), 'total' (LIGGGHTS)."""
    name = "mindlin"

    def __init__(self, form="rescale"):
        if form not in MINDLIN_FORMS:
            raise UserError(f"mindlin form must be one of {', '.join(MINDLIN_FORMS)}, got {form!r}")
        self.form = form
        self.code = MINDLIN_FORMS[form]

    def label(self):
        return f"mindlin({self.form})"

    def parameter(self, contact, k_n):
        return contact.G_star


class MindlinDeresiewicz(Mindlin):
    """Mindlin-Deresiewicz as Thornton & Yin (1991): dT = 8G*a theta_k dd + (-1)^k mu dN (1 - theta_k)."""
    name, code, form = "mindlin-deresiewicz", C.TANGENTIAL_MINDLIN_DERESIEWICZ, "deresiewicz"

    def __init__(self):
        pass

    def label(self):
        return self.name


class WaltonBraunTangential(LinearTangential):
    """Walton & Braun (1986): k_t = k_t0 [1 - (T - T*)/(mu N - T*)]^1/3, k_t0 = ratio k_n (2/7 default) [rec]."""
    name, code = "walton-braun", C.TANGENTIAL_WALTON_BRAUN

    def label(self):
        return f"walton-braun(k_t0/k_n={self.kt_kn if isinstance(self.kt_kn, str) else round(self.kt_kn, 6)})"


class ViscousTangential:
    """No spring: F_t = -sign(V_s) min(c_t |V_s|, mu F_n) with the tangential dashpot's c_t computed from k_t =
    k_n ('linear') or 8 G* a ('mindlin'); LIGGGHTS 'tangential no_history'. Needs a tangential-damping rule."""
    name = "viscous"
    FORMS = {"linear": C.TANGENTIAL_VISCOUS_LINEAR, "mindlin": C.TANGENTIAL_VISCOUS_MINDLIN}

    def __init__(self, form="linear"):
        if form not in self.FORMS:
            raise UserError(f"viscous tangential form must be one of {', '.join(self.FORMS)}, got {form!r}")
        self.form, self.code = form, self.FORMS[form]

    def label(self):
        return f"viscous({self.form})"

    def parameter(self, contact, k_n):
        return k_n if self.form == "linear" else contact.G_star


TANGENTIAL_MODELS = {cls.name: cls for cls in (LinearTangential, Mindlin, MindlinDeresiewicz, WaltonBraunTangential,
                                                ViscousTangential)}
