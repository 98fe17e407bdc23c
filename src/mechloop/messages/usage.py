"""The command line's usage errors (an unknown option, a missing argument, a value of the
wrong type — Click's own, printed by Typer) in the language of the messages.

Typer prints them itself, before a command runs, so they never reach
:func:`mechloop.messages.render_error`; in Russian (``MECHLOOP_LANG=ru``) its printer is
replaced by one that prints the same three parts — the usage line, where to find help and
the message in a panel — with the message put in Russian by the catalogue.
"""

from __future__ import annotations

import re
from typing import Any

#: The usage line's words in Russian.
USAGE_RU = {"Usage:": "Использование:", "[OPTIONS]": "[ПАРАМЕТРЫ]",
            "COMMAND": "КОМАНДА", "[ARGS]": "[АРГУМЕНТЫ]"}
#: The panel's title and the line that points to the help, in Russian.
TITLE_RU = "Ошибка"
HELP_RU = "Справка: '{command} {option}'."


def usage_line(usage: str) -> str:
    """Click's usage line in Russian (``Usage: mechloop solve [OPTIONS] {model}``)."""
    return re.sub("|".join(map(re.escape, USAGE_RU)), lambda m: USAGE_RU[m.group(0)], usage)


def print_russian(error: Any) -> None:
    """Print a Click usage error as Typer does, in Russian."""
    from rich.console import Console
    from rich.markup import escape
    from rich.panel import Panel

    from mechloop.messages.catalogue_ru import translate

    if type(error).__name__ == "NoArgsIsHelpError":  # the help is printed instead
        return
    console = Console(stderr=True, highlight=False)
    ctx = getattr(error, "ctx", None)
    if ctx is not None:
        console.print(escape(usage_line(ctx.get_usage())), style="yellow")
        if ctx.command.get_help_option(ctx) is not None:
            console.print(escape(HELP_RU.format(command=ctx.command_path,
                                                option=ctx.help_option_names[0])),
                          style="dim")
    console.print(Panel(escape(translate(error.format_message())), border_style="red",
                        title=TITLE_RU, title_align="left"))


def install() -> None:
    """Make Typer print its usage errors in the language of the messages, chosen when one
    is printed (:func:`mechloop.messages.message_language`: ``MECHLOOP_LANG``)."""
    from typer import rich_utils

    original = rich_utils.rich_format_error
    if getattr(original, "mechloop", False):
        return

    def format_error(error: Any) -> None:
        from mechloop.messages.language import message_language

        if message_language() == "ru":
            print_russian(error)
        else:
            original(error)

    format_error.mechloop = True  # type: ignore[attr-defined]
    rich_utils.rich_format_error = format_error
