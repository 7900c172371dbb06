"""Cundall & Strack's (1979) elastic linear spring against a wall of the sphere's own material: K_n = E R."""
import math

from ..base import NormalParameters
from .linear import LinearSpring


class CundallStrackSpring(LinearSpring):
    """Against a wall of reference radius R: K_n = 2 E R E R/(E R + E R) = E R, with E
    Young's modulus, whatever the impact speed; runs on the linear spring's kernel."""
    name = "cundall-strack"

    def label(self):
        return self.name

    def parameters(self, contact, e_n, speed):
        k = contact.E * contact.radius
        return NormalParameters.named(k, math.pi * math.sqrt(contact.mass / k), k_n=k)
