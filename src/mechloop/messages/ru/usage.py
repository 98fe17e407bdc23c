"""Russian of the command line's usage errors (Click's own messages, printed by Typer:
see :mod:`mechloop.messages.usage`)."""

from __future__ import annotations

from mechloop.messages.ru.base import Entry

ENTRIES: list[Entry] = [
    (r"No such option: (?P<o>\S+) \(Possible options: (?P<p>[^)]*)\)",
     "нет параметра {o} (возможно: {p})"),
    (r"No such option: (?P<o>\S+)", "нет параметра {o}"),
    (r"No such command '(?P<c>[^']*)'\.", "нет команды '{c}'"),
    (r"Missing command\.", "не указана команда"),
    (r"Missing argument (?P<a>'[^']*')\.", "не указан аргумент {a}"),
    (r"Missing option (?P<o>'[^']*'(?: / '[^']*')*)\.", "не указан параметр {o}"),
    (r"Missing parameter: (?P<p>\S+)", "не указан параметр '{p}'"),
    (r"Missing (?:argument|option|parameter) (?P<o>'[^']*'(?: / '[^']*')*)\. (?P<m_tr>.+)",
     "не указан {o}. {m_tr}"),
    (r"Invalid value for (?P<o>'[^']*'(?: / '[^']*')*|--?[\w-]+): (?P<m_tr>.+)",
     "недопустимое значение {o}: {m_tr}"),
    (r"Invalid value: (?P<m_tr>.+)", "недопустимое значение: {m_tr}"),
    (r"Option '(?P<o>[^']*)' requires an argument\.", "параметру '{o}' нужно значение"),
    (r"Option '(?P<o>[^']*)' requires (?P<n>\d+) arguments\.",
     "параметру '{o}' нужно значений: {n}"),
    (r"Option '(?P<o>[^']*)' does not take a value\.", "параметр '{o}' не принимает значения"),
    (r"Argument '(?P<a>[^']*)' takes (?P<n>\d+) values\.",
     "аргументу '{a}' нужно значений: {n}"),
    (r"Got unexpected extra argument\(s\) \((?P<a>.*)\)",
     lambda m: "лишние аргументы: " + ", ".join(f"'{a}'" for a in m["a"].split())),
    # the command line's own refusals of a value (typer.BadParameter in mechloop.cli)
    (r"(?P<v>'[^']*'|\S+): use auto, de, cmaes or multistart",
     "{v}: допустимо 'auto', 'de', 'cmaes' или 'multistart'"),
    (r"(?P<v>\S+): give a cam angle in degrees", "{v}: укажите угол кулачка в градусах"),
    (r"Could not open file '(?P<f>[^']*)': (?P<m_tr>.+)",
     "не удаётся открыть файл '{f}': {m_tr}"),
]
