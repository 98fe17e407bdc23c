"""Atomic writing: a file appears whole or not at all, and nothing is left beside it.

On Linux the content goes to an anonymous file in the target's folder (``O_TMPFILE``: it
has no name, so a process killed even by SIGKILL while writing leaves nothing behind); when
it is complete and on disk (fsync) it is given the target's name — directly by
``linkat`` when the target does not exist yet, else under a hidden temporary name renamed
onto the target at once (``os.replace``), a window of two system calls.  Elsewhere, or on a
file system without ``O_TMPFILE``, a hidden temporary file beside the target is written
instead and removed on any exception, on Ctrl-C and on SIGTERM/SIGHUP.

While a file is written, a thread has the disk write its pages back every 32 MB (Linux's
``sync_file_range``), so that the final fsync does not wait for the whole file.

The written file keeps the mode (and, where allowed, the owner) of the file it replaces; a
new file gets ``0o666`` less the umask, as any program's.  A symlink as the target is
followed: the file it points to is replaced and the link stays.
"""

from __future__ import annotations

import errno
import os
import secrets
import signal
import stat
import sys
import threading
from collections.abc import Callable, Iterator
from contextlib import contextmanager, nullcontext
from pathlib import Path
from typing import BinaryIO

from mechloop.output.paths import DISK_ERRORS, destination, write_error

#: errno values by which ``open(O_TMPFILE)`` says the file system cannot do it.
_NO_TMPFILE = frozenset({errno.EOPNOTSUPP, errno.EISDIR, errno.EINVAL, errno.ENOSYS})


#: Whether anonymous files can be linked into the file system here (False after a failure).
_ANONYMOUS = True

_AT_FDCWD = -100
_AT_EMPTY_PATH = 0x1000


def _link(fd: int, name: Path) -> bool:
    """Give the anonymous file ``fd`` the name ``name``: by its /proc link
    (AT_SYMLINK_FOLLOW), else by ``linkat(fd, "", AT_EMPTY_PATH)``; False when neither is
    allowed.  FileExistsError when ``name`` exists."""
    try:
        os.link(f"/proc/self/fd/{fd}", name, follow_symlinks=True)
        return True
    except FileExistsError:
        raise
    except OSError as exc:
        if exc.errno not in _NO_LINK:
            raise
    import ctypes

    libc = ctypes.CDLL(None, use_errno=True)
    if libc.linkat(fd, b"", _AT_FDCWD, os.fsencode(name), _AT_EMPTY_PATH) == 0:
        return True
    code = ctypes.get_errno()
    if code == errno.EEXIST:
        raise FileExistsError(code, os.strerror(code), str(name))
    if code not in _NO_LINK:
        raise OSError(code, os.strerror(code), str(name))
    return False


#: errno values by which a link of an anonymous file is refused (not a disk error).
_NO_LINK = frozenset({errno.EXDEV, errno.ENOENT, errno.EPERM, errno.EACCES,
                      errno.EOPNOTSUPP, errno.EINVAL, errno.ENOSYS})


class _Stage:
    """The file being written for ``target`` until it is committed or discarded."""

    def __init__(self, target: Path):
        self.dest = destination(target)
        self.folder = self.dest.parent
        try:
            st = os.stat(self.dest)
            self.mode: int | None = stat.S_IMODE(st.st_mode)
            self.owner: tuple[int, int] | None = (st.st_uid, st.st_gid)
        except FileNotFoundError:
            self.mode = self.owner = None
        self.named: Path | None = None
        fd = self._anonymous()
        self.fd = fd if fd is not None else self._named()
        self.writeback = _Writeback.start(self.fd)

    def _anonymous(self) -> int | None:
        flag = getattr(os, "O_TMPFILE", None)
        if flag is None or not _ANONYMOUS or not os.path.isdir(f"/proc/{os.getpid()}/fd"):
            return None
        try:
            return os.open(self.folder, flag | os.O_RDWR | os.O_CLOEXEC, 0o666)
        except OSError as exc:
            if exc.errno in _NO_TMPFILE:
                return None
            raise

    def _free_name(self) -> Path:
        return self.folder / f".{self.dest.name}.{secrets.token_hex(6)}.tmp{self.dest.suffix}"

    def _named(self) -> int:
        while True:
            name = self._free_name()
            try:
                fd = os.open(name, os.O_RDWR | os.O_CREAT | os.O_EXCL | getattr(os, "O_CLOEXEC", 0),
                             0o666)
            except FileExistsError:
                continue
            self.named = name
            return fd

    @property
    def path(self) -> str:
        """A path by which another program (ffmpeg) can open the staged file to write."""
        return str(self.named) if self.named is not None else f"/proc/{os.getpid()}/fd/{self.fd}"

    def _stop_writeback(self) -> None:
        if self.writeback is not None:
            self.writeback.stop()
            self.writeback = None

    def _keep_mode(self) -> None:
        """Give the staged file the mode and (where allowed) the owner of the file it
        replaces; before its fsync, so that they are on disk with it."""
        if self.mode is None:
            return
        os.fchmod(self.fd, self.mode)
        if self.owner is not None and hasattr(os, "fchown"):
            st = os.fstat(self.fd)
            if (st.st_uid, st.st_gid) != self.owner:
                try:
                    os.fchown(self.fd, *self.owner)
                except PermissionError:
                    pass

    def commit(self) -> None:
        """Put the staged file, complete and on disk, in place of the target."""
        self._stop_writeback()
        self._keep_mode()
        os.fsync(self.fd)
        if self.named is None:
            try:
                linked = _link(self.fd, self.dest)
            except FileExistsError:
                self.named = self._free_name()
                linked = _link(self.fd, self.named)
                if linked:
                    os.replace(self.named, self.dest)
                else:
                    self.named = None
            if not linked:
                self._copy_named()
        else:
            os.replace(self.named, self.dest)
        self.named = None
        os.close(self.fd)
        self.fd = -1
        _sync_folder(self.folder)

    def _copy_named(self) -> None:
        """The anonymous file cannot be given a name here (no /proc link, no
        AT_EMPTY_PATH): copy it to a named temporary file, then rename that, and use named
        temporary files from now on."""
        global _ANONYMOUS
        _ANONYMOUS = False
        anonymous = self.fd
        with _signals_raise():
            try:
                self.fd = -1
                self.fd = self._named()
                size = os.fstat(anonymous).st_size
                copied = 0
                while copied < size:
                    done = os.sendfile(self.fd, anonymous, copied, size - copied)
                    if done == 0:  # never a short file in place of the target
                        raise OSError(errno.EIO, f"copied {copied} of {size} bytes",
                                      str(self.named))
                    copied += done
                self._keep_mode()  # the mode and the owner, as the anonymous file had them
                os.fsync(self.fd)
                os.replace(self.named, self.dest)  # type: ignore[arg-type]
            finally:
                os.close(anonymous)

    def discard(self) -> None:
        """Drop the staged file: close it and remove its temporary name, if it has one."""
        self._stop_writeback()
        if self.fd >= 0:
            os.close(self.fd)
            self.fd = -1
        if self.named is not None:
            self.named.unlink(missing_ok=True)
            self.named = None


#: Bytes written into the staged file between two requests to write them back to the disk,
#: and seconds between two looks at its size.
WRITEBACK_BYTES = 32 << 20
WRITEBACK_SECONDS = 0.05


def _sync_file_range() -> Callable[[int, int, int], int] | None:
    """Linux's ``sync_file_range(fd, offset, length, SYNC_FILE_RANGE_WRITE)``: start
    writing a range of a file back to the disk without waiting for it; None elsewhere."""
    if not sys.platform.startswith("linux"):
        return None
    import ctypes

    try:
        call = ctypes.CDLL(None, use_errno=True).sync_file_range
    except (AttributeError, OSError):
        return None
    call.argtypes = [ctypes.c_int, ctypes.c_int64, ctypes.c_int64, ctypes.c_uint]
    return lambda fd, offset, length: call(fd, offset, length, 2)  # SYNC_FILE_RANGE_WRITE


class _Writeback:
    """A thread that has the disk write the staged file back while it is being written,
    every WRITEBACK_BYTES: the fsync at the end then waits for the last pages only.  A
    file of 1.5 GB stays below the kernel's threshold for writing back in the background
    (10 % of the available memory), so without it the fsync wrote the whole file after
    the writer had finished: 1.28-2.50 s in all for 1.5 GB written in 1 MiB blocks on the
    development machine, against 0.88-1.07 s with it (three runs each, under load)."""

    _call: Callable[[int, int, int], int] | None = None
    _looked = False

    def __init__(self, fd: int, call: Callable[[int, int, int], int]):
        self._fd, self._call_range = fd, call
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._run, name="mechloop-writeback",
                                        daemon=True)
        self._thread.start()

    @classmethod
    def start(cls, fd: int) -> _Writeback | None:
        """The thread for ``fd``, or None where the system cannot start a writeback."""
        if not cls._looked:
            cls._call, cls._looked = _sync_file_range(), True
        return None if cls._call is None else cls(fd, cls._call)

    def _run(self) -> None:
        done = 0
        while not self._stop.wait(WRITEBACK_SECONDS):
            try:
                end = os.fstat(self._fd).st_size
            except OSError:
                return
            if end - done >= WRITEBACK_BYTES:
                self._call_range(self._fd, done, end - done)  # errors: the fsync tells
                done = end

    def stop(self) -> None:
        """Stop the thread (before the file is synced or closed)."""
        self._stop.set()
        self._thread.join()


def _sync_folder(folder: Path) -> None:
    try:
        fd = os.open(folder, os.O_RDONLY | getattr(os, "O_DIRECTORY", 0))
    except OSError:
        return
    try:
        os.fsync(fd)
    except OSError:
        pass
    finally:
        os.close(fd)


def _exit_on_signal(signum: int, frame: object) -> None:
    raise SystemExit(128 + signum)


@contextmanager
def _signals_raise() -> Iterator[None]:
    """In the main thread, SIGTERM and SIGHUP (left at their default) raise SystemExit
    inside the block, so that its clean-up runs; the handlers are restored after it."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    saved = {}
    for sig in (getattr(signal, "SIGTERM", None), getattr(signal, "SIGHUP", None)):
        if sig is not None and signal.getsignal(sig) is signal.SIG_DFL:
            saved[sig] = signal.signal(sig, _exit_on_signal)
    try:
        yield
    finally:
        for sig, handler in saved.items():
            signal.signal(sig, handler)


@contextmanager
def _staged(target: str | os.PathLike[str]) -> Iterator[_Stage]:
    try:
        stage = _Stage(Path(target))
    except OSError as exc:
        raise write_error(exc, target) from None
    guard = _signals_raise() if stage.named is not None else nullcontext()
    try:
        with guard:
            yield stage
            with _signals_raise():
                stage.commit()
    except OSError as exc:
        stage.discard()
        if exc.errno not in DISK_ERRORS | {errno.ENOENT}:
            raise  # not the disk's: e.g. the caller's own reads inside the block
        raise write_error(exc, target) from None
    except BaseException:
        stage.discard()
        raise


@contextmanager
def atomic_file(target: str | os.PathLike[str]) -> Iterator[BinaryIO]:
    """A binary file to write ``target`` through; it replaces ``target`` when the block
    ends without an exception, and vanishes otherwise.  Write errors (no space, no
    permission, a read-only disk) raise :class:`~mechloop.output.paths.OutputError`."""
    with _staged(target) as stage:
        handle = open(stage.fd, "wb", closefd=False, buffering=1 << 20)
        try:
            yield handle  # type: ignore[misc]
            if not handle.closed:
                handle.flush()
        finally:
            if not handle.closed:
                handle.close()


@contextmanager
def atomic_path(target: str | os.PathLike[str]) -> Iterator[str]:
    """A path for a writer that opens the file itself (ffmpeg, matplotlib's movie
    writers); the file it writes replaces ``target`` when the block succeeds.  The path
    need not end in the target's suffix: tell the writer the format explicitly."""
    with _staged(target) as stage:
        yield stage.path


def atomic_write_bytes(target: str | os.PathLike[str], payload: bytes) -> None:
    """Write ``payload`` to ``target`` atomically (see :func:`atomic_file`)."""
    with atomic_file(target) as handle:
        handle.write(payload)


def atomic_write_text(target: str | os.PathLike[str], text: str) -> None:
    """Write ``text`` (UTF-8) to ``target`` atomically (see :func:`atomic_file`)."""
    atomic_write_bytes(target, text.encode("utf-8"))
