"""Tangential dashpot: c_t = 2 g_t sqrt(m_t k_t), acting while the contact sticks (docs/laws.md#tangential-dashpot).
A spec is a rule for g_t, then options: 'total' (Coulomb's test on spring plus dashpot) and 'sphere-mass'."""
import math

from ..infra.errors import UserError

RULES = ("none", "normal-ratio", "normal-coefficient", "proportional", "beta", "reversed-beta", "classical")
CONES = ("spring-first", "total")        # the paper scheme's Coulomb test: the spring's first, or the sum's
MASSES = ("mass", "sphere-mass")         # m_t: the sphere's mass m, or its tangential effective mass
CONE_CODES = {"spring-first": 0.0, "total": 1.0}      # the cone slot's values
SLOTS = ("prefactor", "cone", "share")   # c_t = prefactor sqrt(k_t) + share c_n, CONE_CODES: its columns


class TangentialDashpot:
    """g_t fixed, or borrowed from the normal dashpot: g_t = g_n ('normal-ratio') or
    c_t = c_n ('normal-coefficient': g_t = g_n sqrt(k_n/k_t), constant k_t only) or
    c_t = c_n k_t/k_n ('proportional': g_t = g_n sqrt(k_t/k_n), constant k_t only); or from e_n:
    g_t = -ln e/sqrt(ln^2 e + pi^2) ('classical', the linear oscillator's with tension), g_t = sqrt(5/6)|beta|
    ('beta', Tsuji's with tension), and its negative ('reversed-beta': a dashpot of the wrong sign,
    which adds energy), beta = ln e/sqrt(ln^2 e + pi^2).
    Options, for the paper scheme: 'spring-first' (default: a spring beyond mu F_n slides and carries the whole
    force; a sticking spring gets the dashpot, the sum capped at mu F_n) or 'total' (the spring held within the
    cone, then the sum capped); 'sphere-mass': m_t = m/(1 + m R^2/I) (2/7 m for a solid sphere on a wall) in place
    of m."""

    normal_share = 0.0          # c_t += normal_share c_n(alpha): its slot 'share'

    def __init__(self, spec="none"):
        self.spec = str(spec)
        head, *options = self.spec.split(":")
        self.cone, self.mass = CONES[0], MASSES[0]
        for option in options:
            if option in CONES:
                self.cone = option
            elif option in MASSES:
                self.mass = option
            else:
                raise UserError(f"tangential-damping options are {', '.join(CONES + MASSES)}, got {option!r} "
                                f"in {spec!r}")
        if head in RULES:
            self.rule, self.value = head, 0.0
            return
        try:
            self.rule, self.value = "ratio", float(head)
        except ValueError:
            raise UserError(f"tangential-damping must be {', '.join(RULES)} or a damping ratio, then options "
                            f"(e.g. normal-ratio:total), got {spec!r}") from None
        if not (math.isfinite(self.value) and 0.0 <= self.value < 100.0):
            raise UserError(f"tangential-damping ratio must lie in [0, 100), got {spec!r}")

    def label(self):
        """The rule and its options other than the defaults, e.g. 'normal-ratio' or 'classical:total:sphere-mass'."""
        head = self.spec.split(":")[0]
        options = [o for o in (self.cone, self.mass) if o not in (CONES[0], MASSES[0])]
        return ":".join([head] + options)

    def ratio(self, dashpot, k_n, k_t, e_n):
        """The damping ratio g_t for this contact (dashpot: the calibrated normal Dashpot)."""
        if self.rule == "none":
            return 0.0
        if self.rule in ("beta", "reversed-beta", "classical"):
            beta = abs(math.log(e_n)) / math.sqrt(math.log(e_n) ** 2 + math.pi ** 2)
            if self.rule == "classical":
                return beta
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

    def effective_mass(self, contact):
        """m_t: the mass m, or m/(1 + m R^2/I) with 'sphere-mass' (the mass the contact point's slip responds with)."""
        if self.mass == "sphere-mass":
            return contact.mass / (1.0 + contact.mass * contact.radius ** 2 / contact.inertia)
        return contact.mass

    def prefactor(self, contact, dashpot, k_n, k_t, e_n):
        """2 g_t sqrt(m_t): c_t = this sqrt(k_t)."""
        return 2.0 * self.ratio(dashpot, k_n, k_t, e_n) * math.sqrt(self.effective_mass(contact))



class GivenTangentialDashpot(TangentialDashpot):
    """c_t(alpha) = share c_n(alpha) + per_mass m, given by an input's numbers: the share through the slot 'share',
    per_mass m as the prefactor c_t/sqrt(k_t), k_t = unit_stiffness R^radius_power (the caller has checked that k_t
    is constant there)."""

    def __init__(self, share, per_mass, unit_stiffness, radius_power):
        super().__init__("none")
        self.normal_share, self.per_mass = float(share), float(per_mass)
        self.unit_stiffness, self.radius_power = float(unit_stiffness), float(radius_power)
        self.rule = "given" if (self.normal_share or self.per_mass) else "none"

    def label(self):
        if self.rule == "none":
            return "none"
        return f"c_t={self.normal_share:.6g}*c_n" if self.normal_share else f"c_t={self.per_mass:.6g}*m"

    def prefactor(self, contact, dashpot, k_n, k_t, e_n):
        if not self.per_mass:
            return 0.0
        return self.per_mass * contact.mass / (self.unit_stiffness * contact.radius ** self.radius_power) ** 0.5
