"""The paper's figure axes: Psi2*, Omega* and e_t against Psi1* on its ranges, with the rigid-body lines."""
import numpy as np

PSI1_RANGE = (0.0, 14.0)                 # the paper's Psi1* axis
RIGID_ONSET = 7.0                        # a rigid sphere slides throughout from Psi1* = 7
PANELS = (   # (column, axis label, y range as the paper draws it)
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


def draw_rigid_body(ax, column):
    """The rigid-body curve, grey dash-dotted, over the paper's Psi1* range."""
    x = np.linspace(PSI1_RANGE[0] + 1e-9, PSI1_RANGE[1], 400)
    ax.plot(x, rigid_body(column, x), color="0.55", ls="-.", lw=1.0, label="rigid body")


def set_paper_axes(ax, column, label):
    """The paper's x range and the column's y range; the y range widens only to show data inside the x window."""
    ax.set_xlim(*PSI1_RANGE)
    ax.set_xlabel(X_LABEL)
    ax.set_ylabel(label)
    ax.set_ylim(*dict((c, r) for c, _, r in PANELS)[column])
    ax.grid(alpha=0.3)


def in_window(frame):
    """Rows whose Psi1* lies in the paper's window (grazing rows far beyond it would only flatten the curves)."""
    return frame[(frame.psi1_star > PSI1_RANGE[0]) & (frame.psi1_star <= PSI1_RANGE[1])]
