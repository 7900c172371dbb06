"""The tangential spring's pieces every kernel shares: the mean contact radius of a step and the trial spring force
from the registered kernels (dispatch.tangential_spring)."""

from ..infra.jit import compiled
from ..submodels.tangential.state import T_AOLD
from .dispatch import tangential_spring


@compiled
def mean_radius(a_old, a):
    """Mean of a = sqrt(R alpha) over a step in which alpha changes linearly: 2/3 (a1^3 - a0^3)/(a1^2 - a0^2); exact
    at first touch (a ~ sqrt(t), where the trapezoid's error would sum to O(h^1.5)), second order elsewhere."""
    total = a_old + a
    if total <= 0.0:
        return 0.0
    return (2.0 / 3.0) * (a_old * a_old + a_old * a + a * a) / total


@compiled
def spring_force(code, p, f_s, dd, a, mu, n_new, n_old, st, scratch, midpoint):
    """Trial spring force after the increment dd, before the Coulomb cap; updates the history `st`. `a` is the
    contact radius at the end of the step, st[T_AOLD] the one at its start; with `midpoint` (the paper scheme) the
    kernels use the step's mean radius, engines the current one."""
    a_old = st[T_AOLD]
    a_mid = mean_radius(a_old, a) if midpoint else a
    st[T_AOLD] = a
    return tangential_spring(code, p, f_s, dd, a_mid, a, a_old, mu, n_new, n_old, st, scratch, midpoint)
