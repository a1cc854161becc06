"""Reaching a Dask cluster: `local` starts one on this machine, an address joins a running one.
`distributed` is an optional extra (`pip install lagrade[dask]`), imported only here and only
when a run asks for a cluster, so that every other command starts without it."""

from __future__ import annotations

import importlib.util
import logging
import re
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

from lagrade.errors import ClusterError

#: What `--dask` takes besides `local`: a scheduler's address, `tcp://host:port` (or another of
#: Dask's protocols, `tls://…`).
ADDRESS = re.compile(r"[a-z][a-z0-9+.-]*://\S+")
#: Seconds to wait for a scheduler to answer, and for a joined cluster to have a worker.
CONNECT_SECONDS = 30.0
INSTALL = "pip install 'lagrade[dask]'"


def require(scheduler: str, jobs: int = 1) -> None:
    """Refuse, before any work, a `--dask` value no run could use: Dask's distributed scheduler
    not installed, an address of no protocol, or `jobs` given for a cluster someone else runs
    (its workers' threads say how many sheets it judges at once)."""
    if scheduler != "local" and not ADDRESS.fullmatch(scheduler):
        raise ClusterError(
            f"--dask takes 'local' or a scheduler's address such as tcp://10.0.0.5:8786, "
            f"not {scheduler!r}"
        )
    if scheduler != "local" and jobs > 1:
        raise ClusterError(
            "--jobs is for this machine or --dask local; a cluster's workers judge as many at "
            "once as they have threads (dask worker --nthreads N)"
        )
    if importlib.util.find_spec("distributed") is None:
        raise ClusterError(f"--dask needs Dask's distributed scheduler, not installed: {INSTALL}")


def _distributed() -> Any:
    try:
        import distributed
    except ImportError:
        raise ClusterError(
            f"--dask needs Dask's distributed scheduler, not installed: {INSTALL}"
        ) from None
    return distributed


@contextmanager
def connect(scheduler: str, workers: int = 1) -> Iterator[Any]:
    """A `distributed.Client` of the cluster `scheduler` names, closed on leaving: `local`
    starts `workers` Dask workers on this machine (one thread each, so `--jobs N` judges N
    sheets at once as it does without Dask), stopped on leaving; an address joins the cluster
    there, which must have a worker within CONNECT_SECONDS."""
    require(scheduler, workers if scheduler == "local" else 1)
    distributed = _distributed()
    cluster = None
    try:
        if scheduler == "local":
            cluster = distributed.LocalCluster(
                n_workers=workers,
                threads_per_worker=1,
                processes=True,
                dashboard_address=":0",
                silence_logs=logging.CRITICAL,  # its own errors come back with the chunks
            )
            address = cluster.scheduler_address
        else:
            address = scheduler
        try:
            client = distributed.Client(address, timeout=CONNECT_SECONDS)
        except (OSError, TimeoutError) as error:
            raise ClusterError(f"cannot reach the Dask scheduler at {address}: {error}") from None
        try:
            try:
                client.wait_for_workers(1, timeout=CONNECT_SECONDS)
            except TimeoutError:
                raise ClusterError(
                    f"the Dask scheduler at {address} has no worker "
                    f"(start some with: dask worker {address})"
                ) from None
            yield client
        finally:
            client.close()
    finally:
        if cluster is not None:
            cluster.close()


def threads(client: Any) -> int:
    """The cluster's threads, all workers together: how many chunks it judges at once."""
    return max(1, sum(client.nthreads().values()))
