"""What runs plans of its own: calibration, the cost study, campaigns, the Chung & Ooi suite, the paper's figure set,
the baseline, explain and the hard cases."""
