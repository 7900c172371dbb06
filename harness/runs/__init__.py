"""A request made runs: the request, its plan, executing it, which engines can take it, the store of a results
directory and the comparison built from it."""
