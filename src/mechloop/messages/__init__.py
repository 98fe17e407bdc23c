"""The language of mechloop's messages on the command line (issue 15: Russian throughout).

Owns: choosing the language of a message (:mod:`.language`: a command's ``--lang``, else the
environment variable ``MECHLOOP_LANG``), the Russian catalogue of the library's error
messages and fixes (:mod:`.catalogue_ru`) and the rendering of a
:class:`~mechloop.errors.MechloopError` in a language (:mod:`.render`).  The library raises
its errors in English; they are translated only when printed.  May import
:mod:`mechloop.errors` and the standard library only (the CLI imports it at start-up).
"""

from mechloop.messages.language import message_language
from mechloop.messages.render import error_label, render_error

__all__ = ["error_label", "message_language", "render_error"]
