"""The version of harness, in one place (the package, its metadata and every results row read it)."""
__version__ = "0.1.0"
