"""The graded mesh of the converged ladder (steps that shrink like s^3 at both ends of the contact) and the
interpolated peak of F_n from its last samples."""
from ..infra.jit import compiled

PEAK_POINTS = 5           # samples of F_n through which its peak is interpolated (paper scheme)


GRADE_ZONE = 0.1            # share of the graded steps spent at each end of [0, T]
RAMP_AREA = 4.0 / 7.0      # integral of the ramp over [0, 1]


@compiled
def ramp_integral(x):
    """Integral of the step-size ramp x^3 (20 - 45 x + 36 x^2 - 10 x^3), which rises from 0 like x^3 and meets 1 with
    three vanishing derivatives."""
    return x ** 4 * (5.0 + x * (-9.0 + x * (6.0 - x * (10.0 / 7.0))))


@compiled
def graded_time(s):
    """Time fraction Phi(s) of the graded mesh at uniform s in [0, 1]: Phi ~ s^4 at both ends, so that alpha^(1/4),
    alpha^(1/2) and alpha^(3/2) at first touch and at release become smooth in s and the error expands in powers
    of the step (Richardson), uniform in the middle."""
    q = GRADE_ZONE
    total = 1.0 - 2.0 * q + 2.0 * q * RAMP_AREA
    if s <= q:
        g = q * ramp_integral(s / q)
    elif s >= 1.0 - q:
        g = total - q * ramp_integral((1.0 - s) / q)
    else:
        g = q * RAMP_AREA + (s - q)
    return g / total


def graded_largest_step(n, span):
    """The largest of n graded steps over span: the uniform middle step, span / (n (1 - 2 q (1 - RAMP_AREA)))."""
    return span / (n * (1.0 - 2.0 * GRADE_ZONE * (1.0 - RAMP_AREA)))


@compiled
def graded_step(k, n, span):
    """Step k of n graded steps over [0, span]; beyond the span (a release later than foreseen), uniform span/n."""
    if k >= n:
        return span / n
    if 2 * k < n:
        return span * (graded_time((k + 1.0) / n) - graded_time(k / n))
    return span * (graded_time((n - k) / n) - graded_time((n - k - 1.0) / n))   # mirrored: no cancellation near 1


@compiled
def parabola_peak(y0, y1, y2, h1, h2):
    """Peak of the parabola through (-h1, y0), (0, y1), (h2, y2) with y1 the largest sample."""
    c = ((y0 - y1) / h1 + (y2 - y1) / h2) / (h1 + h2)
    if c >= 0.0:
        return y1
    b = (y2 - y1) / h2 - c * h2
    return y1 - b * b / (4.0 * c)


@compiled
def newton_value(coef, x, u):
    """Value and slope at u of the Newton-form polynomial with nodes x and divided differences coef."""
    value, slope = coef[len(coef) - 1], 0.0
    for i in range(len(coef) - 2, -1, -1):
        slope = slope * (u - x[i]) + value
        value = value * (u - x[i]) + coef[i]
    return value, slope


@compiled
def polynomial_peak(times, values, x, coef):
    """Largest value of the polynomial through the samples (times, values), the second newest sample being the
    largest, between the third newest and the newest: O(h^5) where the parabola's error, O(h^3) with a phase that
    jumps with h, would spoil the extrapolation of F_max. x and coef: work arrays of the samples' length."""
    m = len(times)
    for i in range(m):
        x[i] = times[i] - times[m - 2]
        coef[i] = values[i]
    for j in range(1, m):
        for i in range(m - 1, j - 1, -1):
            coef[i] = (coef[i] - coef[i - 1]) / (x[i] - x[i - j])
    lo, hi = x[m - 3], x[m - 1]
    slope_lo = newton_value(coef, x, lo)[1]
    if not (slope_lo > 0.0 and newton_value(coef, x, hi)[1] < 0.0):
        return values[m - 2]
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        if newton_value(coef, x, mid)[1] > 0.0:
            lo = mid
        else:
            hi = mid
    return max(values[m - 2], newton_value(coef, x, 0.5 * (lo + hi))[0])
