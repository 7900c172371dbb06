"""The reference solver: compiled integrators of the contact laws, their plans and their results."""
from ..infra.jit import compiled  # noqa: F401  (numba's cache directory is chosen before anything is compiled)
