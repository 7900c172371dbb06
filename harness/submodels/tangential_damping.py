"""Tangential dashpot: c_t = 2 g_t sqrt(m k_t), applied only while the contact sticks (docs/laws.md#tangential-dashpot)."""
import math

from ..errors import UserError

RULES = ("none", "normal-ratio", "normal-coefficient", "proportional", "beta", "reversed-beta")


class TangentialDashpot:
    """g_t fixed, or borrowed from the normal dashpot: g_t = g_n ('normal-ratio', LIGGGHTS hertz, YADE) or
    c_t = c_n ('normal-coefficient', LIGGGHTS hooke: g_t = g_n sqrt(k_n/k_t), constant k_t only) or
    c_t = c_n k_t/k_n ('proportional', YADE ViscEl: g_t = g_n sqrt(k_t/k_n), constant k_t only); or from e_n:
    g_t = sqrt(5/6)|beta| ('beta'), and its negative ('reversed-beta': the sign defect of LIGGGHTS thornton_ning,
    which adds energy), beta = ln e/sqrt(ln^2 e + pi^2)."""

    def __init__(self, spec="none"):
        self.spec = str(spec)
        if self.spec in RULES:
            self.rule, self.value = self.spec, 0.0
            return
        try:
            self.rule, self.value = "ratio", float(self.spec)
        except ValueError:
            raise UserError(f"tangential-damping must be {', '.join(RULES)} or a damping ratio, got {spec!r}") from None
        if not (math.isfinite(self.value) and 0.0 <= self.value < 100.0):
            raise UserError(f"tangential-damping ratio must lie in [0, 100), got {spec!r}")

    def label(self):
        return self.spec

    def ratio(self, dashpot, k_n, k_t, e_n):
        """The damping ratio g_t for this contact (dashpot: the calibrated normal Dashpot)."""
        if self.rule == "none":
            return 0.0
        if self.rule in ("beta", "reversed-beta"):
            beta = abs(math.log(e_n)) / math.sqrt(math.log(e_n) ** 2 + math.pi ** 2)
            return math.sqrt(5.0 / 6.0) * beta * (1.0 if self.rule == "beta" else -1.0)
        if self.rule == "ratio":
            return self.value
        if self.rule == "normal-ratio":
            return dashpot.g
        if k_t is None:
            raise UserError(f"{self.rule} tangential damping needs a constant tangential stiffness")
        if self.rule == "proportional":
            return dashpot.g * math.sqrt(k_t / k_n)
        return dashpot.g * math.sqrt(k_n / k_t)
