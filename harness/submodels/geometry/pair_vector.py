"""Geometry 'pair-vector': two spheres in their relative motion, the shear a vector turned with the normal."""
from .pair import SLOTS, parameters  # noqa: F401  (the pair's bodies)

NAME = "pair-vector"
SUMMARY = "two spheres in their relative motion, the normal turning; the shear vector turned with the normal"
TWO_SPHERES = True
