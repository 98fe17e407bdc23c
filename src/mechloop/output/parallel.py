"""Cores for the table writers, and formatting beside writing.

:func:`threads_for` tells how many threads format a large table in compiled code
(:mod:`mechloop.output.lines`): one per core the process may use, whatever the load.
:func:`write_ordered` writes the pieces of a table formatted in Python (orjson, which holds
Python's lock: small tables, tables with strings) from a thread of its own
(:class:`_Writer`), so that the write — on a busy disk as costly as the formatting — runs
beside it.

Forked worker processes formatting pieces of the text (orjson's, under Python's lock) were
the way to use idle cores before the numbers were formatted in compiled code; threads
do it now, without copying the text through pipes, and nothing is left running when the
writer is killed.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Iterator, Sequence
from typing import BinaryIO

#: At most this many formatting threads.
MAX_THREADS = 8

#: Parts (chunks of rows, about 100 kB of text each) formatted in this process ahead of
#: the one its writing thread is writing.
WRITE_AHEAD = 32

#: A part of a piece's text: a list of buffers written in a row, or a function giving them
#: (called by the thread that writes the part).
Part = list[bytes | memoryview] | Callable[[], list[bytes | memoryview]]

#: A piece's text, as an iterator of parts.
Render = Callable[[int, int], Iterator[Part]]


def buffers(part: Part) -> list[bytes | memoryview]:
    """The buffers of a part (its function called where it is one)."""
    return part() if callable(part) else part


def threads_for(values: int) -> int:
    """Threads to format a table of ``values`` values in compiled code: one per core the
    process may use, at most MAX_THREADS and one per 2^16 values, at least one.  The
    calling thread writes meanwhile.

    Not fewer on a loaded machine: the load average (and a count of the threads running
    at one instant) mistook this process's own solve, a job just ended or a kernel thread
    for other work and left a core idle half the time, halving the write's speed; threads
    beside other work only share the cores, for as long as the write lasts."""
    return max(1, min(usable_cores(), MAX_THREADS, values >> 16))

def usable_cores() -> int:
    """The cores this process may run on (its affinity; all of them where unknown)."""
    try:
        return len(os.sched_getaffinity(0))
    except (AttributeError, OSError):
        return os.cpu_count() or 1


def idle_cores(own: float = 0.0, *, now: bool = False) -> float:
    """Cores not used by other work: :func:`usable_cores` less the 1-minute load average,
    of which ``own`` (runnable tasks, averaged alike) is this process's own work and
    not counted (the caller knows it will stop it or share it out); every usable core
    where the load average is unknown.  With ``now``, other work is at most what runs
    at this moment besides the calling thread (Linux's count of runnable threads): a job
    that has just ended still weighs on the average for a minute, not there."""
    cores = usable_cores()
    try:
        load = os.getloadavg()[0]
    except (AttributeError, OSError):
        return float(cores)
    others = max(load - own, 0.0)
    running = running_threads() if now else None
    if running is not None:
        others = min(others, max(running - 1, 0))
    return cores - others


def running_threads() -> int | None:
    """Threads of the whole system runnable at this moment, the caller's included
    (``/proc/loadavg``); None where unknown."""
    try:
        with open("/proc/loadavg", encoding="ascii") as handle:
            return int(handle.read().split()[3].split("/")[0])
    except (OSError, ValueError, IndexError):
        return None


def write_ordered(handle: BinaryIO, pieces: Sequence[tuple[int, int]], render: Render
                  ) -> None:
    """Write ``render(start, stop)`` for every piece ``(start, stop)`` of ``pieces``, in
    order, into ``handle``: formatted here, written by a thread of its own (a single piece
    directly)."""
    if len(pieces) < 2:  # a small table: not worth a thread
        for start, stop in pieces:
            for part in render(start, stop):
                for buffer in buffers(part):
                    handle.write(buffer)
        return
    writer = _Writer(handle)
    try:
        for start, stop in pieces:
            for part in render(start, stop):
                writer.put(part)
    except BaseException:
        writer.finish(quiet=True)  # the thread ends before the handle is closed
        raise
    writer.finish()


class _Writer:
    """A thread writing the parts formatted in this process into ``handle``, so that the
    write (the copy into the page cache, the waits on a full one: as costly as formatting
    on a busy disk) runs on another core while the next parts are formatted.  At most
    WRITE_AHEAD parts wait (memory stays bounded); a failure to write is raised at the next
    ``put`` or at ``finish``."""

    def __init__(self, handle: BinaryIO):
        import queue
        import threading

        self.handle = handle
        self.queue: queue.Queue[Part | None] = queue.Queue(
            maxsize=WRITE_AHEAD)
        self.error: BaseException | None = None
        self.thread = threading.Thread(target=self._run, daemon=True)
        self.thread.start()

    def _run(self) -> None:
        try:
            while (part := self.queue.get()) is not None:
                for buffer in buffers(part):
                    self.handle.write(buffer)
        except BaseException as exc:
            self.error = exc
            while self.queue.get() is not None:  # let put() go on until the end
                pass

    def put(self, part: Part) -> None:
        """Write a part (its buffers in a row): queued, made (where it is a function) and
        written by the thread."""
        if self.error is not None:
            raise self.error
        self.queue.put(part)

    def finish(self, *, quiet: bool = False) -> None:
        """Wait until everything put is written; a failure to write is raised (unless
        ``quiet``: the caller is raising its own)."""
        self.queue.put(None)
        self.thread.join()
        if self.error is not None and not quiet:
            raise self.error
