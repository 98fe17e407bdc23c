"""``mechloop serve``: the web application on this machine.

By default the server listens on 127.0.0.1 (this machine only) on a free port and opens the
browser at its address.  With another ``host`` (reachable from other machines) it prints a
warning and requires a random token, which the printed address carries.
"""

from __future__ import annotations

import ipaddress
import secrets
import socket
import webbrowser
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from urllib.parse import quote

from mechloop.web.safety import MODEL_SUFFIXES, WebError, Workspace

LOOPBACK_NAMES = ("127.0.0.1", "localhost", "::1")


def is_loopback(host: str) -> bool:
    """Whether ``host`` is reachable from this machine only."""
    if host == "localhost":
        return True
    try:
        return ipaddress.ip_address(host).is_loopback
    except ValueError:
        return False


def free_port(host: str = "127.0.0.1") -> int:
    """A TCP port free on ``host`` now (chosen by the system)."""
    family = socket.AF_INET6 if ":" in host else socket.AF_INET
    with socket.socket(family, socket.SOCK_STREAM) as probe:
        probe.bind((host, 0))
        return int(probe.getsockname()[1])


@dataclass(frozen=True)
class Plan:
    """What the server serves and where: the folder, the model opened first (relative to
    the folder, or None), host, port, token (None on loopback) and the address to open."""

    folder: Path
    start: str | None
    host: str
    port: int
    token: str | None

    @property
    def url(self) -> str:
        shown = "127.0.0.1" if self.host in ("0.0.0.0", "") else self.host
        shown = f"[{shown}]" if ":" in shown else shown
        query = f"?token={self.token}" if self.token else ""
        if self.start:  # a file name with a space, & or # stays one name in the address
            query += ("&" if query else "?") + f"path={quote(self.start)}"
        return f"http://{shown}:{self.port}/{query}"

    @property
    def hosts(self) -> list[str] | None:
        """The Host names the server answers (None: any — the token guards it)."""
        return list(LOOPBACK_NAMES) if self.token is None else None


def plan(target: Path | None, host: str = "127.0.0.1", port: int | None = None) -> Plan:
    """The :class:`Plan` for ``mechloop serve [target]`` (a model file or a folder;
    default: the current folder)."""
    target = Path.cwd() if target is None else target
    if target.is_file():
        if target.suffix.lower() not in MODEL_SUFFIXES:
            raise WebError(f"{target} is not a model file",
                           f"give a {', '.join(MODEL_SUFFIXES)} file or a folder")
        folder, start = target.resolve().parent, target.resolve().name
    elif target.is_dir():
        folder, start = target.resolve(), None
    else:
        raise WebError(f"{target} not found", "give a model file or a folder")
    Workspace.at(folder)
    if port is not None and not 0 < port < 65536:
        raise WebError(f"port {port} is out of range", "use 1 to 65535, or leave it out")
    token = None if is_loopback(host) else secrets.token_urlsafe(24)
    try:
        chosen = port if port is not None else free_port(host)
    except OSError as exc:
        raise WebError(f"cannot listen on {host}: {exc.strerror or exc}",
                       "give an address of this machine with --host") from None
    return Plan(folder, start, host, chosen, token)


def run(target: Path | None, *, host: str = "127.0.0.1", port: int | None = None,
        browser: bool = True, say: Callable[[str], None] = print,
        solve_seconds: float | None = None) -> None:
    """Serve until interrupted (Ctrl+C)."""
    import uvicorn

    from mechloop.web.app import create_app
    from mechloop.web.worker import SOLVE_SECONDS, warm_up

    chosen = plan(target, host, port)
    warm_up()  # the fork server of the solves imports mechloop now, not at the first solve
    app = create_app(chosen.folder, token=chosen.token, hosts=chosen.hosts,
                     solve_seconds=solve_seconds or SOLVE_SECONDS, start=chosen.start)
    if chosen.token is not None:
        say(f"warning: serving {chosen.folder} on {host}, reachable from other machines; "
            "anyone with the address below can read and write the model files there (from "
            "another machine, put this machine's address in place of 127.0.0.1)")
    say(f"mechloop serves {chosen.folder} at {chosen.url}  (Ctrl+C stops it)")
    if browser:
        webbrowser.open(chosen.url)
    uvicorn.run(app, host=host, port=chosen.port, log_level="warning")
