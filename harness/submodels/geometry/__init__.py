"""Geometries: what moves and how the normal and the shear history follow. A geometry's slots are what its stepper
reads of the scene (`parameters(law, scene)` gives them); the stepper of each (integrator, geometry) pair is the
solver's (submodels/stepping.py)."""
