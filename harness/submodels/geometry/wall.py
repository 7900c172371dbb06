"""Geometry 'wall': a sphere against a flat wall."""
NAME = "wall"
SUMMARY = "a sphere against a flat wall: the normal fixed, scalar shear"
SLOTS = ()
ADAPTIVE = True             # the adaptive integrator's contact ODE is this geometry's
