"""Changes of regime located inside their step (paper scheme): the turn, the yield kink, the start and end of sliding
and the release, each by Illinois false position on the step fraction, and the step split there."""
from numba import njit

from ..infra.jit import compiled
from ..submodels.tangential.state import T_HELD, T_MARGIN, T_STEP
from . import layout as L
from .dispatch import END_PULLS, TANGENTIAL_IMPLICIT, TANGENTIAL_NONE, TANGENTIAL_VISCOUS
from .schemes import loading_kink, step_paper
from .state import S_ALPHA, S_AMAX, S_FN, S_VZ

RELEASE_ITERATIONS = 100
EVENT_NONE, EVENT_TURN, EVENT_SLIP, EVENT_STICK, EVENT_YIELD, EVENT_SATURATE = 0, 1, 2, 3, 4, 5
EVENT_ITERATIONS = 60


@njit(cache=True, inline="always")
def event_kind(s, st, o, ot, p, ints, ext):
    """A change of regime inside the step (paper scheme): the normal motion turns (alpha_dot through 0), the loading
    curve's kink is passed (yield), the contact starts to slide (trial spring force reaches mu F_n) or stops sliding
    (the spring leaves the Coulomb cone)."""
    if s[S_VZ] < 0.0 <= o[S_VZ] and s[S_ALPHA] > 0.0:
        return EVENT_TURN
    kink = loading_kink(p, ints, ext)
    if s[S_ALPHA] < kink <= o[S_ALPHA] and s[S_ALPHA] >= s[S_AMAX]:
        return EVENT_YIELD
    code = ints[L.I_TANGENTIAL]
    if code == TANGENTIAL_NONE or TANGENTIAL_VISCOUS[code] or s[S_FN] <= 0.0 or o[S_FN] <= 0.0:
        return EVENT_NONE
    if TANGENTIAL_IMPLICIT[code]:             # a stiff spring (k_t -> 0 at full mobilisation) meets mu F_n
        return EVENT_NONE                     # tangentially, and locating that only amplifies round-off
    if st[T_HELD] < 0.0 < ot[T_HELD] and p[L.TANGENTIAL_DAMPING_PREFACTOR] != 0.0:   # spring and dashpot reach the cone
        return EVENT_SATURATE
    if st[T_MARGIN] < 0.0 < ot[T_MARGIN]:
        return EVENT_SLIP
    if st[T_HELD] > 0.0 >= ot[T_HELD]:
        return EVENT_STICK
    if st[T_STEP] > 0.0 and ot[T_STEP] > 0.0:      # still sliding at the step's end, but the margin per unit time
        rate, rate_before = ot[T_HELD] / ot[T_STEP], st[T_HELD] / st[T_STEP]       # falls fast: it may stick inside
        if 0.0 < rate < 2.0 * (rate_before - rate):
            return EVENT_STICK
    return EVENT_NONE


STICK_PROBE = 1e-4          # step fraction of the probe step that tells whether a contact on the cone still slides


@compiled
def event_value(kind, f, s, st, lo, lot, probe, probe_t, p, ints, h, scratch, ext):
    """The quantity that rises through zero at the event, after a trial step of fraction f from (s, st) (into lo, lot):
    -alpha_dot at the turn; alpha - alpha_y at yield; the trial spring margin |F_s| - mu F_n where sliding starts;
    where sliding stops, minus the margin's rate for a contact that starts on the Coulomb cone at f (a short probe
    step from there, into probe, probe_t): the spring leaves the cone when it moves inward faster than mu F_n
    shrinks, at a slip reversal only when F_n is constant."""
    if kind == EVENT_TURN or kind == EVENT_YIELD:
        at = s
        if f > 0.0:
            step_paper(s, st, lo, lot, p, ints, f * h, scratch, ext)
            at = lo
        return at[S_VZ] if kind == EVENT_TURN else at[S_ALPHA] - loading_kink(p, ints, ext)
    if kind == EVENT_SLIP or kind == EVENT_SATURATE:
        which = T_MARGIN if kind == EVENT_SLIP else T_HELD
        return st[which] if f == 0.0 else margin_at(f, s, st, lo, lot, p, ints, h, scratch, which, ext)
    if f == 0.0:
        step_paper(s, st, probe, probe_t, p, ints, STICK_PROBE * h, scratch, ext)
    else:
        step_paper(s, st, lo, lot, p, ints, f * h, scratch, ext)
        step_paper(lo, lot, probe, probe_t, p, ints, STICK_PROBE * h, scratch, ext)
    return -probe_t[T_HELD] / STICK_PROBE


@compiled
def margin_at(f, s, st, lo, lot, p, ints, h, scratch, which, ext):
    """The margin `which` (T_MARGIN: |F_s| - mu F_n; T_HELD: what holds the cone) after a trial step of fraction
    f > 0 (at f = 0 the start's own margin holds: a step of length 0 would end the contact at first touch, where a
    constant dashpot already pushes)."""
    step_paper(s, st, lo, lot, p, ints, f * h, scratch, ext)
    return lot[which]


@compiled
def locate_event(kind, s, st, lo, lot, probe, probe_t, p, ints, h, scratch, ext):
    """Step fraction at which the event happens in the step from (s, st) (Illinois false position on the event
    value, trial steps in lo, lot and probe, probe_t); -1 if the value does not change sign over the step."""
    g_lo = event_value(kind, 0.0, s, st, lo, lot, probe, probe_t, p, ints, h, scratch, ext)
    g_hi = event_value(kind, 1.0, s, st, lo, lot, probe, probe_t, p, ints, h, scratch, ext)
    if not (g_lo < 0.0 < g_hi):
        return -1.0
    lo_f, hi_f, side = 0.0, 1.0, 0
    for _ in range(EVENT_ITERATIONS):
        if hi_f - lo_f <= 1e-14:
            break
        mid = (lo_f * g_hi - hi_f * g_lo) / (g_hi - g_lo) if g_hi > g_lo else 0.5 * (lo_f + hi_f)
        if not lo_f < mid < hi_f:
            mid = 0.5 * (lo_f + hi_f)
        g_mid = event_value(kind, mid, s, st, lo, lot, probe, probe_t, p, ints, h, scratch, ext)
        lo_f, hi_f, g_lo, g_hi, side = illinois(lo_f, hi_f, g_lo, g_hi, side, mid, g_mid, g_mid < 0.0)
    return hi_f


@njit(cache=True, inline="always")
def illinois(lo_f, hi_f, g_lo, g_hi, side, mid, g_mid, on_low_side):
    """One Illinois false-position update of the bracket [lo_f, hi_f] with values g_lo, g_hi: the new point
    replaces the end on its side, and the other end's value is halved when it was kept twice in a row."""
    if on_low_side:
        lo_f, g_lo = mid, g_mid
        if side == 1:
            g_hi *= 0.5
        return lo_f, hi_f, g_lo, g_hi, 1
    hi_f, g_hi = mid, g_mid
    if side == -1:
        g_lo *= 0.5
    return lo_f, hi_f, g_lo, g_hi, -1


@compiled
def locate_release(s, st, lo, lot, p, ints, h, scratch, indicator, ext):
    """Step fraction of the release (alpha = 0, or F = 0 without tension) in the step from (s, st) whose end value is
    `indicator` <= 0: Illinois false position; the fraction returned still has contact."""
    frac_lo, frac_hi = 0.0, 1.0
    g_lo, g_hi = s[S_ALPHA] if s[S_ALPHA] > 0.0 else 1.0, indicator
    if not END_PULLS[ints[L.I_END]]:
        g_lo = min(s[S_FN], s[S_ALPHA]) if s[S_ALPHA] > 0.0 else s[S_FN]
    side = 0
    for _ in range(RELEASE_ITERATIONS):
        if frac_hi - frac_lo <= 1e-15:
            break
        mid = (frac_lo * g_hi - frac_hi * g_lo) / (g_hi - g_lo) if g_lo > 0.0 > g_hi else 0.5 * (frac_lo + frac_hi)
        if not frac_lo < mid < frac_hi:
            mid = 0.5 * (frac_lo + frac_hi)
        g_mid = step_paper(s, st, lo, lot, p, ints, mid * h, scratch, ext)
        frac_lo, frac_hi, g_lo, g_hi, side = illinois(frac_lo, frac_hi, g_lo, g_hi, side, mid, g_mid, g_mid > 0.0)
    return frac_lo


@compiled
def split_at_event(s, st, o, ot, lo, lot, at_event, at_event_t, p, ints, h, scratch, a_peak, f_peak, h_full,
                   indicator, ext):
    """Redo the step (s, st) -> (o, ot) of length h in two at a change of regime inside it, so that the error stays
    smooth in h. A step that ended at the release (h < h_full) is continued from the event to the release again,
    within what is left of h_full. Returns alpha_max and F_max (found at a turn), the end indicator (`indicator`
    if nothing happened) and the time the step took."""
    kind = event_kind(s, st, o, ot, p, ints, ext)
    if kind == EVENT_NONE:
        return a_peak, f_peak, indicator, h
    frac = locate_event(kind, s, st, lo, lot, at_event, at_event_t, p, ints, h, scratch, ext)
    if not 0.0 < frac < 1.0:
        return a_peak, f_peak, indicator, h
    step_paper(s, st, at_event, at_event_t, p, ints, frac * h, scratch, ext)
    if kind == EVENT_TURN:                  # alpha_max itself; F_max too when undamped
        a_peak = max(a_peak, at_event[S_ALPHA])
        if p[L.DAMPING_C0] == 0.0:
            f_peak = max(f_peak, at_event[S_FN])
    rest = h_full - frac * h
    indicator = step_paper(at_event, at_event_t, o, ot, p, ints, rest, scratch, ext)
    if h < h_full and indicator <= 0.0:
        rest *= locate_release(at_event, at_event_t, lo, lot, p, ints, rest, scratch, indicator, ext)
        step_paper(at_event, at_event_t, o, ot, p, ints, rest, scratch, ext)
    return a_peak, f_peak, indicator, frac * h + rest
