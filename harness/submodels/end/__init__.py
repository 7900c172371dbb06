"""End-of-contact rules: whether the normal force may pull (`clip(f_n)`), and so whether a contact ends where the
overlap or the force returns to 0 (PULLS)."""
