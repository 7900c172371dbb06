"""Sub-models, one module each: its calibration, its parameters and its compiled kernel (registry.py numbers them)."""
