"""Campaigns: a TOML matrix of comparisons expanded into the run plan, executed in-process or on Dask, each task
stored once in a content-addressed Parquet store (docs/campaigns.md)."""
