"""Integrator 'velocity-verlet'."""
NAME = "velocity-verlet"
SUMMARY = "half kick, drift, forces from the half-step velocities, half kick; release at the step"
SLOTS = ()
EXPLICIT = True
