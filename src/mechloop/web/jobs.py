"""Work that takes time — a synthesis — as a background job of the web application.

A job runs in a child process forked by the fork server of :mod:`mechloop.web.worker`
(mechloop is imported there once).  The child sends its progress through a pipe after
every generation: the generation, the limit, the best objective value, whether it is
feasible, and — at most every :data:`DRAW_SECONDS` while the best improves — the vector
diagram of the best design so far (:func:`mechloop.web.payload.diagram`, every position,
as the page draws it).  A reader thread of the server keeps the
latest state; the page polls it.

Cancelling sends SIGINT to the child: the synthesis stops as after Ctrl-C in the CLI and
returns the best design found (``stopped: interrupted``).  Past the job's time limit the
same happens; a child that does not answer within :data:`GRACE_SECONDS` after that is
killed.  At most :data:`MAX_JOBS` jobs run at once (another start is refused, 429), and
:meth:`Jobs.stop_all` (the server's shutdown) kills every child.

An animation, a sweep or a simulation runs the same way (:mod:`mechloop.web.work`); its
file (the animation, the table) is kept apart from the state the page polls
(:attr:`Job.file`), for ``GET /api/jobs/{id}/file``.

The result of a synthesis is the synthesized model's text, as ``mechloop synthesize -o
best.yaml`` writes it (a group file is written back as a group file), with the run's
summary.
"""

from __future__ import annotations

import os
import signal
import tempfile
import threading
import time
import uuid
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from mechloop.web.safety import WebError
from mechloop.web.worker import _context

#: Jobs running at once.
MAX_JOBS = 1
#: The default time limit of a job, s (then it is stopped, keeping the best).
JOB_SECONDS = 600.0
#: Time a stopped child has to send its result before it is killed, s.
GRACE_SECONDS = 20.0
#: Least time between two drawings of the best design sent by the child, s.
DRAW_SECONDS = 0.5
#: Finished jobs kept for the page to read.
KEEP_FINISHED = 20


def _synthesis_child(connection: Any, text: str, path: str, root: str,
                     options: dict[str, Any]) -> None:
    """The child: run the synthesis of the model in ``text``, sending
    ``("progress", {...})`` items and finally ``("done", {...})`` or ``("error",
    problems)`` / ``("crash", message)``."""
    signal.signal(signal.SIGINT, signal.default_int_handler)  # cancel = Ctrl-C
    from mechloop.errors import MechloopError
    from mechloop.web.documents import problems

    try:
        try:
            connection.send(("done", _synthesize(connection, text, Path(path), Path(root),
                                                 options)))
        except KeyboardInterrupt:  # cancelled, or past its limit, before the search started
            connection.send(("error", [{"line": None, "path": "", "message":
                                        "the job was stopped before the search started",
                                        "hint": "start it again (with a longer time "
                                        "limit, if it was reached)"}]))
        except MechloopError as exc:
            connection.send(("error", problems(exc)))
        except Exception as exc:  # reported to the page, with its cause
            connection.send(("crash", f"{type(exc).__name__}: {exc}"))
    finally:
        connection.close()
        os._exit(0)


def _synthesize(connection: Any, text: str, path: Path, root: Path,
                options: dict[str, Any]) -> dict[str, Any]:
    from mechloop.errors import ModelError, Problem
    from mechloop.model.document import parse_document
    from mechloop.model.groups.files import _from_group_data
    from mechloop.solve.kinematics import solve
    from mechloop.synthesis.output import write_model
    from mechloop.synthesis.search import synthesize
    from mechloop.views.plan import plan_scene
    from mechloop.web.documents import read_model
    from mechloop.web.payload import diagram, solution

    document = read_model(text, path, root)
    model = document.model
    if model.synthesis is None:
        raise ModelError([Problem(("synthesis",), "the model has no synthesis task",
                                  "add a synthesis: section, see "
                                  "examples/four_bar_path_synthesis.yaml")], path.name)
    total = int(options.get("iterations") or model.synthesis.search.iterations)
    drawn = [-float("inf"), float("inf")]  # when last drawn, the best total drawn

    def report(p: Any) -> None:
        item: dict[str, Any] = {"iteration": min(p.iteration, total), "total": total,
                                "best": p.best_q if p.feasible else None,
                                "best_total": p.best_total, "feasible": p.feasible,
                                "elapsed": p.elapsed}
        now = time.monotonic()
        if p.best_model is not None and p.best_total < drawn[1] and \
                now - drawn[0] >= DRAW_SECONDS:
            try:
                item["diagram"] = diagram(plan_scene(solve(p.best_model())))
                drawn[:] = [now, p.best_total]
            except (ModelError, ValueError):
                pass  # a design that cannot be drawn is not drawn; the search goes on
        connection.send(("progress", item))

    try:
        result = synthesize(model, iterations=options.get("iterations"),
                            time_budget=options.get("time"), progress=report)
    except ModelError as exc:
        raise document.locate(exc) from None
    data, lines = parse_document(text, path.name)
    mechanism = (_from_group_data(data, str(path), lines, build_it=False)
                 if "groups" in data else None)
    with tempfile.TemporaryDirectory() as folder:
        written = write_model(result, Path(folder) / "best.yaml", mechanism=mechanism)
        best_text = written.read_text(encoding="utf-8")
    answer: dict[str, Any] = {"text": best_text, "stopped": result.stopped,
                              "feasible": bool(result.feasible),
                              "best": float(result.evaluation.q[0]) if result.feasible
                              else None,
                              "values": result.values(), "summary": result.summary()}
    try:
        answer["diagram"] = solution(result.model)["diagram"]
    except ModelError:
        answer["diagram"] = None
    return answer


@dataclass
class Job:
    """One background job and what the page is told about it."""

    id: str
    kind: str
    process: Any
    connection: Any
    started: float
    seconds: float
    state: str = "running"  # running, stopping, done, failed
    progress: dict[str, Any] = field(default_factory=dict)
    diagram: dict[str, Any] | None = None
    result: dict[str, Any] | None = None
    problems: list[dict[str, Any]] = field(default_factory=list)
    cancelled: bool = False
    file: dict[str, Any] | None = None  # an animation, a table: content, type, suffix
    lock: threading.Lock = field(default_factory=threading.Lock)

    def status(self) -> dict[str, Any]:
        with self.lock:
            return {"id": self.id, "kind": self.kind, "state": self.state,
                    "cancelled": self.cancelled, "progress": dict(self.progress),
                    "diagram": self.diagram, "result": self.result,
                    "problems": list(self.problems),
                    "elapsed": time.monotonic() - self.started}


class Jobs:
    """The background jobs of one server."""

    def __init__(self, *, seconds: float = JOB_SECONDS, max_jobs: int = MAX_JOBS):
        self.seconds = seconds
        self.max_jobs = max_jobs
        self.jobs: dict[str, Job] = {}
        self.lock = threading.Lock()

    def running(self) -> list[Job]:
        return [j for j in self.jobs.values() if j.state in ("running", "stopping")]

    def start(self, kind: str, text: str, path: Path, root: Path,
              options: dict[str, Any]) -> Job:
        """Start a job (``kind``: ``synthesis``, or one of :data:`mechloop.web.work.KINDS`
        with its checked ``options``); refused (429) when :data:`MAX_JOBS` run."""
        from mechloop.web import work

        if kind != "synthesis" and kind not in work.KINDS:
            raise WebError(f"no job kind {kind!r}", f"use synthesis, {', '.join(work.KINDS)}",
                           400)
        target, args = ((_synthesis_child, ()) if kind == "synthesis"
                        else (work.child, (kind,)))
        with self.lock:
            if len(self.running()) >= self.max_jobs:
                raise WebError("another job is running",
                               "wait for it to finish, or cancel it", 429)
            context = _context()
            parent, child = context.Pipe(duplex=False)
            process = context.Process(target=target,
                                      args=(child, *args, text, str(path), str(root),
                                            options),
                                      daemon=True)
            try:
                process.start()
            except (OSError, RuntimeError) as exc:
                parent.close()
                raise WebError(f"cannot start the job: {exc}", "try again", 500) from None
            finally:
                child.close()
            job = Job(uuid.uuid4().hex[:12], kind, process, parent, time.monotonic(),
                      self.seconds)
            self.jobs[job.id] = job
            finished = [j for j in self.jobs.values() if j.state in ("done", "failed")]
            for old in finished[:-KEEP_FINISHED]:
                del self.jobs[old.id]
        threading.Thread(target=self._read, args=(job,), daemon=True,
                         name=f"mechloop-job-{job.id}").start()
        return job

    def get(self, job_id: str) -> Job:
        job = self.jobs.get(job_id)
        if job is None:
            raise WebError(f"no job {job_id!r}", "start a job first", 404)
        return job

    def cancel(self, job_id: str) -> Job:
        """Stop the job, keeping the best design found (SIGINT, as Ctrl-C)."""
        job = self.get(job_id)
        with job.lock:
            job.cancelled = True
        self._interrupt(job)
        return job

    def _interrupt(self, job: Job) -> None:
        with job.lock:
            if job.state != "running":
                return
            job.state = "stopping"
        if job.process.pid is not None and job.process.is_alive():
            os.kill(job.process.pid, signal.SIGINT)

    def _read(self, job: Job) -> None:
        """Drain the child's messages until its result, stopping it past its limit."""
        deadline = job.started + job.seconds
        killed_at = None
        try:
            while True:
                now = time.monotonic()
                if now >= deadline and job.state == "running":
                    self._interrupt(job)
                    killed_at = now + GRACE_SECONDS
                if killed_at is None and job.state == "stopping":
                    killed_at = now + GRACE_SECONDS
                if killed_at is not None and now >= killed_at:
                    job.process.kill()
                    self._fail(job, "the job did not stop in time and was killed",
                               "use fewer generations or positions")
                    return
                if not job.connection.poll(0.2):
                    continue
                try:
                    kind, value = job.connection.recv()
                except EOFError:
                    self._fail(job, "the job stopped without a result (out of memory?)",
                               "use fewer positions or a smaller population")
                    return
                with job.lock:
                    if kind == "progress":
                        job.diagram = value.pop("diagram", job.diagram)
                        job.progress = value
                    elif kind == "done":
                        job.file = value.pop("file", None)
                        job.result = value
                        job.diagram = value.get("diagram") or job.diagram
                        job.state = "done"
                        return
                    elif kind == "error":
                        if job.kind != "synthesis" and not job.cancelled and \
                                time.monotonic() >= deadline:
                            from mechloop.web.work import timed_out

                            value = timed_out(job.seconds)
                        job.problems = value
                        job.state = "failed"
                        return
                    else:
                        job.problems = [{"line": None, "path": "", "message":
                                         f"mechloop failed: {value}",
                                         "hint": "please report this with the model"}]
                        job.state = "failed"
                        return
        finally:
            job.connection.close()
            job.process.join(5)
            if job.process.is_alive():
                job.process.kill()

    def _fail(self, job: Job, message: str, hint: str) -> None:
        with job.lock:
            job.problems = [{"line": None, "path": "", "message": message, "hint": hint}]
            job.state = "failed"

    def stop_all(self) -> None:
        """Kill every running child (the server stops)."""
        for job in list(self.jobs.values()):
            if job.process.is_alive():
                job.process.kill()
                job.process.join(5)
