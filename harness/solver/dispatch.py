"""Generated from harness/submodels/registry.py by `python -m harness.submodels.generate`: do not edit.

Kernel codes, capability tables and the dispatch of every compiled sub-model function (docs/design.md).
"""
import math

import numpy as np

from ..jit import compiled
from ..submodels.normal import linear as normal_linear
from ..submodels.normal import hertz as normal_hertz
from ..submodels.normal import walton_braun as normal_walton_braun
from ..submodels.normal import thornton as normal_thornton
from ..submodels.normal import stronge as normal_stronge
from ..submodels.normal import luding_peak as normal_luding_peak
from ..submodels.normal import thornton_ning as normal_thornton_ning
from ..submodels.normal import luding_incremental as normal_luding_incremental
from ..submodels.tangential import linear as tangential_linear
from ..submodels.tangential import mindlin as tangential_mindlin
from ..submodels.tangential import mindlin_deresiewicz as tangential_mindlin_deresiewicz
from ..submodels.tangential import walton_braun as tangential_walton_braun
from ..submodels.tangential import viscous as tangential_viscous
from ..submodels.tangential import mindlin_wall_coefficient as tangential_mindlin_wall_coefficient
from ..submodels.tangential import contact_radius_spring as tangential_contact_radius_spring
from ..submodels.tangential import mindlin_unloading as tangential_mindlin_unloading
from .extension import BELOW, FORCE, KINK, RESIDUAL, SLOPE, call

N_NORMAL = 8
NORMAL_LINEAR = 0
NORMAL_HERTZ = 1
NORMAL_WALTON_BRAUN = 2
NORMAL_THORNTON = 3
NORMAL_STRONGE = 4
NORMAL_LUDING_PEAK = 5
NORMAL_THORNTON_NING = 6
NORMAL_LUDING_INCREMENTAL = 7
NORMAL_HISTORY = 3
NORMAL_RESET = np.array([[0.0, 0.0, 0.0], [0.0, 0.0, 0.0], [0.0, 0.0, 0.0], [0.0, 0.0, 0.0], [0.0, 0.0, 0.0], [0.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 0.0, 0.0]], dtype=np.float64)
NORMAL_INCREMENTAL = (6, 7)
TANGENTIAL_NONE = 0
TANGENTIAL_LINEAR = 1
TANGENTIAL_MINDLIN_INCREMENTAL = 2
TANGENTIAL_MINDLIN_RESCALE = 3
TANGENTIAL_MINDLIN_TOTAL = 4
TANGENTIAL_MINDLIN_DERESIEWICZ = 5
TANGENTIAL_WALTON_BRAUN = 6
TANGENTIAL_VISCOUS_LINEAR = 7
TANGENTIAL_VISCOUS_MINDLIN = 8
TANGENTIAL_MINDLIN_TOTAL_RESCALE = 9
TANGENTIAL_MINDLIN_FORCE_RESCALE = 10
TANGENTIAL_CONTACT_RADIUS_SPRING = 11
TANGENTIAL_MINDLIN_UNLOADING = 12
TANGENTIAL_VISCOUS = np.array([False, False, False, False, False, False, False, True, True, False, False, False, False], dtype=np.bool_)
TANGENTIAL_IMPLICIT = np.array([False, False, False, False, False, False, True, False, False, False, False, False, False], dtype=np.bool_)
TANGENTIAL_LOG_RATE = np.array([0, 0, 0, 1, 2, 0, 0, 0, 0, 0, 0, 0, 0], dtype=np.int64)
TANGENTIAL_ANY_IMPLICIT = True   # numba drops the implicit stepper where False


@compiled
def normal_force(code, p1, p2, p3, p4, radius, alpha, alpha_max, ext):
    if code == 0:
        return normal_linear.force(p1, p2, p3, p4, radius, alpha, alpha_max)
    if code == 1:
        return normal_hertz.force(p1, p2, p3, p4, radius, alpha, alpha_max)
    if code == 2:
        return normal_walton_braun.force(p1, p2, p3, p4, radius, alpha, alpha_max)
    if code == 3:
        return normal_thornton.force(p1, p2, p3, p4, radius, alpha, alpha_max)
    if code == 4:
        return normal_stronge.force(p1, p2, p3, p4, radius, alpha, alpha_max)
    if code == 5:
        return normal_luding_peak.force(p1, p2, p3, p4, radius, alpha, alpha_max)
    if code >= N_NORMAL:
        return call(ext, code - N_NORMAL, FORCE, p1, p2, p3, p4, radius, alpha, alpha_max, 0.0, 0.0)
    return math.nan, math.nan


@compiled
def normal_below(code, p1, p2, p3, p4, alpha, ext):
    if code == 0:
        return normal_linear.below(p1, p2, p3, p4, alpha)
    if code >= N_NORMAL:
        return call(ext, code - N_NORMAL, BELOW, p1, p2, p3, p4, 0.0, alpha, 0.0, 0.0, 0.0)[0]
    return 0.0


@compiled
def normal_slope(code, p1, p2, p3, p4, radius, alpha, loading, f, a, ext):
    if code == 0:
        return normal_linear.slope(p1, p2, p3, p4, radius, alpha, loading, f, a)
    if code == 1:
        return normal_hertz.slope(p1, p2, p3, p4, radius, alpha, loading, f, a)
    if code == 2:
        return normal_walton_braun.slope(p1, p2, p3, p4, radius, alpha, loading, f, a)
    if code == 3:
        return normal_thornton.slope(p1, p2, p3, p4, radius, alpha, loading, f, a)
    if code == 4:
        return normal_stronge.slope(p1, p2, p3, p4, radius, alpha, loading, f, a)
    if code >= N_NORMAL:
        return call(ext, code - N_NORMAL, SLOPE, p1, p2, p3, p4, radius, alpha, 1.0 if loading else 0.0, f, a)
    return math.nan, math.nan


@compiled
def normal_residual(code, p1, p2, p3, p4, radius, alpha_max, ext):
    if code == 2:
        return normal_walton_braun.residual(p1, p2, p3, p4, radius, alpha_max)
    if code == 3:
        return normal_thornton.residual(p1, p2, p3, p4, radius, alpha_max)
    if code == 4:
        return normal_stronge.residual(p1, p2, p3, p4, radius, alpha_max)
    if code >= N_NORMAL:
        return call(ext, code - N_NORMAL, RESIDUAL, p1, p2, p3, p4, radius, 0.0, alpha_max, 0.0, 0.0)[0]
    return 0.0


@compiled
def normal_kink(code, p1, p2, p3, p4, ext):
    if code == 3:
        return normal_thornton.kink(p1, p2, p3, p4)
    if code == 4:
        return normal_stronge.kink(p1, p2, p3, p4)
    if code == 5:
        return normal_luding_peak.kink(p1, p2, p3, p4)
    if code >= N_NORMAL:
        return call(ext, code - N_NORMAL, KINK, p1, p2, p3, p4, 0.0, 0.0, 0.0, 0.0, 0.0)[0]
    return 0.0


@compiled
def normal_step(code, p1, p2, p3, p4, radius, alpha, alpha_old, f_old, alpha_max, history, new_history, ext):
    if code == 6:
        return normal_thornton_ning.step(p1, p2, p3, p4, radius, alpha, alpha_old, f_old, alpha_max, history, new_history)
    if code == 7:
        return normal_luding_incremental.step(p1, p2, p3, p4, radius, alpha, alpha_old, f_old, alpha_max, history, new_history)
    return normal_force(code, p1, p2, p3, p4, radius, alpha, alpha_max, ext)


@compiled
def tangential_stiffness(code, p1, a):
    if code == 1:
        return tangential_linear.stiffness(p1, a)
    if code == 2:
        return tangential_mindlin.stiffness(p1, a)
    if code == 3:
        return tangential_mindlin.stiffness(p1, a)
    if code == 4:
        return tangential_mindlin.stiffness(p1, a)
    if code == 5:
        return tangential_mindlin_deresiewicz.stiffness(p1, a)
    if code == 6:
        return tangential_walton_braun.stiffness(p1, a)
    if code == 7:
        return tangential_viscous.linear_stiffness(p1, a)
    if code == 8:
        return tangential_viscous.mindlin_stiffness(p1, a)
    if code == 9:
        return tangential_mindlin_wall_coefficient.stiffness(p1, a)
    if code == 10:
        return tangential_mindlin_wall_coefficient.stiffness(p1, a)
    if code == 11:
        return tangential_contact_radius_spring.stiffness(p1, a)
    if code == 12:
        return tangential_mindlin_unloading.stiffness(p1, a)
    return math.nan


@compiled
def tangential_spring(code, f_s, dd, a_mid, a, a_old, p1, mu, n_new, n_old, st, scratch, midpoint):
    if code == 1:
        return tangential_linear.spring(f_s, dd, a_mid, a, a_old, p1, mu, n_new, n_old, st, scratch, midpoint)
    if code == 2:
        return tangential_mindlin.incremental(f_s, dd, a_mid, a, a_old, p1, mu, n_new, n_old, st, scratch, midpoint)
    if code == 3:
        return tangential_mindlin.rescale(f_s, dd, a_mid, a, a_old, p1, mu, n_new, n_old, st, scratch, midpoint)
    if code == 4:
        return tangential_mindlin.total(f_s, dd, a_mid, a, a_old, p1, mu, n_new, n_old, st, scratch, midpoint)
    if code == 5:
        return tangential_mindlin_deresiewicz.spring(f_s, dd, a_mid, a, a_old, p1, mu, n_new, n_old, st, scratch, midpoint)
    if code == 6:
        return tangential_walton_braun.spring(f_s, dd, a_mid, a, a_old, p1, mu, n_new, n_old, st, scratch, midpoint)
    if code == 9:
        return tangential_mindlin_wall_coefficient.total_rescale(f_s, dd, a_mid, a, a_old, p1, mu, n_new, n_old, st, scratch, midpoint)
    if code == 10:
        return tangential_mindlin_wall_coefficient.force_rescale(f_s, dd, a_mid, a, a_old, p1, mu, n_new, n_old, st, scratch, midpoint)
    if code == 11:
        return tangential_contact_radius_spring.spring(f_s, dd, a_mid, a, a_old, p1, mu, n_new, n_old, st, scratch, midpoint)
    if code == 12:
        return tangential_mindlin_unloading.spring(f_s, dd, a_mid, a, a_old, p1, mu, n_new, n_old, st, scratch, midpoint)
    return math.nan


@compiled
def tangential_after_cap(code, f_s, p1, a, st):
    if code == 4:
        tangential_mindlin.total_after_cap(f_s, p1, a, st)
        return
    if code == 9:
        tangential_mindlin_wall_coefficient.total_after_cap(f_s, p1, a, st)
        return
    if code == 11:
        tangential_contact_radius_spring.after_cap(f_s, p1, a, st)
        return
    return


@compiled
def tangential_force_from_w(code, d, star, cone, w):
    if code == 6:
        return tangential_walton_braun.force_from_w(d, star, cone, w)
    return math.nan


@compiled
def tangential_w_from_force(code, d, star, cone, f_s):
    if code == 6:
        return tangential_walton_braun.w_from_force(d, star, cone, f_s)
    return math.nan


@compiled
def tangential_edge_w(code, d, star, sign):
    if code == 6:
        return tangential_walton_braun.edge_w(d, star, sign)
    return math.nan


@compiled
def tangential_onset_w(code, p1, v_s, rise):
    if code == 6:
        return tangential_walton_braun.onset_w(p1, v_s, rise)
    return math.nan
