"""The cores this process may use (its CPU affinity): how many threads or processes harness runs at once."""
import os

CORES = len(os.sched_getaffinity(0))
