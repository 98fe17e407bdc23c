"""The page's other work that takes time, as background jobs beside the synthesis
(:mod:`mechloop.web.jobs`): an animation, a parametric sweep, a simulation.

Each kind runs the library's own function in a child of the fork server, as the CLI
command does, and reports ``("progress", {"done", "total"})`` at most every
:data:`PROGRESS_SECONDS`:

* ``animation`` (``mechloop animate``): :func:`mechloop.views.animation.animate`, one
  frame per position (the dynamics' plan when the model has bodies); ``format`` gif, mp4
  or html, ``fps`` optional; progress in frames; the file is the animation;
* ``sweep`` (``mechloop sweep``): :func:`mechloop.synthesis.sweep.sweep`, serial, with
  ``vary`` (one or two ``PATH=VALUES``, at most :data:`MAX_SWEEP_DESIGNS` designs) and
  ``collect`` (``COLUMN:REDUCTION``); progress in designs; the result is the table (as
  JSON rows) and its plot (:func:`mechloop.views.sweep.plot_sweep`, SVG), the file the
  table as CSV;
* ``simulation`` (``mechloop simulate``): :func:`mechloop.dynamics.simulate.simulate` of
  the model's ``simulate:`` section (``duration``, ``cycles`` override it, as the CLI's
  options); progress in simulated seconds; the result is the run's summary and its
  curves (:func:`mechloop.views.motion.plot_simulation`, SVG), the file the time series
  as CSV.

The request's options are checked in the server (:func:`job_options`: a clear 400 with
the library's message before any child starts); what only the model can tell (a path
that is not in it, a column it has not, no ``simulate:`` section) fails the job with the
problems located by line.  Cancelling (SIGINT) stops the child; these kinds have no best
design to keep, so the job ends ``failed`` with ``cancelled`` set.
"""

from __future__ import annotations

import math
import os
import signal
import tempfile
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

from mechloop.web.safety import WebError

#: The job kinds of this module.
KINDS = ("animation", "sweep", "simulation")
#: Content types of an animation, by format.
ANIMATION_TYPES = {"gif": "image/gif", "mp4": "video/mp4",
                   "html": "text/html; charset=utf-8"}
#: Most designs of one sweep from the page (a grid of 20 × 20).
MAX_SWEEP_DESIGNS = 400
#: Most quantities collected by one sweep.
MAX_QUANTITIES = 12
#: Largest frame rate asked for an animation, 1/s.
MAX_FPS = 100.0
#: Least time between two progress reports of the child, s.
PROGRESS_SECONDS = 0.1

Send = Callable[[float, float], None]


def _positive(data: dict[str, Any], key: str, kind: type, limit: float | None = None
              ) -> Any:
    value = data.get(key)
    if value is None:
        return None
    if isinstance(value, bool) or not isinstance(value, int | float) \
            or not math.isfinite(value) or value <= 0:
        raise WebError(f"{key!r} is not a positive number", f"give {key} > 0")
    if kind is int and value != int(value):
        raise WebError(f"{key!r} is not a whole number", f"give a whole number of {key}")
    if limit is not None and value > limit:
        raise WebError(f"{key!r} is {value:g}, more than {limit:g}",
                       f"give {key} of at most {limit:g}")
    return kind(value)


def _strings(data: dict[str, Any], key: str, example: str) -> list[str]:
    value = data.get(key)
    if isinstance(value, str):
        value = [value]
    if (not isinstance(value, list) or not value
            or not all(isinstance(v, str) and v.strip() for v in value)):
        raise WebError(f"{key!r} is not a list of texts", f'send e.g. {{"{key}": '
                       f'["{example}"]}}')
    return [v.strip() for v in value]


def job_options(kind: str, data: dict[str, Any]) -> dict[str, Any]:
    """The options of a job of ``kind`` read from the request ``data`` — a
    :class:`WebError` (400) naming what is wrong, or the library's
    :class:`~mechloop.synthesis.sweep.SweepError` for a ``vary`` it cannot read."""
    from mechloop.web.exports import language, pick

    lang = language(data.get("lang", "en"))
    if kind == "animation":
        return {"format": pick("animation", data.get("format", "gif"), ANIMATION_TYPES),
                "fps": _positive(data, "fps", float, MAX_FPS)}
    if kind == "sweep":
        from mechloop.synthesis.sweep import MAX_PARAMETERS, parse_vary

        vary = _strings(data, "vary", "time.rpm=1000:4000:7")
        if len(vary) > MAX_PARAMETERS:
            raise WebError(f"{len(vary)} parameters to vary; a sweep varies one or "
                           f"{MAX_PARAMETERS}", "vary one parameter, or two for a grid")
        pairs = [parse_vary(text) for text in vary]
        designs = math.prod(len(values) for _, values in pairs)
        if designs > MAX_SWEEP_DESIGNS:
            raise WebError(f"the sweep has {designs} designs; the page runs at most "
                           f"{MAX_SWEEP_DESIGNS}", "use fewer values, or run mechloop "
                           "sweep from the command line")
        collect = _strings(data, "collect", "M_bal:max")
        if len(collect) > MAX_QUANTITIES:
            raise WebError(f"{len(collect)} quantities to collect; at most "
                           f"{MAX_QUANTITIES}", "collect fewer quantities")
        return {"vary": pairs, "collect": collect, "lang": lang}
    if kind == "simulation":
        return {"duration": _positive(data, "duration", float),
                "cycles": _positive(data, "cycles", int), "lang": lang}
    raise WebError(f"no job kind {kind!r}", f"use synthesis, {', '.join(KINDS)}")


def child(connection: Any, kind: str, text: str, path: str, root: str,
          options: dict[str, Any]) -> None:
    """The child: do the work of ``kind`` for the model in ``text``, sending
    ``("progress", {"done", "total"})`` items and finally ``("done", {...})`` (its
    ``file``: ``{"content", "type", "suffix"}``) or ``("error", problems)`` /
    ``("crash", message)``."""
    signal.signal(signal.SIGINT, signal.default_int_handler)  # cancel = Ctrl-C
    from mechloop.errors import MechloopError, ModelError
    from mechloop.web.documents import problems, read_model

    last = [0.0]

    def send(done: float, total: float) -> None:
        now = time.monotonic()
        if now - last[0] >= PROGRESS_SECONDS or done >= total:
            last[0] = now
            connection.send(("progress", {"done": float(done), "total": float(total)}))

    try:
        try:
            document = read_model(text, Path(path), Path(root))
            try:
                answer = WORK[kind](document.model, options, send)
            except ModelError as exc:
                raise document.locate(exc) from None
            connection.send(("done", answer))
        except KeyboardInterrupt:
            connection.send(("error", [{"line": None, "path": "", "message":
                                        "the job was cancelled",
                                        "hint": "start it again to get its result"}]))
        except MechloopError as exc:
            connection.send(("error", problems(exc)))
        except Exception as exc:  # reported to the page, with its cause
            connection.send(("crash", f"{type(exc).__name__}: {exc}"))
    finally:
        connection.close()
        os._exit(0)


def _written(suffix: str, write: Callable[[Path], Any]) -> bytes:
    with tempfile.TemporaryDirectory(prefix="mechloop-web-") as folder:
        target = Path(folder) / f"work{suffix}"
        write(target)
        return target.read_bytes()


def _svg(figure: Any, lang: str) -> str:
    from mechloop.views.figure import save_figure
    from mechloop.views.russian import translate

    return _written(".svg", lambda t: save_figure(translate(figure, lang), t)
                    ).decode("utf-8")


def _csv(frame: Any) -> bytes:
    from mechloop.output.tables import write_frame

    return _written(".csv", lambda t: write_frame(frame, t))


def _number(value: Any) -> Any:
    """A table cell as JSON: a float NaN or inf as None, NumPy scalars as Python's."""
    if hasattr(value, "item"):
        value = value.item()
    if isinstance(value, float) and not math.isfinite(value):
        return None
    return value


def animation(model: Any, options: dict[str, Any], send: Send) -> dict[str, Any]:
    """The model's motion as an animation file (``mechloop animate``)."""
    from mechloop.dynamics.analysis import solve_dynamics
    from mechloop.solve.kinematics import solve
    from mechloop.views.animation import animate

    spatial = any(c.spatial for c in model.contours)
    results = solve_dynamics(model) if model.bodies and not spatial else solve(model)
    if spatial:  # issue 17: the 3-D plan (the HTML file: the interactive 3-D view)
        from mechloop.views.spatial_animation import animate_spatial as animate
    frames = [0]

    def progress(done: int, total: int) -> None:
        frames[0] = total
        send(done, total)

    fmt = options["format"]
    content = _written(f".{fmt}", lambda t: animate(results, t, fps=options["fps"],
                                                    progress=progress))
    return {"frames": frames[0], "format": fmt, "size": len(content),
            "file": {"content": content, "type": ANIMATION_TYPES[fmt],
                     "suffix": f".{fmt}"}}


def sweep(model: Any, options: dict[str, Any], send: Send) -> dict[str, Any]:
    """The sweep's table and plot (``mechloop sweep``), solved serially."""
    from mechloop.output.display import TableDisplay, plot_display
    from mechloop.synthesis.sweep import sweep as run_sweep
    from mechloop.views.sweep import plot_sweep

    frame = run_sweep(model, options["vary"], options["collect"], scheduler="serial",
                      progress=send)
    columns = [str(c) for c in frame.columns]
    rows = [[_number(v) for v in row] for row in frame.itertuples(index=False)]
    figure = plot_sweep(frame, display=plot_display(TableDisplay({})))
    return {"columns": columns, "rows": rows,
            "parameters": list(frame.attrs["parameters"]),
            "quantities": list(frame.attrs["quantities"]),
            "svg": _svg(figure, options["lang"]),
            "file": {"content": _csv(frame), "type": "text/csv; charset=utf-8",
                     "suffix": "-sweep.csv"}}


def simulation(model: Any, options: dict[str, Any], send: Send) -> dict[str, Any]:
    """The run of the model's ``simulate:`` section (``mechloop simulate``): a summary,
    its curves (SVG) and its time series."""
    from mechloop.dynamics.analysis import solve_dynamics
    from mechloop.dynamics.motors import RPM
    from mechloop.dynamics.simulate import simulate
    from mechloop.dynamics.simulate_inputs import InputsSimulation
    from mechloop.dynamics.simulate_summary import summary_lines
    from mechloop.errors import ModelError, Problem
    from mechloop.views.motion import plot_simulation

    settings = model.simulate
    if settings is None:
        raise ModelError([Problem(("simulate",), "the model has no simulate: section",
                                  "add simulate: {motor: {kloss: ...}, duration: 5}")])
    changed = {key: options[key] for key in ("duration", "cycles")
               if options.get(key) is not None}
    if changed:
        settings = settings.model_copy(update=changed)
    sim = simulate(model, settings, dynamics=solve_dynamics(model), progress=send)
    summary: dict[str, Any] = {"rows": int(sim.time.size), "end": float(sim.time[-1])}
    if isinstance(sim, InputsSimulation):
        summary["lines"] = [text for text, _ in summary_lines(sim, options["lang"])]
    else:
        summary["cycles"] = int(sim.cycle_time.size)
        summary["steady"] = None if sim.steady_time is None else float(sim.steady_time)
        summary["speed"] = (float(sim.cycle_speed[-1] / RPM) if sim.cycle_time.size
                            else None)
        summary["events"] = [event.describe(options["lang"]) for event in sim.events[1:]]
    frame = sim.to_frame()
    return {"summary": summary, "columns": [str(c) for c in frame.columns],
            "svg": _svg(plot_simulation(sim, title=model.name or ""), options["lang"]),
            "file": {"content": _csv(frame), "type": "text/csv; charset=utf-8",
                     "suffix": "-simulation.csv"}}


#: The work of each kind: ``work(model, options, send) -> result`` (run in the child).
WORK: dict[str, Callable[[Any, dict[str, Any], Send], dict[str, Any]]] = {
    "animation": animation, "sweep": sweep, "simulation": simulation}


def job_file(job: Any) -> dict[str, Any]:
    """The file a finished job made (``content``, ``type``, ``suffix``) — a
    :class:`WebError` while it runs (409) or when it made none (404)."""
    if job.state in ("running", "stopping"):
        raise WebError("the job is still running", "download its file when it is done",
                       409)
    if job.file is None:
        raise WebError("the job made no file",
                       "an animation, a sweep or a simulation that finished makes one", 404)
    return job.file


def timed_out(seconds: float) -> list[dict[str, Any]]:
    """The problem of a job of this module stopped at its time limit (not cancelled)."""
    return [{"line": None, "path": "", "message":
             f"the job took longer than {seconds:g} s and was stopped",
             "hint": "use fewer values, fewer positions or a shorter duration"}]
