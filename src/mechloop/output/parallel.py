"""Formatting a long text on every core, written in order: forked workers and pipes.

The table writers format numbers with orjson, which holds Python's global lock, so threads
do not help.  Instead the process forks one worker per idle core (:func:`workers_for`);
the workers share the table (copy-on-write: nothing is copied) and format pieces of it
round-robin — worker ``k`` does pieces ``k, k + W, k + 2W, ...`` — each sending its text
through its own pipe.  The parent takes the pieces in order, pipe after pipe, and moves
them into the output file with ``splice`` (kernel to kernel, no copy through Python; a
plain read and write where the output cannot be spliced into, e.g. a Python buffer).

A worker formats whole pieces and hands them to a thread of its own that sends them (a
pipe holds only 1 MiB: sent by the formatting thread, a worker would wait for the parent
to reach its piece instead of formatting on).  Memory stays bounded: a worker stops when
AHEAD pieces wait to be sent, so it holds at most AHEAD + 1 pieces.  If the parent stops
— an error, Ctrl-C, a kill — the workers are killed (or, if the parent was killed
outright, they die writing to a pipe nobody reads).  Nothing is written to a file by a
worker: an atomic write stays atomic.  A failure inside a worker is raised in the parent
with the worker's traceback.

Without workers (a small table, a busy machine) the pieces are formatted in this process
and written by a thread of its own (:class:`_Writer`), so that the write — on a busy disk as
costly as the formatting — runs beside it.

A piece's text is sent as frames: an 8-byte little-endian length, then that many bytes;
a length of 0 ends the piece, and a length of ``2**63 - 1`` is followed by a frame holding
a worker's traceback (UTF-8).
"""

from __future__ import annotations

import errno
import os
import signal
import traceback
from collections.abc import Callable, Iterable, Iterator, Sequence
from typing import BinaryIO

#: Fewest values in a table worth forking workers for (below it: format in this process).
PARALLEL_VALUES = 1 << 19

#: At most this many workers (one per core the process may run on).
MAX_WORKERS = 8

#: Pipe capacity asked for (Linux ``F_SETPIPE_SZ``; the default max is 1 MiB).
PIPE_BYTES = 1 << 20

#: Pieces a worker formats ahead of the one the parent is copying from it.
AHEAD = 3

#: Parts (chunks of rows, about 100 kB of text each) formatted in this process ahead of
#: the one its writing thread is writing.
WRITE_AHEAD = 32

_FAILED = (1 << 63) - 1

def _iov_max() -> int:
    """Buffers one ``writev`` takes (1024 on Linux; POSIX guarantees 16)."""
    try:
        return max(16, os.sysconf("SC_IOV_MAX"))
    except (AttributeError, ValueError, OSError):
        return 16


_IOV_MAX = _iov_max()
_F_SETPIPE_SZ = 1031

#: A part of a piece's text: a list of buffers written in a row, or a function giving them
#: (work that does not hold Python's lock, e.g. compiled code: called by the thread that
#: writes the part, beside the formatting of the next ones).
Part = list[bytes | memoryview] | Callable[[], list[bytes | memoryview]]

#: A piece's text, as an iterator of parts.
Render = Callable[[int, int], Iterator[Part]]


def buffers(part: Part) -> list[bytes | memoryview]:
    """The buffers of a part (its function called where it is one)."""
    return part() if callable(part) else part


def workers_for(values: int, pieces: int) -> int:
    """How many workers to fork for a table of ``values`` values cut into ``pieces``
    pieces: one per idle core the process may use (its cores less the 1-minute load
    average — at most the threads running now besides this one, so that this process's
    own solve before the write, or a job just ended, does not count —, rounded; at most
    MAX_WORKERS and ``pieces``), or 0 (format here) for a small
    table, fewer than two idle cores or a system without ``fork``.  On a busy machine
    workers gain nothing — the cores are taken, and Linux shares the CPU between sessions,
    not processes — and would cost the copies through the pipes."""
    if not hasattr(os, "fork") or values < PARALLEL_VALUES or pieces < 2:
        return 0
    count = min(usable_cores(), MAX_WORKERS, pieces, int(idle_cores(now=True) + 0.5))
    return count if count >= 2 else 0


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


def write_ordered(handle: BinaryIO, pieces: Sequence[tuple[int, int]], render: Render,
                  workers: int) -> None:
    """Write ``render(start, stop)`` for every piece ``(start, stop)`` of ``pieces``, in
    order, into ``handle``: formatted by ``workers`` forked processes, or here when
    ``workers`` is 0."""
    if workers < 2:
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
        return
    handle.flush()
    try:
        pool = _Pool(pieces, render, workers)
    except OSError:  # no fork now (memory, a process limit): format here
        write_ordered(handle, pieces, render, 0)
        return
    try:
        copy = _copier(handle)
        for index in range(len(pieces)):
            source = pool.reads[index % workers]
            while (size := _read_size(source)) != 0:
                if size == _FAILED:
                    text = _read_exact(source, _read_size(source)).decode("utf-8", "replace")
                    raise RuntimeError(f"a table-writing worker failed:\n{text}")
                copy(source, size)
        pool.finish()
    finally:
        pool.stop()


class _Pool:
    """The forked workers and the read ends of their pipes."""

    def __init__(self, pieces: Sequence[tuple[int, int]], render: Render, workers: int):
        self.reads: list[int] = []
        self.pids: list[int] = []
        try:
            for k in range(workers):
                read, write = os.pipe()
                try:
                    import fcntl

                    fcntl.fcntl(write, _F_SETPIPE_SZ, PIPE_BYTES)
                except (ImportError, OSError):
                    pass  # the default capacity works too, a little slower
                self.reads.append(read)
                pid = os.fork()
                if pid == 0:  # the worker: never returns
                    _work(write, self.reads, pieces[k::workers], render)
                self.pids.append(pid)
                os.close(write)
        except BaseException:
            self.stop()
            raise

    def finish(self) -> None:
        """Wait for the workers, which have sent everything; a failure if one did not end
        well."""
        pids, self.pids = self.pids, []
        for pid in pids:
            _, status = os.waitpid(pid, 0)
            if status != 0:
                raise RuntimeError(f"a table-writing worker ended with status {status}")

    def stop(self) -> None:
        """Kill the workers still running (after an error) and close the pipes."""
        for pid in self.pids:
            try:
                os.kill(pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
        for pid in self.pids:
            try:
                os.waitpid(pid, 0)
            except ChildProcessError:
                pass
        self.pids = []
        for fd in self.reads:
            os.close(fd)
        self.reads = []


def _work(write: int, reads: Iterable[int], pieces: Sequence[tuple[int, int]],
          render: Render) -> None:
    """A worker's life: format its pieces into ``write``, then exit (never return)."""
    code = 0
    sender: _Sender | None = None
    try:
        for sig in (signal.SIGINT, signal.SIGTERM, getattr(signal, "SIGHUP", None)):
            if sig is not None:
                signal.signal(sig, signal.SIG_DFL)
        for fd in reads:
            os.close(fd)
        sender = _Sender(write)
        for start, stop in pieces:  # sent as they are (a join would copy them once more)
            texts = [b for part in render(start, stop) for b in buffers(part) if len(b)]
            size = sum(len(b) for b in texts)
            sender.put([size.to_bytes(8, "little"), *texts] if size else [])
        sender.finish()
    except BrokenPipeError:
        code = 1  # the parent stopped reading: it has failed or was killed
    except BaseException:
        code = 1
        try:
            text = traceback.format_exc().encode("utf-8")
            failure = [_FAILED.to_bytes(8, "little"), len(text).to_bytes(8, "little"), text]
            if sender is not None and sender.error is None:
                sender.queue.put(failure)  # after the pieces already queued
                sender.finish()
            else:
                _write_all(write, failure)
        except BaseException:
            pass
    finally:
        os._exit(code)


class _Sender:
    """A worker's thread sending its formatted pieces into its pipe, so that formatting
    goes on while the parent is still busy with another worker's piece: at most AHEAD
    pieces wait (a failure to send is raised at the next ``put``)."""

    def __init__(self, fd: int):
        import queue
        import threading

        self.fd = fd
        self.queue: queue.Queue[list[bytes] | None] = queue.Queue(maxsize=AHEAD)
        self.error: BaseException | None = None
        self.thread = threading.Thread(target=self._run, daemon=True)
        self.thread.start()

    def _run(self) -> None:
        try:
            while (frames := self.queue.get()) is not None:
                _write_all(self.fd, frames)
        except BaseException as exc:
            self.error = exc
            while self.queue.get() is not None:  # let put() go on until the end
                pass

    def put(self, frames: list[bytes]) -> None:
        """Send a piece: its frames (without the end mark, added here)."""
        if self.error is not None:
            raise self.error
        self.queue.put([*frames, bytes(8)])

    def finish(self) -> None:
        """Wait until everything put is sent."""
        self.queue.put(None)
        self.thread.join()
        if self.error is not None:
            raise self.error


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


def _write_all(fd: int, buffers: list[bytes | memoryview]) -> None:
    views = [memoryview(b).cast("B") for b in buffers]
    while views:
        done = os.writev(fd, views[:_IOV_MAX])
        while views and done >= len(views[0]):
            done -= len(views[0])
            views.pop(0)
        if views and done:
            views[0] = views[0][done:]


def _read_exact(fd: int, size: int) -> bytes:
    parts = []
    while size:
        got = os.read(fd, size)
        if not got:
            raise RuntimeError("a table-writing worker stopped before its text was complete")
        parts.append(got)
        size -= len(got)
    return b"".join(parts)


def _read_size(fd: int) -> int:
    return int.from_bytes(_read_exact(fd, 8), "little")


def _copier(handle: BinaryIO) -> Callable[[int, int], None]:
    """A function moving ``size`` bytes from a pipe into ``handle``: by ``splice`` into
    its file descriptor where the system can, else read and written."""
    try:
        out = handle.fileno()
    except (AttributeError, OSError, ValueError):
        out = -1
    can_splice = [out >= 0 and hasattr(os, "splice")]

    def copy(source: int, size: int) -> None:
        while size and can_splice[0]:
            try:
                moved = os.splice(source, out, size)
            except OSError as exc:
                if exc.errno not in (errno.EINVAL, errno.ENOSYS, errno.EBADF):
                    raise
                can_splice[0] = False  # e.g. a file opened for appending, a terminal
                break
            if moved == 0:
                raise RuntimeError("a table-writing worker stopped before its text was "
                                   "complete")
            size -= moved
        while size:
            block = _read_exact(source, min(size, PIPE_BYTES))
            handle.write(block)
            size -= len(block)

    return copy
