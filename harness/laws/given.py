"""A law of given numbers: an engine input's spring, dashpot and friction as neutral sub-models whose parameters are
the input's numbers, not calibrated from e_n (docs/laws.md#given-numbers)."""
from ..infra.errors import not_modelled
from ..submodels.damping.fixed import FixedDashpot
from ..submodels.normal.given import GivenHertz, GivenLinear
from ..submodels.tangential.given import GivenContactRadiusSpring, GivenLinearTangential, GivenMindlin, GivenViscous
from ..submodels.tangential_damping import GivenTangentialDashpot
from .law import Law, replace_submodels


def given_law(spring, dashpot, friction, tangential_damping, overrides, summary):
    """The Law of an input: spring ('linear', k_n) or ('hertz', E*); dashpot (c, mass power, radius power, alpha power)
    for c0 = c m^a R^b; friction ('linear', k_t), ('mindlin:FORM', k_t/a), ('contact-radius', k[, nan reason]) or
    ('viscous', _, _[, nan reason]); tangential_damping ('share', x: c_t = x c_n) or ('per-mass', g: c_t = g m);
    `overrides` the stepping sub-models. A constant tangential dashpot beside a Mindlin spring
    does is not modelled (the solver's c_t = prefactor sqrt(k_t) + share c_n)."""
    normal = GivenLinear(spring[1]) if spring[0] == "linear" else GivenHertz(spring[1])
    damping = FixedDashpot(*dashpot)
    kind, reason = friction[0], (friction[3] if len(friction) > 3 else "")
    if kind == "linear":
        tangential, unit, radius_power, k_power = GivenLinearTangential(friction[1]), friction[1], 0.0, 0.0
    elif kind == "contact-radius":
        tangential, unit, radius_power, k_power = GivenContactRadiusSpring(friction[1], reason), friction[1], 0.0, 0.0
    elif kind.startswith("mindlin:"):
        tangential = GivenMindlin(kind.partition(":")[2], friction[1])
        unit, radius_power, k_power = friction[1], 0.5, 0.5          # k_t = k R^1/2 alpha^1/2
    else:                                    # no spring: the dashpot alone (c_t = prefactor sqrt(1), or the share)
        tangential, unit, radius_power, k_power = GivenViscous("linear", 1.0, reason), 1.0, 0.0, 0.0
    share, per_mass = ((tangential_damping[1], 0.0) if tangential_damping[0] == "share" else
                       (0.0, tangential_damping[1]))
    if per_mass and k_power:
        not_modelled(f"a constant tangential dashpot beside a tangential stiffness growing as alpha^{k_power:g} "
                     f"({summary}); give a tangential damping of 0")
    law = Law("input", normal, damping, "tension", tangential,
              GivenTangentialDashpot(share, per_mass, unit, radius_power), summary=summary)
    return replace_submodels(law, overrides)
