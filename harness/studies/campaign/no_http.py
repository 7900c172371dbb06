"""A Dask preload that closes the HTTP server every scheduler and worker opens on start (metrics and a dashboard
nobody asked for, not under TLS): a campaign's processes listen only on their TLS ports."""


def dask_setup(server):
    """Stop `server`'s HTTP listener (it has served nothing: harness starts Dask with no HTTP routes)."""
    http = getattr(server, "http_server", None)
    if http is not None:
        http.stop()
