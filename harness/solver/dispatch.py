"""Generated from harness/submodels/registry.py by `python -m harness.submodels.generate`: do not edit.

Kernel codes, capability tables and the dispatch of every compiled sub-model function (docs/design.md).
"""
import math

import numpy as np

from ..infra.jit import compiled
from ..submodels.normal import linear as normal_linear
from ..submodels.normal import hertz as normal_hertz
from ..submodels.normal import walton_braun as normal_walton_braun
from ..submodels.normal import thornton as normal_thornton
from ..submodels.normal import stronge as normal_stronge
from ..submodels.normal import luding_peak as normal_luding_peak
from ..submodels.normal import thornton_ning as normal_thornton_ning
from ..submodels.normal import luding_incremental as normal_luding_incremental
from ..submodels.end import tension as end_tension
from ..submodels.end import no_tension as end_no_tension
from ..submodels.tangential import linear as tangential_linear
from ..submodels.tangential import mindlin_incremental as tangential_mindlin_incremental
from ..submodels.tangential import mindlin_rescale as tangential_mindlin_rescale
from ..submodels.tangential import mindlin_total as tangential_mindlin_total
from ..submodels.tangential import mindlin_deresiewicz as tangential_mindlin_deresiewicz
from ..submodels.tangential import walton_braun as tangential_walton_braun
from ..submodels.tangential import viscous_linear as tangential_viscous_linear
from ..submodels.tangential import viscous_mindlin as tangential_viscous_mindlin
from ..submodels.tangential import mindlin_total_rescale as tangential_mindlin_total_rescale
from ..submodels.tangential import mindlin_force_rescale as tangential_mindlin_force_rescale
from ..submodels.tangential import contact_radius_spring as tangential_contact_radius_spring
from ..submodels.tangential import mindlin_unloading as tangential_mindlin_unloading
from ..submodels.coulomb import spring as coulomb_spring
from ..submodels.coulomb import total as coulomb_total
from ..submodels.coulomb import total_cases as coulomb_total_cases
from ..submodels.coulomb import spring_first as coulomb_spring_first
from ..submodels.touch import gap as touch_gap
from ..submodels.touch import overlap as touch_overlap
from .extension import BELOW, FORCE, KINK, RESIDUAL, SLOPE, call
from .layout import (NORMAL_BLOCK, NORMAL_BLOCK_END, NORMAL_HERTZ_E_STAR, NORMAL_LINEAR_K_N,
                     NORMAL_LUDING_INCREMENTAL_DELT_P_MAX, NORMAL_LUDING_INCREMENTAL_DELT_P_NULL,
                     NORMAL_LUDING_INCREMENTAL_K1, NORMAL_LUDING_INCREMENTAL_KP, NORMAL_LUDING_PEAK_D_LIM,
                     NORMAL_LUDING_PEAK_K1, NORMAL_LUDING_PEAK_K2_MAX, NORMAL_STRONGE_ALPHA_Y,
                     NORMAL_STRONGE_E_STAR, NORMAL_STRONGE_F_Y, NORMAL_THORNTON_ALPHA_Y,
                     NORMAL_THORNTON_E_STAR, NORMAL_THORNTON_F_Y, NORMAL_THORNTON_NING_A_Y,
                     NORMAL_THORNTON_NING_E_STAR, NORMAL_THORNTON_P_Y, NORMAL_WALTON_BRAUN_K1,
                     NORMAL_WALTON_BRAUN_K2, TANGENTIAL_CONTACT_RADIUS_SPRING_K, TANGENTIAL_LINEAR_K_T,
                     TANGENTIAL_MINDLIN_DERESIEWICZ_G, TANGENTIAL_MINDLIN_FORCE_RESCALE_G,
                     TANGENTIAL_MINDLIN_INCREMENTAL_G, TANGENTIAL_MINDLIN_RESCALE_G,
                     TANGENTIAL_MINDLIN_TOTAL_G, TANGENTIAL_MINDLIN_TOTAL_RESCALE_G,
                     TANGENTIAL_MINDLIN_UNLOADING_G, TANGENTIAL_VISCOUS_LINEAR_K_T,
                     TANGENTIAL_VISCOUS_MINDLIN_G, TANGENTIAL_WALTON_BRAUN_K_T0)  # noqa: F401

N_NORMAL = 8
NORMAL_LINEAR = 0
NORMAL_HERTZ = 1
NORMAL_WALTON_BRAUN = 2
NORMAL_THORNTON = 3
NORMAL_STRONGE = 4
NORMAL_LUDING_PEAK = 5
NORMAL_THORNTON_NING = 6
NORMAL_LUDING_INCREMENTAL = 7
NORMAL_ADAPTIVE = np.array([True, True, True, True, True, False, False, False], dtype=np.bool_)
END_TENSION = 0
END_NO_TENSION = 1
END_PULLS = np.array([True, False], dtype=np.bool_)
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
TANGENTIAL_ADAPTIVE = np.array([True, True, True, True, True, False, True, False, False, False, False, False, False],
                                dtype=np.bool_)
TANGENTIAL_VISCOUS = np.array([False, False, False, False, False, False, False, True, True, False, False, False,
                               False], dtype=np.bool_)
TANGENTIAL_IMPLICIT = np.array([False, False, False, False, False, False, True, False, False, False, False, False,
                                False], dtype=np.bool_)
TANGENTIAL_LOG_RATE = np.array([0, 0, 0, 1, 2, 0, 0, 0, 0, 0, 0, 0, 0], dtype=np.int64)
INTEGRATOR_PAPER = 0
INTEGRATOR_VELOCITY_VERLET = 1
INTEGRATOR_LEAPFROG = 2
INTEGRATOR_EXPLICIT = np.array([False, True, True], dtype=np.bool_)
INTEGRATOR_EVENTS = np.array([True, False, False], dtype=np.bool_)
INTEGRATOR_ADAPTIVE = np.array([True, False, False], dtype=np.bool_)
COULOMB_SPRING = 0
COULOMB_TOTAL = 1
COULOMB_TOTAL_CASES = 2
COULOMB_SPRING_FIRST = 3
GEOMETRY_WALL = 0
GEOMETRY_STAND_IN_SPHERE = 1
GEOMETRY_PAIR = 2
GEOMETRY_PAIR_VECTOR = 3
GEOMETRY_TWO_SPHERES = np.array([False, False, True, True], dtype=np.bool_)
GEOMETRY_ADAPTIVE = np.array([True, False, False, False], dtype=np.bool_)
TOUCH_GAP = 0
TOUCH_OVERLAP = 1
NORMAL_HISTORY = 3
NORMAL_RESET = np.array([[0.0, 0.0, 0.0], [0.0, 0.0, 0.0], [0.0, 0.0, 0.0], [0.0, 0.0, 0.0], [0.0, 0.0, 0.0],
                         [0.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 0.0, 0.0]], dtype=np.float64)
NORMAL_INCREMENTAL = (6, 7)
TANGENTIAL_ANY_IMPLICIT = True   # numba drops the implicit stepper where False


@compiled
def normal_force(code, p, radius, alpha, alpha_max, ext):
    if code == 0:
        return normal_linear.force(p[NORMAL_LINEAR_K_N], radius, alpha, alpha_max)
    if code == 1:
        return normal_hertz.force(p[NORMAL_HERTZ_E_STAR], radius, alpha, alpha_max)
    if code == 2:
        return normal_walton_braun.force(p[NORMAL_WALTON_BRAUN_K1], p[NORMAL_WALTON_BRAUN_K2], radius, alpha,
                                         alpha_max)
    if code == 3:
        return normal_thornton.force(p[NORMAL_THORNTON_E_STAR], p[NORMAL_THORNTON_P_Y], p[NORMAL_THORNTON_ALPHA_Y],
                                     p[NORMAL_THORNTON_F_Y], radius, alpha, alpha_max)
    if code == 4:
        return normal_stronge.force(p[NORMAL_STRONGE_E_STAR], p[NORMAL_STRONGE_ALPHA_Y], p[NORMAL_STRONGE_F_Y], radius,
                                    alpha, alpha_max)
    if code == 5:
        return normal_luding_peak.force(p[NORMAL_LUDING_PEAK_K1], p[NORMAL_LUDING_PEAK_K2_MAX],
                                        p[NORMAL_LUDING_PEAK_D_LIM], radius, alpha, alpha_max)
    if code >= N_NORMAL:
        return call(ext, code - N_NORMAL, FORCE, p[NORMAL_BLOCK:NORMAL_BLOCK_END], radius, alpha, alpha_max, 0.0, 0.0)
    return math.nan, math.nan


@compiled
def normal_below(code, p, alpha, ext):
    if code == 0:
        return normal_linear.below(p[NORMAL_LINEAR_K_N], alpha)
    if code >= N_NORMAL:
        return call(ext, code - N_NORMAL, BELOW, p[NORMAL_BLOCK:NORMAL_BLOCK_END], 0.0, alpha, 0.0, 0.0, 0.0)[0]
    return 0.0


@compiled
def normal_slope(code, p, radius, alpha, loading, f, a, ext):
    if code == 0:
        return normal_linear.slope(p[NORMAL_LINEAR_K_N], radius, alpha, loading, f, a)
    if code == 1:
        return normal_hertz.slope(p[NORMAL_HERTZ_E_STAR], radius, alpha, loading, f, a)
    if code == 2:
        return normal_walton_braun.slope(p[NORMAL_WALTON_BRAUN_K1], p[NORMAL_WALTON_BRAUN_K2], radius, alpha, loading,
                                         f, a)
    if code == 3:
        return normal_thornton.slope(p[NORMAL_THORNTON_E_STAR], p[NORMAL_THORNTON_P_Y], p[NORMAL_THORNTON_ALPHA_Y],
                                     p[NORMAL_THORNTON_F_Y], radius, alpha, loading, f, a)
    if code == 4:
        return normal_stronge.slope(p[NORMAL_STRONGE_E_STAR], p[NORMAL_STRONGE_ALPHA_Y], p[NORMAL_STRONGE_F_Y], radius,
                                    alpha, loading, f, a)
    if code >= N_NORMAL:
        return call(ext, code - N_NORMAL, SLOPE, p[NORMAL_BLOCK:NORMAL_BLOCK_END], radius, alpha,
                    1.0 if loading else 0.0, f, a)
    return math.nan, math.nan


@compiled
def normal_residual(code, p, radius, alpha_max, ext):
    if code == 2:
        return normal_walton_braun.residual(p[NORMAL_WALTON_BRAUN_K1], p[NORMAL_WALTON_BRAUN_K2], radius, alpha_max)
    if code == 3:
        return normal_thornton.residual(p[NORMAL_THORNTON_E_STAR], p[NORMAL_THORNTON_P_Y], p[NORMAL_THORNTON_ALPHA_Y],
                                        p[NORMAL_THORNTON_F_Y], radius, alpha_max)
    if code == 4:
        return normal_stronge.residual(p[NORMAL_STRONGE_E_STAR], p[NORMAL_STRONGE_ALPHA_Y], p[NORMAL_STRONGE_F_Y],
                                       radius, alpha_max)
    if code >= N_NORMAL:
        return call(ext, code - N_NORMAL, RESIDUAL, p[NORMAL_BLOCK:NORMAL_BLOCK_END], radius, 0.0, alpha_max, 0.0,
                       0.0)[0]
    return 0.0


@compiled
def normal_kink(code, p, ext):
    if code == 3:
        return normal_thornton.kink(p[NORMAL_THORNTON_E_STAR], p[NORMAL_THORNTON_P_Y], p[NORMAL_THORNTON_ALPHA_Y],
                                    p[NORMAL_THORNTON_F_Y])
    if code == 4:
        return normal_stronge.kink(p[NORMAL_STRONGE_E_STAR], p[NORMAL_STRONGE_ALPHA_Y], p[NORMAL_STRONGE_F_Y])
    if code == 5:
        return normal_luding_peak.kink(p[NORMAL_LUDING_PEAK_K1], p[NORMAL_LUDING_PEAK_K2_MAX],
                                       p[NORMAL_LUDING_PEAK_D_LIM])
    if code >= N_NORMAL:
        return call(ext, code - N_NORMAL, KINK, p[NORMAL_BLOCK:NORMAL_BLOCK_END], 0.0, 0.0, 0.0, 0.0, 0.0)[0]
    return 0.0


@compiled
def normal_step(code, p, radius, alpha, alpha_old, f_old, alpha_max, history, new_history, ext):
    if code == 6:
        return normal_thornton_ning.step(p[NORMAL_THORNTON_NING_E_STAR], p[NORMAL_THORNTON_NING_A_Y], radius, alpha,
                                         alpha_old, f_old, alpha_max, history, new_history)
    if code == 7:
        return normal_luding_incremental.step(p[NORMAL_LUDING_INCREMENTAL_K1], p[NORMAL_LUDING_INCREMENTAL_KP],
                                              p[NORMAL_LUDING_INCREMENTAL_DELT_P_MAX],
                                              p[NORMAL_LUDING_INCREMENTAL_DELT_P_NULL], radius, alpha, alpha_old,
                                              f_old, alpha_max, history, new_history)
    return normal_force(code, p, radius, alpha, alpha_max, ext)


@compiled
def end_clip(code, p, f_n):
    if code == 0:
        return end_tension.clip(f_n)
    if code == 1:
        return end_no_tension.clip(f_n)
    return math.nan


@compiled
def tangential_stiffness(code, p, a):
    if code == 1:
        return tangential_linear.stiffness(p[TANGENTIAL_LINEAR_K_T], a)
    if code == 2:
        return tangential_mindlin_incremental.stiffness(p[TANGENTIAL_MINDLIN_INCREMENTAL_G], a)
    if code == 3:
        return tangential_mindlin_rescale.stiffness(p[TANGENTIAL_MINDLIN_RESCALE_G], a)
    if code == 4:
        return tangential_mindlin_total.stiffness(p[TANGENTIAL_MINDLIN_TOTAL_G], a)
    if code == 5:
        return tangential_mindlin_deresiewicz.stiffness(p[TANGENTIAL_MINDLIN_DERESIEWICZ_G], a)
    if code == 6:
        return tangential_walton_braun.stiffness(p[TANGENTIAL_WALTON_BRAUN_K_T0], a)
    if code == 7:
        return tangential_viscous_linear.stiffness(p[TANGENTIAL_VISCOUS_LINEAR_K_T], a)
    if code == 8:
        return tangential_viscous_mindlin.stiffness(p[TANGENTIAL_VISCOUS_MINDLIN_G], a)
    if code == 9:
        return tangential_mindlin_total_rescale.stiffness(p[TANGENTIAL_MINDLIN_TOTAL_RESCALE_G], a)
    if code == 10:
        return tangential_mindlin_force_rescale.stiffness(p[TANGENTIAL_MINDLIN_FORCE_RESCALE_G], a)
    if code == 11:
        return tangential_contact_radius_spring.stiffness(p[TANGENTIAL_CONTACT_RADIUS_SPRING_K], a)
    if code == 12:
        return tangential_mindlin_unloading.stiffness(p[TANGENTIAL_MINDLIN_UNLOADING_G], a)
    return math.nan


@compiled
def tangential_spring(code, p, f_s, dd, a_mid, a, a_old, mu, n_new, n_old, st, scratch, midpoint):
    if code == 1:
        return tangential_linear.spring(p[TANGENTIAL_LINEAR_K_T], f_s, dd, a_mid, a, a_old, mu, n_new, n_old, st,
                                        scratch, midpoint)
    if code == 2:
        return tangential_mindlin_incremental.spring(p[TANGENTIAL_MINDLIN_INCREMENTAL_G], f_s, dd, a_mid, a, a_old, mu,
                                                     n_new, n_old, st, scratch, midpoint)
    if code == 3:
        return tangential_mindlin_rescale.spring(p[TANGENTIAL_MINDLIN_RESCALE_G], f_s, dd, a_mid, a, a_old, mu, n_new,
                                                 n_old, st, scratch, midpoint)
    if code == 4:
        return tangential_mindlin_total.spring(p[TANGENTIAL_MINDLIN_TOTAL_G], f_s, dd, a_mid, a, a_old, mu, n_new,
                                               n_old, st, scratch, midpoint)
    if code == 5:
        return tangential_mindlin_deresiewicz.spring(p[TANGENTIAL_MINDLIN_DERESIEWICZ_G], f_s, dd, a_mid, a, a_old, mu,
                                                     n_new, n_old, st, scratch, midpoint)
    if code == 6:
        return tangential_walton_braun.spring(p[TANGENTIAL_WALTON_BRAUN_K_T0], f_s, dd, a_mid, a, a_old, mu, n_new,
                                              n_old, st, scratch, midpoint)
    if code == 9:
        return tangential_mindlin_total_rescale.spring(p[TANGENTIAL_MINDLIN_TOTAL_RESCALE_G], f_s, dd, a_mid, a, a_old,
                                                       mu, n_new, n_old, st, scratch, midpoint)
    if code == 10:
        return tangential_mindlin_force_rescale.spring(p[TANGENTIAL_MINDLIN_FORCE_RESCALE_G], f_s, dd, a_mid, a, a_old,
                                                       mu, n_new, n_old, st, scratch, midpoint)
    if code == 11:
        return tangential_contact_radius_spring.spring(p[TANGENTIAL_CONTACT_RADIUS_SPRING_K], f_s, dd, a_mid, a, a_old,
                                                       mu, n_new, n_old, st, scratch, midpoint)
    if code == 12:
        return tangential_mindlin_unloading.spring(p[TANGENTIAL_MINDLIN_UNLOADING_G], f_s, dd, a_mid, a, a_old, mu,
                                                   n_new, n_old, st, scratch, midpoint)
    return math.nan


@compiled
def tangential_after_cap(code, p, f_s, a, st):
    if code == 4:
        tangential_mindlin_total.after_cap(p[TANGENTIAL_MINDLIN_TOTAL_G], f_s, a, st)
        return
    if code == 9:
        tangential_mindlin_total_rescale.after_cap(p[TANGENTIAL_MINDLIN_TOTAL_RESCALE_G], f_s, a, st)
        return
    if code == 11:
        tangential_contact_radius_spring.after_cap(p[TANGENTIAL_CONTACT_RADIUS_SPRING_K], f_s, a, st)
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
def tangential_onset_w(code, p, v_s, rise):
    if code == 6:
        return tangential_walton_braun.onset_w(p[TANGENTIAL_WALTON_BRAUN_K_T0], v_s, rise)
    return math.nan


@compiled
def coulomb_cap(code, p, f_s, damping, k_t, slip, limit):
    if code == 0:
        return coulomb_spring.cap(f_s, damping, k_t, slip, limit)
    if code == 1:
        return coulomb_total.cap(f_s, damping, k_t, slip, limit)
    if code == 2:
        return coulomb_total_cases.cap(f_s, damping, k_t, slip, limit)
    if code == 3:
        return coulomb_spring_first.cap(f_s, damping, k_t, slip, limit)
    return math.nan, math.nan, False


@compiled
def coulomb_first_touch(code, p, f_d, limit):
    if code == 1:
        return coulomb_total.first_touch(f_d, limit)
    if code == 2:
        return coulomb_total_cases.first_touch(f_d, limit)
    if code == 3:
        return coulomb_spring_first.first_touch(f_d, limit)
    return f_d


@compiled
def touch_contact(code, p, alpha):
    if code == 0:
        return touch_gap.contact(alpha)
    if code == 1:
        return touch_overlap.contact(alpha)
    return False
