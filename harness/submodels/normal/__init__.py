"""Normal sub-models: the elastic or plastic part of F_n (damping is separate: submodels/damping)."""
