"""harness: cross-validation of DEM contact force models (Thornton, Cummins & Cleary 2013)."""

__version__ = "0.1.0"
