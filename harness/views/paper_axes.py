"""The paper's figure axes: Psi2*, Omega* and e_t against Psi1* on its ranges, grown to the data drawn (nothing is
hidden: a point far off gets a marker on the edge and a count), with the rigid-body lines and the published points."""
import numpy as np

from ..infra.wording import counted

PSI1_RANGE = (0.0, 14.0)                 # the paper's Psi1* axis
RIGID_ONSET = 7.0                        # a rigid sphere slides throughout from Psi1* = 7
PAPER_PANELS = (   # (column, axis label, y range as the paper draws it)
    ("psi2_star", "rebound slip Psi2*", (-5.0, 8.0)),
    ("omega_star", "rebound spin Omega*", (-6.0, 0.5)),
    ("e_t", "tangential restitution e_t", (-0.6, 1.05)),
)
X_LABEL = "impact angle Psi1*"
ANGLE_LABELS = ("impact angle from the normal [deg]", "rebound angle from the normal [deg]")


def rigid_body(column, psi1):
    """The rigid sphere without initial spin: rolling below Psi1* = 7 (Psi2* = 0, Omega* = -5/7 Psi1*, e_t = 5/7),
    sliding throughout above (Psi2* = Psi1* - 7, Omega* = -5, e_t = 1 - 2/Psi1*)."""
    psi1 = np.asarray(psi1, dtype=float)
    sliding = psi1 >= RIGID_ONSET
    with np.errstate(divide="ignore", invalid="ignore"):
        values = {"psi2_star": np.where(sliding, psi1 - RIGID_ONSET, 0.0),
                  "omega_star": np.where(sliding, -5.0, -5.0 / 7.0 * psi1),
                  "e_t": np.where(sliding, 1.0 - 2.0 / psi1, 5.0 / 7.0)}
    return values[column]


def draw_published(ax, points, colour, label=None):
    """The paper's published points of one curve (harness/data/digitised.py), open markers in the curve's colour."""
    ax.plot(points.psi1_star, points.value, ls="none", marker="o", ms=4, mfc="none", mew=1.0, color=colour,
            label=label, zorder=4, gid="published-points")


def draw_rigid_body(ax, column):
    """The rigid-body curve, grey dash-dotted, over the paper's Psi1* range."""
    x = np.linspace(PSI1_RANGE[0] + 1e-9, PSI1_RANGE[1], 400)
    ax.plot(x, rigid_body(column, x), color="0.55", ls="-.", lw=1.0, label="rigid body")


GROWTH = 3.0       # the y axis grows to the data up to this many of the paper's spans beyond either end of its range
PAD = 0.04         # of the axis' span, between the outermost point and the axis


def drawn_points(ax):
    """(x, y) of every line and marker drawn in data coordinates (lines like axvline's, in axes coordinates, left
    out)."""
    xs, ys = [np.empty(0)], [np.empty(0)]
    for line in ax.get_lines():
        if line.get_transform() is ax.transData:
            xs.append(np.asarray(line.get_xdata(), dtype=float))
            ys.append(np.asarray(line.get_ydata(), dtype=float))
    return np.concatenate(xs), np.concatenate(ys)


def set_paper_axes(ax, column, label, beyond_x=0):
    """The paper's x range and the column's y range, grown to every point drawn inside the x window; points beyond
    GROWTH spans get a marker on the axis' edge and a count, as do `beyond_x` rows past the x window (not drawn)."""
    ax.set_xlim(*PSI1_RANGE)
    ax.set_xlabel(X_LABEL)
    ax.set_ylabel(label)
    lo, hi = dict((c, r) for c, _, r in PAPER_PANELS)[column]
    x, y = drawn_points(ax)
    shown = np.isfinite(x) & np.isfinite(y) & (x >= PSI1_RANGE[0]) & (x <= PSI1_RANGE[1])
    x, y = x[shown], y[shown]
    span = hi - lo
    near = (y >= lo - GROWTH * span) & (y <= hi + GROWTH * span)
    if near.any():
        low, high = y[near].min(), y[near].max()
        margin = PAD * (max(hi, high) - min(lo, low))
        lo, hi = (low - margin if low < lo else lo), (high + margin if high > hi else hi)
    ax.set_ylim(lo, hi)
    far = ~near
    notes = []
    if far.any():
        ax.plot(x[far], np.where(y[far] < lo, lo, hi), ls="none", marker="d", ms=5, color="red", clip_on=False,
                zorder=5, gid="beyond-axis")
        notes.append(f"{int(far.sum())} beyond the axis (red: {y[far].min():.3g} to {y[far].max():.3g})")
    if beyond_x:
        notes.append(f"{counted(beyond_x, 'impact')} beyond Psi1* = {PSI1_RANGE[1]:g} not drawn")
    if notes:
        ax.text(0.02, 0.02, "; ".join(notes), transform=ax.transAxes, fontsize=6.5, va="bottom",
                color="red" if far.any() else "0.35")
    ax.grid(alpha=0.3)


def in_window(frame):
    """Rows whose Psi1* lies in the paper's window (grazing rows far beyond it would only flatten the curves)."""
    return frame[(frame.psi1_star > PSI1_RANGE[0]) & (frame.psi1_star <= PSI1_RANGE[1])]
