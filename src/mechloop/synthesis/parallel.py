"""Map a function over items, serially or spread over processes and machines by Dask.

:func:`map_tasks` is the one place where mechloop runs work in parallel: parametric sweeps
(:mod:`mechloop.synthesis.sweep`) and the multi-start runs of the optimization use it.  A
*scheduler* is

* ``"serial"`` — a plain loop in this process;
* ``"processes"`` — a ``dask.distributed.LocalCluster`` of worker processes on this
  machine, started for the call and closed when it ends;
* an address ``"tcp://host:8786"`` — an existing dask.distributed scheduler (started with
  ``dask scheduler``, with workers attached by ``dask worker tcp://host:8786``);
* a ``distributed.Client`` — used as it is and left open (to run many maps on one cluster).

``None`` chooses by :func:`choose_scheduler`.  Results come back in the order of the items;
an exception raised by ``fn`` in a worker (every :class:`~mechloop.errors.MechloopError`
pickles) is raised again in the caller with its type and message; Ctrl-C cancels the
work still queued and closes the cluster.

``fn`` and the items must pickle: a function defined at the top level of an importable
module (Dask pickles by reference, so the workers import it), plain data as items.  A
script that starts a ``LocalCluster`` must guard its top level with
``if __name__ == "__main__":`` (worker processes are spawned and import the script).
"""

from __future__ import annotations

import logging
import os
from collections.abc import Callable, Iterable, Sequence
from typing import TYPE_CHECKING, Any, TypeVar

from mechloop.errors import HintedError

if TYPE_CHECKING:
    from distributed import Client

T = TypeVar("T")
R = TypeVar("R")

#: A progress callback: ``progress(done, total)``, called with ``(0, total)`` first and
#: after every finished item.
Progress = Callable[[int, int], Any]

#: Scheduler names; anything else must be a ``tcp://``, ``tls://``, ``ucx://`` or
#: ``inproc://`` address of a dask.distributed scheduler, or a ``distributed.Client``.
SERIAL, PROCESSES = "serial", "processes"
_ADDRESS_SCHEMES = ("tcp://", "tls://", "ucx://", "inproc://", "ws://", "wss://")

#: The automatic rule (``scheduler=None``) without a time estimate: more than this many
#: items go to processes.
AUTO_MIN_ITEMS = 8
#: The automatic rule with a time estimate: processes when the serial run would take
#: longer than this (s) — several times the ~2 s a LocalCluster takes to start and stop.
AUTO_MIN_SECONDS = 10.0
#: How long to wait for a remote scheduler to answer and to have a worker (s).
CONNECT_TIMEOUT = 30.0


class SchedulerError(HintedError):
    """The scheduler asked for cannot be used: an unknown name, an address that does not
    answer, a cluster without workers."""


def choose_scheduler(n_items: int, *, seconds_per_item: float | None = None,
                     cpus: int | None = None) -> str:
    """The scheduler that ``scheduler=None`` stands for.

    ``"serial"`` when there is one CPU or at most one item; otherwise, with an estimate
    of the time one item takes (``seconds_per_item``, s), ``"processes"`` when the serial
    run would last more than :data:`AUTO_MIN_SECONDS` (10 s), and without an estimate
    when there are more than :data:`AUTO_MIN_ITEMS` (8) items.

    >>> choose_scheduler(4, cpus=8), choose_scheduler(100, seconds_per_item=0.01, cpus=8)
    ('serial', 'serial')
    >>> choose_scheduler(100, seconds_per_item=1.0, cpus=8), choose_scheduler(9, cpus=8)
    ('processes', 'processes')
    """
    cpus = (os.cpu_count() or 1) if cpus is None else cpus
    if cpus < 2 or n_items < 2:
        return SERIAL
    if seconds_per_item is None:
        return PROCESSES if n_items > AUTO_MIN_ITEMS else SERIAL
    return PROCESSES if n_items * seconds_per_item > AUTO_MIN_SECONDS else SERIAL


def check_scheduler(scheduler: object) -> None:
    """Raise :class:`SchedulerError` unless ``scheduler`` is None, a scheduler name, an
    address or a ``distributed.Client`` (nothing is started or contacted)."""
    if scheduler is None or scheduler in (SERIAL, PROCESSES) or _is_client(scheduler):
        return
    if isinstance(scheduler, str) and scheduler.strip().startswith(_ADDRESS_SCHEMES):
        return
    raise SchedulerError(f"unknown scheduler {scheduler!r}",
                         "use 'serial', 'processes' or the address of a running "
                         "dask.distributed scheduler, e.g. 'tcp://host:8786'")


def map_tasks(fn: Callable[[T], R], items: Iterable[T], *,
              scheduler: str | Client | None = None, progress: Progress | None = None,
              seconds_per_item: float | None = None, workers: int | None = None) -> list[R]:
    """``[fn(item) for item in items]``, serially or on a Dask cluster.

    Parameters
    ----------
    fn : a picklable function of one item (top level of an importable module).
    items : the inputs, picklable; consumed once.
    scheduler : ``"serial"``, ``"processes"``, an address ``"tcp://host:8786"``, a
        ``distributed.Client``, or None (default: :func:`choose_scheduler`).
    progress : ``progress(done, total)``, called with ``(0, total)`` first and after every
        finished item (in the order they finish).
    seconds_per_item : an estimate of the time of one item (s), for ``scheduler=None``.
    workers : worker processes of the local cluster (default: one per CPU, at most one
        per item), one thread each.

    Returns
    -------
    list : ``fn(item)`` for every item, in the order of the items.

    Raises
    ------
    The first exception that ``fn`` raises, with its type and message (work still queued
    is cancelled); :class:`SchedulerError` for an unusable scheduler;
    ``KeyboardInterrupt`` after cancelling the queued work and closing the cluster.
    """
    work: list[T] = list(items)
    check_scheduler(scheduler)
    if scheduler is None:
        scheduler = choose_scheduler(len(work), seconds_per_item=seconds_per_item)
    if progress is not None:
        progress(0, len(work))
    if not work:
        return []
    if scheduler == SERIAL:
        return _map_serial(fn, work, progress)
    if _is_client(scheduler):
        return _map_client(scheduler, fn, work, progress)
    if scheduler == PROCESSES:
        return _map_local(fn, work, progress, workers)
    return _map_remote(str(scheduler).strip(), fn, work, progress)


def _map_serial(fn: Callable[[T], R], work: Sequence[T], progress: Progress | None
                ) -> list[R]:
    out: list[R] = []
    for item in work:
        out.append(fn(item))
        if progress is not None:
            progress(len(out), len(work))
    return out


def _is_client(scheduler: object) -> bool:
    if isinstance(scheduler, str | bytes) or scheduler is None:
        return False
    try:
        from distributed import Client
    except ImportError:  # pragma: no cover - distributed is a dependency
        return False
    return isinstance(scheduler, Client)


def _map_local(fn: Callable[[T], R], work: Sequence[T], progress: Progress | None,
               workers: int | None) -> list[R]:
    """Start a LocalCluster of processes, map, close it (also on errors and Ctrl-C)."""
    from distributed import Client, LocalCluster

    n = workers or min(os.cpu_count() or 1, len(work))
    with LocalCluster(n_workers=max(1, n), threads_per_worker=1, processes=True,
                      dashboard_address=None, silence_logs=logging.CRITICAL) as cluster, \
            Client(cluster, set_as_default=False) as client:
        return _map_client(client, fn, work, progress)


def _map_remote(address: str, fn: Callable[[T], R], work: Sequence[T],
                progress: Progress | None) -> list[R]:
    """Connect to a running scheduler, map, disconnect (the cluster stays up)."""
    from distributed import Client

    try:
        client = Client(address, timeout=CONNECT_TIMEOUT, set_as_default=False)
    except (OSError, TimeoutError, ValueError) as exc:
        raise SchedulerError(f"cannot reach the dask scheduler at {address} ({exc})",
                             "start one with 'dask scheduler' and attach workers with "
                             f"'dask worker {address}', or use the 'processes' scheduler"
                             ) from None
    with client:
        try:
            client.wait_for_workers(1, timeout=CONNECT_TIMEOUT)
        except (TimeoutError, OSError):
            raise SchedulerError(f"the dask scheduler at {address} has no workers",
                                 f"attach some with 'dask worker {address}'") from None
        return _map_client(client, fn, work, progress)


def _map_client(client: Client, fn: Callable[[T], R], work: Sequence[T],
                progress: Progress | None) -> list[R]:
    """Submit every item to ``client``, collect in item order; cancel on any error."""
    from distributed import as_completed

    futures = client.map(fn, work, pure=False)
    where = {future.key: i for i, future in enumerate(futures)}
    out: list[Any] = [None] * len(work)
    done = 0
    try:
        for future in as_completed(futures, loop=client.loop):
            out[where[future.key]] = future.result()  # raises fn's exception as it was
            done += 1
            if progress is not None:
                progress(done, len(work))
    except BaseException:
        client.cancel(futures)
        raise
    return out
