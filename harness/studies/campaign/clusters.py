"""The Dask clusters a campaign runs on. Dask unpickles whatever a client submits, so reaching a scheduler is running
code on its workers: every cluster harness starts speaks TLS only, with credentials made for this run (a client
without them is refused), binds the loopback address unless remote workers must reach it, serves no HTTP, and keeps
its scratch in a private directory of its own that is removed when it closes. An existing scheduler is reached
within a deadline, or the campaign says it could not be."""
import asyncio
import json
import os
import shutil
import tempfile

from ...infra.errors import UserError
from .limits import CONNECT_TIMEOUT_S, MAX_FILE_BYTES
from .reading import read_regular

NO_HTTP = "harness.studies.campaign.no_http"        # the preload that closes each process' HTTP listener
# A scheduler opens an HTTP listener whatever it is told, on port 8787 of every interface by default (and warns on
# stderr when that is taken): here on a free loopback port, without a dashboard, closed at once by NO_HTTP.
SCHEDULER = {"dashboard": False, "dashboard_address": "127.0.0.1:0", "preload": [NO_HTTP]}
PROTOCOLS = ("tcp", "tls")


class Unavailable(Exception):
    """A resource the campaign needs is missing or unreachable (no sbatch, no scheduler): one line, exit 3."""


def scratch_directory(what):
    """A private directory (mode 0700) for a cluster's scratch, named so that one left by a killed harness is
    removed by the next (harness.engines.runner.sweep_stale)."""
    return tempfile.mkdtemp(prefix=f"harness-{os.getpid()}-{what}-")


def dask_settings(scratch):
    """Dask's settings for a cluster harness starts: its scratch (and the directory Dask puts on a worker's
    sys.path) in `scratch`, and no HTTP routes, so the listener no_http closes serves nothing meanwhile."""
    return {"temporary-directory": scratch, "distributed.scheduler.http.routes": [],
            "distributed.worker.http.routes": []}


def local_cluster(workers, scratch):
    """Worker processes on this machine, one thread each, on the loopback address, TLS with this run's
    credentials, no HTTP."""
    import dask
    from distributed import LocalCluster, Security
    with dask.config.set(dask_settings(scratch)):
        return LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, host="127.0.0.1",
                            protocol="tls://", security=Security.temporary(), dashboard_address=None,
                            scheduler_kwargs=SCHEDULER, preload=[NO_HTTP], local_directory=scratch)


def remove(directory):
    """Remove a directory harness made, whatever it holds."""
    shutil.rmtree(directory, ignore_errors=True)


def address_in(scheduler_file):
    """The scheduler's address in a Dask scheduler file (JSON with an `address`)."""
    text = read_regular(scheduler_file, "scheduler file", MAX_FILE_BYTES)
    try:
        address = json.loads(text).get("address")
    except (ValueError, AttributeError):
        address = None
    if not isinstance(address, str):
        raise UserError(f"scheduler file {scheduler_file} is not a Dask scheduler file (JSON with an address)")
    return address


def checked_address(address):
    """A scheduler address tcp://HOST:PORT or tls://HOST:PORT; UserError otherwise."""
    from distributed.comm.addressing import parse_address, parse_host_port
    try:
        protocol, location = parse_address(address, strict=True)
        parse_host_port(location)
    except (ValueError, TypeError):
        protocol = None
    if protocol not in PROTOCOLS or any(c.isspace() or not c.isprintable() for c in address):
        raise UserError(f"--scheduler must be tcp://HOST:PORT or tls://HOST:PORT, got {address!r}")
    return address


def connect(address):
    """A Client of the scheduler at `address`, with Dask's configured TLS credentials (if any); Unavailable when no
    scheduler answers within CONNECT_TIMEOUT_S."""
    from distributed import Client, Security
    address = checked_address(address)
    security = Security()
    try:
        asyncio.run(identify(address, security, CONNECT_TIMEOUT_S))
    except TypeError:
        raise UserError(f"scheduler {address} speaks TLS: give Dask its credentials (distributed.comm.tls.* in "
                        "Dask's configuration)") from None
    except (OSError, asyncio.TimeoutError) as exc:
        why = "no answer" if isinstance(exc, asyncio.TimeoutError) else str(exc).splitlines()[0] or "refused"
        raise Unavailable(f"no Dask scheduler answered at {address} within {CONNECT_TIMEOUT_S:g} s ({why})") from None
    return Client(address, security=security, timeout=CONNECT_TIMEOUT_S, set_as_default=False)


async def identify(address, security, timeout):
    """Ask the scheduler who it is, all within `timeout` seconds (a server that accepts and never answers too)."""
    from distributed.comm import connect as open_comm

    async def ask():
        comm = await open_comm(address, timeout=timeout, **security.get_connection_args("client"))
        try:
            await comm.write({"op": "identity", "reply": True})
            reply = await comm.read()
        finally:
            comm.abort()
        if not isinstance(reply, dict) or reply.get("type") != "Scheduler":
            raise OSError("what answered is not a Dask scheduler")
    await asyncio.wait_for(ask(), timeout)
