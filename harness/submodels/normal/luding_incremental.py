"""Luding's hysteretic spring in its incremental form without adhesion (kc = 0), against a huge fixed sphere standing
in for the wall: the plastic overlap DeltNull carried step to step (Luding 2008)."""

from ...infra.jit import compiled
from ..base import NormalParameters
from .luding_peak import LudingPeak

NAME = "luding-incremental"
SUMMARY = "Luding's hysteretic spring, its plastic overlap carried step to step (Luding 2008)"
ADAPTIVE = False
SLOTS = ("k1", "kp", "delt_p_max", "delt_p_null")
DELT_MAX, DELT_NULL, DELT_PREV = 0, 1, 2            # its history: largest, plastic and previous overlap
HISTORY_RESET = (0.0, 0.0, 0.0)


class LudingIncremental(LudingPeak):
    """Luding's incremental spring against a huge fixed sphere: k1 as the linear spring, kp = k1 (2/e^2 - 1), DeltPMax =
    2x the
    normal peak overlap, so k2 = K1/e^2 at the scene speed; DeltPNull = PhiF 2R* with R* = R_big R/(R_big + R) of
    the huge sphere, kc = 0, G0 = 0."""
    name, kernel = "luding-incremental", NAME
    HUGE = 3e5      # radius of the fixed sphere standing in for the wall, in sphere radii (the kernel reproduces
                    # sphere-sphere geometry with it: overlap round-off, tilting normal, rotated shear force)

    def parameters(self, contact, e_n, speed):
        base = super().parameters(contact, e_n, speed)
        k1, kp, d_p_max = base["k1"], base["k2_max"], base["d_lim"]
        return NormalParameters.named(base.linear_stiffness, base.contact_time, k1=k1, kp=kp, delt_p_max=d_p_max,
                                      delt_p_null=self.plasticity_depth(k1, kp, d_p_max, contact) * 2.0 *
                                      self.reduced_radius(contact))

    def stand_in_radius(self, contact):
        """Radius of the fixed sphere that plays the wall (geometry stand-in-sphere)."""
        return self.HUGE * contact.radius

    def reduced_radius(self, contact):
        big = self.stand_in_radius(contact)
        return big * contact.radius / (big + contact.radius)

    def plasticity_depth(self, k1, kp, d_p_max, contact):
        """PhiF from DeltPMax = kp/(kp - k1) PhiF 2R* (equation (7) of Luding 2008)."""
        return d_p_max * (kp - k1) / (kp * 2.0 * self.reduced_radius(contact))


@compiled
def luding(k1, kp, delt_p_max, delt_p_null, delt, delt_max, delt_null, delt_prev):
    """k2 from the previous largest overlap, k2 = k1 + (kp - k1) DeltMax/DeltPMax (<= kp); a new maximum moves
    DeltNull = min((1 - k1/k2) DeltMax, DeltPNull); force k1 d while k2 (d - DeltNull) >= k1 d (k2 line beyond
    DeltPMax), else k2 (d - DeltNull) down to 0, where an unloading contact resets DeltMax = d k2/(k2 - k1).
    Returns (F, DeltMax, DeltNull)."""
    k2 = kp if delt_max / delt_p_max >= 1.0 else k1 + (kp - k1) * delt_max / delt_p_max
    if k2 > kp:
        k2 = kp
    if delt > delt_max:
        delt_max = delt
        delt_null = min((1.0 - k1 / k2) * delt_max, delt_p_null)
    k2_delt = k2 * (delt - delt_null)
    if k2_delt >= k1 * delt:
        force = k1 * delt if delt < delt_p_max else k2_delt
    elif k2_delt > 0.0:
        force = k2_delt
    elif delt - delt_prev < 0.0:
        force = 0.0
        delt_max = delt * k2 / (k2 - k1)
        delt_null = min((1.0 - k1 / k2) * delt_max, delt_p_null)
    else:
        force = k2_delt
    return force, delt_max, delt_null


@compiled
def step(k1, kp, delt_p_max, delt_p_null, radius, alpha, alpha_old, f_old, alpha_max, history, new_history):
    """One step of the incremental Luding law at overlap alpha: (F, 0) and its history after the step."""
    f, new_history[DELT_MAX], new_history[DELT_NULL] = luding(k1, kp, delt_p_max, delt_p_null, alpha, history[DELT_MAX],
                                                              history[DELT_NULL], history[DELT_PREV])
    new_history[DELT_PREV] = alpha
    return f, 0.0
