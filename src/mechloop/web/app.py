"""The routes of the web application (Starlette).

Pages: ``/`` (the application) and ``/static/...`` (its scripts and styles, shipped in
the package).  The API takes and gives JSON; a model is always sent as its text with the
file it belongs to (``{"path": "models/a.yaml"}`` in the served folder, or
``{"example": "crank_slider"}`` among the bundled examples):

* ``GET /api/models`` — the model files of the folder and the bundled examples;
* ``GET /api/model?path=...`` or ``?example=...`` — the text of one;
* ``POST /api/validate`` ``{text, path|example}`` — ``{ok, problems}``, each problem with
  its line, YAML path, message and fix;
* ``POST /api/solve`` — the diagram of every position, the breaks and the results table
  (:func:`mechloop.web.payload.solution`), and the ``structure`` in English and Russian
  (:func:`mechloop.web.exports.structures`, from the same kinematics), computed in a child
  process with a time limit;
* ``POST /api/save`` ``{text, path}`` — written atomically inside the folder;
* ``POST /api/report`` ``{text, path|example, lang, format}`` — the report, ``pdf``
  (default) or ``docx``;
* ``POST /api/table`` ``{text, path|example, format}`` — the results table, ``csv``,
  ``xlsx`` or ``json``, in the model's display units;
* ``POST /api/figure`` ``{text, path|example, names, format, lang}`` — a plot of up to
  six parameters, ``png`` or ``svg``;
* ``POST /api/structure`` ``{text, path|example}`` — the structure formula, the Assur
  groups and the mobility (:func:`mechloop.web.exports.structure`);
* ``POST /api/view`` ``{text, path|example, kind, names, joint, position, op, lang,
  format}`` — one of the other views of ``mechloop plot`` (:mod:`mechloop.web.views`):
  ``svg`` (default) or ``png``, or ``data``: the JSON of the page's interactive plot
  read back from the same figure (:func:`mechloop.web.views.view_data`);
* ``POST /api/jobs`` ``{text, path|example, kind: "synthesis", iterations?, time?}`` —
  a background job (:mod:`mechloop.web.jobs`), ``{id}``; ``GET /api/jobs/{id}`` — its
  state, progress, best design so far and result; ``POST /api/jobs/{id}/cancel`` — stop
  it, keeping the best;
* ``POST /api/jobs`` with ``kind`` ``animation`` ``{format, fps?}``, ``sweep``
  ``{vary, collect, lang}`` or ``simulation`` ``{duration?, cycles?, lang}``
  (:mod:`mechloop.web.work`); ``GET /api/jobs/{id}/file`` — the file a finished one made
  (the animation; the table of a sweep or a simulation as CSV);
* ``POST /api/edit`` ``{text, path|example, keys, value | delete: true | key}`` —
  ``{text, data}``: the text with one value set, one entry deleted or one key renamed at
  the key path ``keys`` (``["vectors", 1, "r"]``), every other byte kept
  (:mod:`mechloop.web.edit`), and the plain data of the new text;
  ``POST /api/data`` ``{text}`` — ``{data}``: the text's plain data, as the page's forms
  read it;
* ``GET /api/autosave?path=...|example=...`` — the working copy of a model
  (:mod:`mechloop.web.autosave`): ``{text, time, differs}`` (``text`` null when there is
  none); ``POST /api/autosave`` ``{text, path|example}`` — keep it (removed when it equals
  the file); ``POST /api/autosave/clear`` — discard it;
* ``GET /api/templates`` — the bundled models a new model can start from
  (:mod:`mechloop.web.templates`); ``GET /api/template?name=...`` — the text of one and the
  file name it is offered to be saved as;
* ``GET /api/units`` — the choices of the Units tab: each kind of quantity of the
  ``display:`` section with its units and default unit, the ranges of ``digits`` and
  ``decimals`` (:mod:`mechloop.web.units`).  ``POST /api/save`` with ``template`` also copies
  the files the model names from beside the template.

Every refusal is JSON ``{"error", "hint", "problems"}`` with a 4xx/5xx status; a model
error is 422 with every problem located by line.  Messages and fixes are in the page's
language (:mod:`mechloop.web.language`: the ``X-Mechloop-Lang`` header).
"""

from __future__ import annotations

import contextlib
from pathlib import Path
from typing import Any

import orjson
from starlette.applications import Starlette
from starlette.concurrency import run_in_threadpool
from starlette.requests import Request
from starlette.responses import FileResponse, JSONResponse, Response
from starlette.routing import Mount, Route
from starlette.staticfiles import StaticFiles

from mechloop.bundled.catalog import examples, examples_dir, find_example
from mechloop.dynamics.analysis import DynamicResults
from mechloop.errors import HintedError, MechloopError, ModelError
from mechloop.output.atomic import atomic_write_text
from mechloop.web import exports, templates, work
from mechloop.web.autosave import working_copy
from mechloop.web.documents import problems, read_model
from mechloop.web.edit import edit_text, json_data
from mechloop.web.jobs import JOB_SECONDS, Jobs
from mechloop.web.language import problems_in, request_language
from mechloop.web.payload import solution, solve_model
from mechloop.web.safety import Guard, WebError, Workspace
from mechloop.web.units import unit_choices
from mechloop.web.views import VIEW_TYPES, view_data, view_svg
from mechloop.web.worker import REPORT_SECONDS, SOLVE_SECONDS, WorkFailed, run_limited

STATIC = Path(__file__).parent / "static"


class _JSON(Response):
    """A JSON response by orjson (NumPy arrays as lists, NaN as null)."""

    media_type = "application/json"

    def render(self, content: Any) -> bytes:
        return orjson.dumps(content, option=orjson.OPT_SERIALIZE_NUMPY)


def _error(exc: MechloopError, status: int | None = None, lang: str = "en") -> JSONResponse:
    items = problems_in(exc.problems if isinstance(exc, WorkFailed) else problems(exc), lang)
    first = items[0] if items else {"message": str(exc), "hint": ""}
    code = status or getattr(exc, "status", 422 if isinstance(exc, ModelError) else 400)
    return JSONResponse({"error": first["message"], "hint": first["hint"],
                         "problems": items}, status_code=code)


def _solve_text(text: str, path: Path, root: Path) -> bytes:
    """The solution of the model in ``text`` as JSON bytes (run in the child)."""
    document = read_model(text, path, root)
    try:
        solved = solve_model(document.model)
        answer = solution(document.model, solved)
    except ModelError as exc:
        raise document.locate(exc) from None
    # the structure panel's answer from the same kinematics (nothing solved twice)
    answer["structure"] = exports.structures(
        document, solved.kinematics if isinstance(solved, DynamicResults) else solved)
    return orjson.dumps(answer, option=orjson.OPT_SERIALIZE_NUMPY)


def create_app(folder: str | Path, *, token: str | None = None,
               hosts: list[str] | None = None, solve_seconds: float = SOLVE_SECONDS,
               report_seconds: float = REPORT_SECONDS, start: str | None = None,
               job_seconds: float = JOB_SECONDS) -> Any:
    """The application serving ``folder``: ``token`` required in every request when given,
    only the ``hosts`` named (None: any; the CLI names the loopback ones), the time limits
    of a solve and a report (s); ``start``: the model (a path in the folder) the page opens
    first."""
    workspace = Workspace.at(folder)
    jobs = Jobs(seconds=job_seconds)

    def source(data: dict[str, Any]) -> tuple[Path, Path]:
        """(the file a request's model belongs to, the folder its tables may come from)."""
        if data.get("example"):
            try:
                found = find_example(str(data["example"]))
            except HintedError as exc:
                raise WebError(exc.message, exc.hint, 404) from None
            if found.path.suffix != ".yaml":
                raise WebError(f"{data['example']!r} is not a model", "pick a model", 404)
            return found.path.resolve(), examples_dir().resolve()
        return workspace.resolve(str(data.get("path", "")), exists=False), workspace.root

    async def body(request: Request) -> dict[str, Any]:
        kind = request.headers.get("content-type", "").split(";")[0].strip().lower()
        if kind != "application/json":
            raise WebError(f"the request is {kind or 'untyped'}, not application/json",
                           "send the JSON with content-type: application/json", 415)
        try:
            data = orjson.loads(await request.body())
        except orjson.JSONDecodeError:
            raise WebError("the request is not JSON", "send a JSON object") from None
        if not isinstance(data, dict):
            raise WebError("the request is not a JSON object", "send a JSON object")
        if "text" in data and not isinstance(data["text"], str):
            raise WebError("'text' is not a string", "send the model's text")
        return data

    def guarded(handler: Any) -> Any:
        async def endpoint(request: Request) -> Response:
            try:
                return await handler(request)
            except MechloopError as exc:
                return _error(exc, lang=request_language(request.headers,
                                                         request.query_params))
        return endpoint

    async def index(request: Request) -> Response:
        return FileResponse(STATIC / "index.html", headers={"cache-control": "no-store"})

    async def models(request: Request) -> Response:
        listed = [{"id": e.stem, "title": e.title, "title_ru": e.title_ru or e.title,
                   "number": e.number} for e in examples() if e.path.suffix == ".yaml"]
        files = await run_in_threadpool(workspace.models)
        return JSONResponse({"folder": workspace.root.name, "files": files,
                             "examples": listed, "start": start})

    async def model(request: Request) -> Response:
        path, _ = source(dict(request.query_params))
        if not path.is_file():
            raise WebError(f"{request.query_params.get('path')!r} not found",
                           "pick a file from the list", 404)
        try:
            text = path.read_text(encoding="utf-8")
        except (OSError, UnicodeDecodeError) as exc:
            raise WebError(f"cannot read the file: {exc}", "save it as UTF-8 text") from None
        return JSONResponse({"text": text})

    async def validate(request: Request) -> Response:
        data = await body(request)
        path, root = source(data)
        try:
            await run_in_threadpool(read_model, data.get("text", ""), path, root)
        except MechloopError as exc:
            lang = request_language(request.headers, request.query_params)
            return JSONResponse({"ok": False, "problems": problems_in(problems(exc), lang)})
        return JSONResponse({"ok": True, "problems": []})

    async def solve(request: Request) -> Response:
        data = await body(request)
        path, root = source(data)
        payload = await run_in_threadpool(run_limited, _solve_text, data.get("text", ""),
                                          path, root, seconds=solve_seconds)
        return Response(payload, media_type="application/json")

    async def save(request: Request) -> Response:
        data = await body(request)
        if data.get("example"):
            raise WebError("a bundled example cannot be overwritten",
                           "save it under a file name in the folder", 403)
        path = workspace.resolve(str(data.get("path", "")), exists=False)
        if not path.parent.is_dir():
            raise WebError(f"no folder {workspace.relative(path.parent)!r}",
                           "save into an existing folder", 404)
        template = templates.template(str(data["template"])) if data.get("template") \
            else None
        await run_in_threadpool(atomic_write_text, path, data.get("text", ""))
        answer: dict[str, Any] = {"saved": workspace.relative(path)}
        if template is not None:  # a new model: the files it names, copied beside it
            answer["copied"] = await run_in_threadpool(
                templates.copy_companions, data.get("text", ""), template, path, workspace)
        working_copy(workspace, path=workspace.relative(path)).clear()
        return JSONResponse(answer)

    def copy_of(data: Any) -> Any:
        """The working copy of the model a request names (``path`` or ``example``)."""
        if data.get("example"):
            return working_copy(workspace, example=templates.template(str(data["example"])))
        return working_copy(workspace, path=str(data.get("path", "")))

    async def autosave_get(request: Request) -> Response:
        copy = copy_of(request.query_params)
        found = await run_in_threadpool(copy.read)
        if found is None:
            return JSONResponse({"text": None, "time": None, "differs": False})
        text, when = found
        return JSONResponse({"text": text, "time": when, "differs": copy.differs(text)})

    async def autosave_put(request: Request) -> Response:
        data = await body(request)
        copy = copy_of(data)
        text = data.get("text", "")
        if not copy.differs(text):  # back to the file: nothing to keep
            await run_in_threadpool(copy.clear)
            return JSONResponse({"kept": False})
        await run_in_threadpool(copy.write, text)
        return JSONResponse({"kept": True})

    async def autosave_clear(request: Request) -> Response:
        data = await body(request)
        return JSONResponse({"cleared": await run_in_threadpool(copy_of(data).clear)})

    async def template_list(request: Request) -> Response:
        return JSONResponse({"templates": templates.listing()})

    async def template_text(request: Request) -> Response:
        path = templates.template(request.query_params.get("name", ""))
        return JSONResponse({"id": path.stem, "file": path.name,
                             "text": path.read_text(encoding="utf-8")})

    def attachment(content: bytes, kind: str, path: Path, suffix: str) -> Response:
        name = (path.stem or "model") + suffix
        return Response(content, media_type=kind,
                        headers={"content-disposition": f'attachment; filename="{name}"'})

    async def report(request: Request) -> Response:
        data = await body(request)
        path, root = source(data)
        lang = exports.language(data.get("lang", "en"))
        fmt = exports.pick("report", data.get("format", "pdf"), exports.REPORT_TYPES)
        content = await run_in_threadpool(run_limited, exports.report_file,
                                          data.get("text", ""), path, root, lang, fmt,
                                          seconds=report_seconds)
        return attachment(content, exports.REPORT_TYPES[fmt], path, f".{fmt}")

    async def table_download(request: Request) -> Response:
        data = await body(request)
        path, root = source(data)
        fmt = exports.pick("table", data.get("format", "csv"), exports.TABLE_TYPES)
        content = await run_in_threadpool(run_limited, exports.table_file,
                                          data.get("text", ""), path, root, fmt,
                                          seconds=solve_seconds)
        return attachment(content, exports.TABLE_TYPES[fmt], path, f".{fmt}")

    async def figure(request: Request) -> Response:
        data = await body(request)
        path, root = source(data)
        names = exports.curve_names(data.get("names"))
        fmt = exports.pick("figure", data.get("format", "png"), exports.FIGURE_TYPES)
        lang = exports.language(data.get("lang", "en"))
        content = await run_in_threadpool(run_limited, exports.figure_file,
                                          data.get("text", ""), path, root, names, fmt,
                                          lang, seconds=solve_seconds)
        return attachment(content, exports.FIGURE_TYPES[fmt], path, f".{fmt}")

    async def structure(request: Request) -> Response:
        data = await body(request)
        path, root = source(data)
        answer = await run_in_threadpool(run_limited, exports.structure,
                                         data.get("text", ""), path, root,
                                         request_language(request.headers,
                                                          request.query_params),
                                         seconds=solve_seconds)
        return JSONResponse(answer)

    def _number(data: dict[str, Any], key: str, kind: type) -> Any:
        value = data.get(key)
        if value is None:
            return None
        if isinstance(value, bool) or not isinstance(value, int | float) or value <= 0:
            raise WebError(f"{key!r} is not a positive number", f"give {key} > 0")
        return kind(value)

    async def view(request: Request) -> Response:
        data = await body(request)
        path, root = source(data)
        names = [str(n) for n in data.get("names") or []][:6]
        joint = data.get("joint")
        position = data.get("position", 0)
        if isinstance(position, bool) or not isinstance(position, int):
            raise WebError("'position' is not a whole number", "give a position number")
        fmt = exports.pick("figure", data.get("format", "svg"), {**VIEW_TYPES, "data": ""})
        args = (data.get("text", ""), path, root, str(data.get("kind", "")), names,
                None if joint is None else str(joint), position,
                exports.language(data.get("lang", "en")), str(data.get("op") or "ratio"))
        if fmt == "data":
            content = await run_in_threadpool(run_limited, view_data, *args,
                                              seconds=solve_seconds)
            return Response(content, media_type="application/json")
        content = await run_in_threadpool(run_limited, view_svg, *args, fmt,
                                          seconds=solve_seconds)
        return Response(content, media_type=VIEW_TYPES[fmt])

    async def job_start(request: Request) -> Response:
        data = await body(request)
        path, root = source(data)
        kind = str(data.get("kind", "synthesis"))
        options = (work.job_options(kind, data) if kind != "synthesis" else
                   {"iterations": _number(data, "iterations", int),
                    "time": _number(data, "time", float)})
        job = await run_in_threadpool(jobs.start, kind,
                                      data.get("text", ""), path, root, options)
        return JSONResponse({"id": job.id})

    async def job_status(request: Request) -> Response:
        answer = jobs.get(request.path_params["job"]).status()
        answer["problems"] = problems_in(answer["problems"],
                                         request_language(request.headers,
                                                          request.query_params))
        return _JSON(answer)

    async def job_file(request: Request) -> Response:
        file = work.job_file(jobs.get(request.path_params["job"]))
        return attachment(file["content"], file["type"], Path("model"), file["suffix"])

    async def job_cancel(request: Request) -> Response:
        job = await run_in_threadpool(jobs.cancel, request.path_params["job"])
        return _JSON(job.status())

    def file_name(data: dict[str, Any]) -> str:
        """The name of the file a text belongs to (its errors carry it; ``.json``: the
        edits write JSON)."""
        return source(data)[0].name if data.get("path") or data.get("example") \
            else "model.yaml"

    async def edit(request: Request) -> Response:
        data = await body(request)
        name = file_name(data)

        def change() -> dict[str, Any]:
            text = edit_text(data.get("text", ""), data.get("keys"), value=data.get("value"),
                             delete=data.get("delete") is True, key=data.get("key"),
                             file=name)
            return {"text": text, "data": json_data(text, name)}
        return JSONResponse(await run_in_threadpool(change))

    async def plain_data(request: Request) -> Response:
        data = await body(request)
        return JSONResponse({"data": await run_in_threadpool(
            json_data, data.get("text", ""), file_name(data))})

    async def units(request: Request) -> Response:
        return JSONResponse(await run_in_threadpool(unit_choices))

    routes = [Route("/", index),
              Route("/api/models", guarded(models)),
              Route("/api/model", guarded(model)),
              Route("/api/validate", guarded(validate), methods=["POST"]),
              Route("/api/solve", guarded(solve), methods=["POST"]),
              Route("/api/save", guarded(save), methods=["POST"]),
              Route("/api/autosave", guarded(autosave_get)),
              Route("/api/autosave", guarded(autosave_put), methods=["POST"]),
              Route("/api/autosave/clear", guarded(autosave_clear), methods=["POST"]),
              Route("/api/templates", guarded(template_list)),
              Route("/api/template", guarded(template_text)),
              Route("/api/report", guarded(report), methods=["POST"]),
              Route("/api/table", guarded(table_download), methods=["POST"]),
              Route("/api/figure", guarded(figure), methods=["POST"]),
              Route("/api/structure", guarded(structure), methods=["POST"]),
              Route("/api/view", guarded(view), methods=["POST"]),
              Route("/api/jobs", guarded(job_start), methods=["POST"]),
              Route("/api/edit", guarded(edit), methods=["POST"]),
              Route("/api/data", guarded(plain_data), methods=["POST"]),
              Route("/api/units", guarded(units)),
              Route("/api/jobs/{job}", guarded(job_status)),
              Route("/api/jobs/{job}/cancel", guarded(job_cancel), methods=["POST"]),
              Route("/api/jobs/{job}/file", guarded(job_file)),
              Mount("/static", StaticFiles(directory=STATIC), name="static")]
    @contextlib.asynccontextmanager
    async def lifespan(app: Any) -> Any:
        try:
            yield
        finally:
            jobs.stop_all()  # no synthesis outlives the server

    app = Starlette(routes=routes, lifespan=lifespan)
    app.state.jobs = jobs
    return Guard(app, token=token, hosts=hosts)
