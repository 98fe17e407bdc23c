"""What keeps the web application safe on a shared machine.

* :class:`Workspace` — the one folder the server reads and writes: a relative path is
  accepted only when it stays inside it (no ``..``, no absolute path, no symlink leading
  out, only model files), and so is every file a model names (``{csv: ...}`` tables, the
  ``project:`` documents): :func:`references_outside`.
* :class:`Guard` — an ASGI middleware: the request body is refused past
  :data:`MAX_BODY_BYTES` (413), a request for another host than the served one is refused
  (a web page cannot reach the server by DNS rebinding), a change asked by a page of
  another origin is refused (a page elsewhere cannot save into the folder; the API also
  takes only ``application/json``, which such a page cannot send without the browser
  asking the server first), and with a token (a server
  reachable from other machines) every API request must carry it, as ``?token=`` or the
  ``X-Mechloop-Token`` header (403); the page and its scripts are the package's own.
"""

from __future__ import annotations

import hmac
import json
import os
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path, PurePosixPath
from typing import Any
from urllib.parse import parse_qs

from mechloop.errors import HintedError
from mechloop.model.limits import MAX_DOCUMENT_BYTES

#: Largest request body, bytes: a model file at its limit, with room for the JSON quoting.
MAX_BODY_BYTES = MAX_DOCUMENT_BYTES + 64 * 1024
#: The suffixes of the model files the server lists, reads and writes.
MODEL_SUFFIXES = (".yaml", ".yml", ".json")
#: Most model files listed (a server started in a large folder stays responsive).
MAX_LISTED = 500
#: Folders never listed.
SKIPPED_DIRS = {".git", ".venv", "venv", "node_modules", "__pycache__", ".mypy_cache"}
TOKEN_HEADER = "x-mechloop-token"


class WebError(HintedError):
    """A request the server refuses: the message, the fix and the HTTP status."""

    def __init__(self, message: str, hint: str = "", status: int = 400):
        super().__init__(message, hint)
        self.status = status

    def __reduce__(self):
        return (type(self), (self.message, self.hint, self.status))


@dataclass(frozen=True)
class Workspace:
    """The folder the server was started in (``root``, resolved)."""

    root: Path

    @classmethod
    def at(cls, folder: str | os.PathLike[str]) -> Workspace:
        root = Path(folder).resolve()
        if not root.is_dir():
            raise WebError(f"{folder} is not a folder", "give a model file or a folder")
        return cls(root)

    def resolve(self, relative: str, *, exists: bool = True) -> Path:
        """The file ``relative`` (a path inside the folder, written with ``/``) — refused
        when absolute, with ``..``, leading out through a symlink, not a model file or
        (``exists``) missing."""
        if not isinstance(relative, str) or not relative.strip() or "\x00" in relative:
            raise WebError("no file named", "give the path of a model file in the folder")
        pure = PurePosixPath(relative.replace("\\", "/"))
        if pure.is_absolute() or (pure.parts and ":" in pure.parts[0]):
            raise WebError(f"{relative!r} is an absolute path",
                           "give a path relative to the folder the server was started in",
                           403)
        if any(part == ".." for part in pure.parts):
            raise WebError(f"{relative!r} leads out of the folder",
                           "give a path inside the folder the server was started in", 403)
        target = (self.root / pure).resolve()
        if not target.is_relative_to(self.root):
            raise WebError(f"{relative!r} leads out of the folder (a symbolic link)",
                           "give a path inside the folder the server was started in", 403)
        if target.suffix.lower() not in MODEL_SUFFIXES:
            raise WebError(f"{relative!r} is not a model file",
                           f"give a file ending in {', '.join(MODEL_SUFFIXES)}", 403)
        if exists and not target.is_file():
            raise WebError(f"{relative!r} not found", "pick a file from the list", 404)
        return target

    def relative(self, path: Path) -> str:
        return path.relative_to(self.root).as_posix()

    def models(self) -> list[str]:
        """The model files in the folder and its subfolders (at most :data:`MAX_LISTED`),
        sorted; symbolic links leading out are left out."""
        found: list[str] = []
        for folder, dirs, files in os.walk(self.root):
            dirs[:] = sorted(d for d in dirs if d not in SKIPPED_DIRS and not d.startswith("."))
            for name in sorted(files):
                path = Path(folder) / name
                if path.suffix.lower() in MODEL_SUFFIXES and \
                        path.resolve().is_relative_to(self.root):
                    found.append(self.relative(path))
                    if len(found) >= MAX_LISTED:
                        return found
        return found


def file_references(data: Any, path: tuple = ()) -> Iterable[tuple[tuple, str]]:
    """Every file the plain data of a model names: its ``{csv: FILE}`` tables and its
    ``project:`` documents (``cam``, ``gears``) — (the path in the document, FILE)."""
    if not path and isinstance(data, dict) and isinstance(data.get("project"), dict):
        for key in ("cam", "gears"):
            if isinstance(data["project"].get(key), str):
                yield ("project", key), data["project"][key]
    if isinstance(data, dict):
        if isinstance(data.get("csv"), str):
            yield path, data["csv"]
        for key, value in data.items():
            yield from file_references(value, (*path, key))
    elif isinstance(data, list):
        for index, value in enumerate(data):
            yield from file_references(value, (*path, index))


def references_outside(data: Any, base: Path, root: Path) -> list[tuple[tuple, str]]:
    """The files ``data`` names (relative to ``base``) that lie outside ``root``: (path
    in the document, file)."""
    outside = []
    for where, name in file_references(data):
        target = Path(name) if Path(name).is_absolute() else base / name
        if not target.resolve().is_relative_to(root):
            outside.append((where, name))
    return outside


class Guard:
    """ASGI middleware: body size limit, allowed hosts, token (see the module docstring)."""

    def __init__(self, app: Any, *, token: str | None = None,
                 hosts: Iterable[str] | None = None, max_body: int = MAX_BODY_BYTES):
        self.app = app
        self.token = token
        self.hosts = None if hosts is None else {h.lower() for h in hosts}
        self.max_body = max_body

    async def __call__(self, scope: dict, receive: Any, send: Any) -> None:
        if scope["type"] != "http":
            await self.app(scope, receive, send)
            return
        headers = {k.decode("latin-1").lower(): v.decode("latin-1")
                   for k, v in scope.get("headers", [])}
        refused = self._refusal(scope, headers)
        if refused is not None:
            await _reply(send, *refused)
            return
        length = headers.get("content-length")
        if length is not None and (not length.isdigit() or int(length) > self.max_body):
            await _reply(send, 413, *self._too_large())
            return
        body = bytearray()  # read here, so the limit holds however the app reads it
        more = True
        while more:
            message = await receive()
            if message["type"] != "http.request":
                return  # the client went away
            body += message.get("body", b"")
            if len(body) > self.max_body:
                await _reply(send, 413, *self._too_large())
                return
            more = message.get("more_body", False)
        sent = False

        async def replay() -> dict:
            nonlocal sent
            if sent:
                return await receive()
            sent = True
            return {"type": "http.request", "body": bytes(body), "more_body": False}

        await self.app(scope, replay, send)

    def _too_large(self) -> tuple[str, str]:
        return (f"the request is larger than {self.max_body // 1024} KiB",
                "keep the model under 2 MiB (long tables go in CSV files)")

    def _refusal(self, scope: dict, headers: dict[str, str]) -> tuple[int, str, str] | None:
        host = headers.get("host", "").lower()
        name = host.rsplit(":", 1)[0] if not host.endswith("]") else host
        if self.hosts is not None and name.strip("[]") not in self.hosts:
            return (403, f"host {host!r} is not served here",
                    "open the address mechloop serve printed")
        origin = headers.get("origin")
        if scope.get("method", "GET") not in ("GET", "HEAD") and origin is not None and \
                origin.lower().split("://", 1)[-1] != host:
            return (403, f"a request from the page {origin!r} is refused",
                    "use the page mechloop serve printed")
        if self.token is None or not scope.get("path", "").startswith("/api/"):
            return None  # the page and its scripts are the package's, the same for all
        query = parse_qs(scope.get("query_string", b"").decode("latin-1"))
        given = headers.get(TOKEN_HEADER) or (query.get("token") or [""])[0]
        if not hmac.compare_digest(given.encode(), self.token.encode()):
            return (403, "a token is required",
                    "open the address with ?token=... that mechloop serve printed")
        return None


async def _reply(send: Any, status: int, message: str, hint: str) -> None:
    body = json.dumps({"error": message, "hint": hint}).encode()
    await send({"type": "http.response.start", "status": status,
                "headers": [(b"content-type", b"application/json"),
                            (b"content-length", str(len(body)).encode())]})
    await send({"type": "http.response.body", "body": body})
