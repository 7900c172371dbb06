"""The limits a campaign, its cluster and `harness query` hold to, in one place so that each refusal and the docs
name the same number (docs/campaigns.md#limits)."""
import os

MAX_FILE_BYTES = 1 << 20          # a campaign file or a scheduler file: a few lines, never megabytes
MAX_LIST = 100_000                # items in one list of a campaign file
MAX_TASKS = 100_000               # tasks in one campaign: the dry run expands and keys each (about 0.5 ms a task)
MAX_SLURM_JOBS = 1000             # --slurm jobs
MAX_SLURM_CORES = 1024            # --slurm cores (and processes) per job
CONNECT_TIMEOUT_S = 30.0          # to reach an existing scheduler, and for sbatch to answer
MAX_QUERY_BYTES = 100_000         # the SQL text of `harness query`
MAX_ROWS = 100_000                # rows `harness query` prints
MAX_CELL_CHARS = 10_000           # characters of one printed value
MAX_RESULT_BYTES = 64 << 20       # bytes of the result `harness query` prints, as Arrow holds it
QUERY_MEMORY_MB = 512             # memory DuckDB may use for one query (its default is 80% of the machine's)
QUERY_GROWTH_MB = 1024            # address space the process may add while a query runs (DuckDB's limit
                                  # leaves out what a scalar function such as repeat() allocates)
MAX_QUERY_S = 120.0               # seconds one query may run


def max_workers():
    """LocalCluster worker processes at most: four per core this process may use."""
    return 4 * len(os.sched_getaffinity(0))
