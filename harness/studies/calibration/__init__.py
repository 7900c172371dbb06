"""Calibration: the engine inputs that make an engine compute the paper law as nearly as it can on a scene, found on
its dialect in the reference and confirmed by running the engine; and the time step that buys a stated accuracy
(docs/calibrate.md)."""
