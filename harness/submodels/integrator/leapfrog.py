"""Integrator 'leapfrog'."""
NAME = "leapfrog"
SUMMARY = "forces at x(t) from v(t - h/2), then v(t + h/2), then x(t + h); contact while the overlap is >= 0"
SLOTS = ()
EXPLICIT = True
