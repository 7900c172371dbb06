"""The names of the engines harness checks, in the registry's order (registry.py holds them to it): known without
importing an engine."""
EXTERNAL = ("liggghts", "yade", "lammps", "kratos")
