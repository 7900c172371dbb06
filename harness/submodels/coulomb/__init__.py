"""Coulomb rules: what the friction cap mu |F_n| bounds, the spring alone or the spring with its tangential dashpot.
Each rule's `cap(f_s, damping, k_t, slip, limit)` returns (F_t, the spring force kept, whether the spring was cut);
the tangential dashpot is c_t = damping sqrt(k_t), none where damping is 0."""
from ...infra.jit import compiled


@compiled
def clip(force, limit):
    """Coulomb cap |F_t| <= mu F_n."""
    if force > limit:
        return limit
    if force < -limit:
        return -limit
    return force
