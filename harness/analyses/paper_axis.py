"""What the paper's figures are drawn over: its Psi1* axis and the name of its elastic curve (studies/paper.py
computes the set over them, views/paper_html.py draws it)."""
import numpy as np

PSI1_GRID = tuple(float(x) for x in np.round(np.r_[np.arange(0.05, 0.21, 0.05), np.arange(0.25, 14.0001, 0.25)], 6))
# the paper's Psi1* axis, from below its first published point (0.15)
ELASTIC = "hertz-mindlin (elastic)"        # e = 1, no dashpots: the elastic companion paper's reference curve
