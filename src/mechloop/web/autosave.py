"""The working copy of the model in the editor: saved as it is typed, so nothing is lost
on a browser crash or a bad edit.

The working copy of a model lives inside the served folder, in
``.mechloop/autosave/`` (a hidden folder, never listed among the models):
``files/<path>`` for a file of the folder and ``examples/<name>.yaml`` for a bundled
example (or a new model made from one, not yet saved).  It is written atomically
(:func:`mechloop.output.atomic.atomic_write_text`), offered back when the model is opened
again and differs from the file, and removed when the model is saved.
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from pathlib import Path

from mechloop.model.limits import MAX_DOCUMENT_BYTES
from mechloop.output.atomic import atomic_write_text
from mechloop.web.safety import WebError, Workspace

#: The folder of the working copies, relative to the served folder.
AUTOSAVE_DIR = Path(".mechloop") / "autosave"


@dataclass(frozen=True)
class WorkingCopy:
    """Where the working copy of one model is kept (``target``) and the model's own file
    (``original``: in the folder, or the bundled example; it may not exist yet)."""

    target: Path
    original: Path

    def read(self) -> tuple[str, float] | None:
        """(the text, its modification time in s since the epoch), or None when there is
        no working copy."""
        try:
            return self.target.read_text(encoding="utf-8"), self.target.stat().st_mtime
        except FileNotFoundError:
            return None
        except (OSError, UnicodeDecodeError) as exc:
            raise WebError(f"cannot read the working copy: {exc}",
                           "discard it and go on from the file") from None

    def differs(self, text: str) -> bool:
        """Whether ``text`` differs from the model's file (a missing file differs)."""
        try:
            return self.original.read_text(encoding="utf-8") != text
        except (OSError, UnicodeDecodeError):
            return True

    def write(self, text: str) -> None:
        """Keep ``text`` as the working copy (refused past the size of a model file)."""
        if len(text.encode("utf-8")) > MAX_DOCUMENT_BYTES:
            raise WebError(f"the working copy is larger than "
                           f"{MAX_DOCUMENT_BYTES // 1024 // 1024} MiB",
                           "keep the model under 2 MiB (long tables go in CSV files)", 413)
        self.target.parent.mkdir(parents=True, exist_ok=True)
        atomic_write_text(self.target, text)

    def clear(self) -> bool:
        """Remove the working copy; whether there was one."""
        try:
            os.unlink(self.target)
        except FileNotFoundError:
            return False
        return True


def working_copy(workspace: Workspace, *, path: str | None = None,
                 example: Path | None = None) -> WorkingCopy:
    """The working copy of the folder's file ``path`` (checked by
    :meth:`Workspace.resolve`: no way out of the folder) or of the bundled ``example``
    (its file, found in the catalogue)."""
    base = workspace.root / AUTOSAVE_DIR
    if example is not None:
        return WorkingCopy(base / "examples" / (example.stem + ".yaml"), example)
    original = workspace.resolve(str(path or ""), exists=False)
    target = base / "files" / workspace.relative(original)
    if not target.resolve().is_relative_to(workspace.root):  # .mechloop a link out
        raise WebError("the autosave folder leads out of the folder",
                       "remove the symbolic link .mechloop", 403)
    return WorkingCopy(target, original)
