"""Sub-models, one module each: its calibration, its parameters and its compiled kernel (registry.py numbers them)."""
from ..infra.jit import compiled  # noqa: F401  (numba's cache directory is chosen before anything is compiled)
