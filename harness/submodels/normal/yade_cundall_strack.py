"""YADE FrictPhys against a wall: K_n = E R (an engine dialect's normal law, docs/yade-dialect.md)."""
import math

from ..base import NormalParameters
from .linear import LinearSpring


class CundallStrackSpring(LinearSpring):
    """YADE FrictPhys against a wall (default geometry, wall radius R): K_n = 2 E R E R/(E R + E R) = E R, with E
    Young's modulus, whatever the impact speed; runs on the linear spring's kernel."""
    name = "yade-cundall-strack"

    def label(self):
        return self.name

    def parameters(self, contact, e_n, speed):
        k = contact.E * contact.radius
        return NormalParameters((k, 0.0, 0.0, 0.0), k, math.pi * math.sqrt(contact.mass / k))
