"""Work that may take long (a solve, a report) in a child process with a time limit.

The child is forked by multiprocessing's fork server, a single-threaded process that has
imported mechloop and loaded its compiled code once (:mod:`mechloop.web.preload`): a child
starts at once, and never inherits a lock held by one of the web server's threads.  Past
the limit the child is terminated, so a model that takes too long costs the server
nothing; at most :data:`MAX_CHILDREN` children run at once (a request beyond waits its
turn, its time limit counting from its start).  The child sends back ``("ok", value)``,
``("error", problems)`` for a :class:`~mechloop.errors.MechloopError` (the problems as
:func:`mechloop.web.documents.problems` gives them) or ``("crash", message)`` for any
other exception — a bad model never takes the server down.
"""

from __future__ import annotations

import multiprocessing
import os
import threading
import traceback
from collections.abc import Callable
from typing import Any

from mechloop.errors import MechloopError
from mechloop.web.safety import WebError

#: The default time limit of a solve, s.
SOLVE_SECONDS = 60.0
#: The default time limit of a report, s.
REPORT_SECONDS = 300.0
#: Children running at once.
MAX_CHILDREN = 2
#: The modules the fork server imports once for every child.
PRELOAD = ["mechloop.web.preload"]

_turns = threading.BoundedSemaphore(MAX_CHILDREN)


def _context() -> multiprocessing.context.BaseContext:
    context = multiprocessing.get_context("forkserver")
    context.set_forkserver_preload(PRELOAD)
    return context


def warm_up() -> threading.Thread:
    """Start the fork server in the background (it imports mechloop and loads the compiled
    code: seconds), so that it is ready before the first solve; the thread it runs in."""
    thread = threading.Thread(target=run_limited, args=(abs, 0), kwargs={"seconds": 300},
                              daemon=True, name="mechloop-warm-up")
    thread.start()
    return thread


class WorkFailed(WebError):
    """The child reported a problem of the model (``problems``: the located items)."""

    def __init__(self, message: str, hint: str = "", status: int = 422,
                 problems: list[dict[str, Any]] | None = None):
        super().__init__(message, hint, status)
        self.problems = problems or []

    def __reduce__(self):
        return (type(self), (self.message, self.hint, self.status, self.problems))


def _child(connection: Any, func: Callable[..., Any], args: tuple) -> None:
    from mechloop.web.documents import problems

    try:
        try:
            result: tuple[str, Any] = ("ok", func(*args))
        except MechloopError as exc:
            result = ("error", problems(exc))
        except Exception as exc:  # reported to the page, with its cause, not swallowed
            result = ("crash", f"{type(exc).__name__}: {exc}\n"
                      + "".join(traceback.format_exception(exc)[-3:]))
        connection.send(result)
    finally:
        connection.close()
        os._exit(0)  # no atexit handlers or finalizers of the server in the child


def _run(func: Callable[..., Any], args: tuple, seconds: float) -> tuple[str, Any]:
    context = _context()
    parent, child = context.Pipe(duplex=False)
    process = context.Process(target=_child, args=(child, func, args), daemon=True)
    try:
        process.start()
    except (OSError, RuntimeError) as exc:  # no process left, or a main module unguarded
        parent.close()
        raise WorkFailed(f"cannot start the work: {exc}".strip(),
                         "start the server by mechloop serve (or, from a script, under "
                         "if __name__ == '__main__':)", 500) from None
    finally:
        child.close()
    try:
        if not parent.poll(seconds):
            raise WorkFailed(f"the work took longer than {seconds:g} s and was stopped",
                             "use fewer positions, or start mechloop serve with a longer "
                             "--time-limit", 504)
        try:
            return parent.recv()
        except EOFError:
            raise WorkFailed("the work stopped without a result (out of memory?)",
                             "use fewer positions", 500) from None
    finally:
        if process.is_alive():
            process.terminate()
        process.join(5)
        parent.close()


def run_limited(func: Callable[..., Any], *args: Any, seconds: float) -> Any:
    """``func(*args)`` computed in a child, its value — or
    :class:`WorkFailed`: 422 with the problems of a model error, 504 past ``seconds``,
    500 for an unexpected exception of the child."""
    with _turns:
        kind, value = _run(func, args, seconds)
    if kind == "ok":
        return value
    if kind == "error":
        first = value[0] if value else {"message": "the model has a problem", "hint": ""}
        raise WorkFailed(first["message"], first["hint"], 422, value)
    raise WorkFailed(f"mechloop failed: {value}", "please report this with the model", 500)
