"""Analyses of a results table: agreement, deviation, attribution, findings, invariants, sliding, cost."""
