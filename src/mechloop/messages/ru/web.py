"""Russian of the messages and fixes of the web application (src/mechloop/web/).

The messages the web application shares with the command line (``the increment needs one
parameter``, ``the model has no synthesis task``, ``the request is …``) are entries of
:mod:`mechloop.messages.ru.views`; the operating system's reasons (``Address already in
use``) too.
"""

from __future__ import annotations

import re

from mechloop.messages.ru.base import Entry, quoted

#: The formats a request names (``no report format 'odt'``).
_FORMATS = {"report": "отчёта", "table": "таблицы", "figure": "рисунка",
            "animation": "анимации"}


def _request(match: re.Match[str]) -> str:
    kind = match["kind"]
    if kind == "untyped":
        return "у запроса не указан тип содержимого, а нужен application/json"
    return f"запрос имеет тип {kind}, а не application/json"


def _or_list(items: str) -> str:
    """``.yaml, .yml, .json`` → ``.yaml, .yml или .json``."""
    head, sep, last = items.rpartition(", ")
    return f"{head} или {last}" if sep else items


def _format(match: re.Match[str]) -> str:
    kind = _FORMATS.get(match["kind"], f"'{match['kind']}'")
    return f"нет формата {kind} {match['v']}"


ENTRIES: list[Entry] = [
    # the requests (web/app.py, web/exports.py)
    (r"(?P<v>'[^']*'|\S+) is not a model", "{v} — не модель"),
    (r"pick a model", "выберите модель"),
    (r"the request is (?P<kind>\S+), not application/json", _request),
    (r"send the JSON with content-type: application/json",
     "отправьте JSON с заголовком 'content-type: application/json'"),
    (r"the request is not JSON", "запрос — не JSON"),
    (r"send a JSON object", "отправьте объект JSON"),
    (r"the request is not a JSON object", "запрос — не объект JSON"),
    (r"'text' is not a string", "'text' — не строка"),
    (r"send the model's text", "отправьте текст модели"),
    (r"(?!(?:CSV )?file )(?P<p>.+?) not found", "{p} не найден"),
    (r"pick a file from the list", "выберите файл из списка"),
    (r"save it as UTF-8 text", "сохраните его как текст в кодировке UTF-8"),
    (r"a bundled example cannot be overwritten", "встроенный пример нельзя перезаписать"),
    (r"save it under a file name in the folder", "сохраните его под своим именем в папке"),
    (r"no folder (?P<v>'[^']*'|\S+)", "нет папки {v}"),
    (r"save into an existing folder", "сохраните в существующую папку"),
    (r"(?P<k>'[^']*'|\S+) is not a positive number", "{k} — не положительное число"),
    (r"give (?P<k>\w+) > 0", "задайте {k} > 0"),
    (r"'position' is not a whole number", "'position' — не целое число"),
    (r"give a position number", "укажите номер положения"),
    (r"no (?P<kind>\w+) format (?P<v>'[^']*'|\S+)", _format),
    (r"no language (?P<v>'[^']*'|\S+)", "нет языка {v}"),
    (r"'names' is not a list of parameter names", "'names' — не список имён параметров"),
    (r"send e\.g\. (?P<ex>\{\"names\": .*\})", "отправьте, например, '{ex}'"),
    (r"(?P<n>\d+|\S+) curves asked for one plot; at most (?P<max>\S+) fit",
     "на одном графике запрошено кривых: {n}; помещается не больше {max}"),
    (r"choose fewer parameters", "выберите меньше параметров"),
    (r"the file (?P<n>'[^']*'|\S+) lies outside the folder the server was started in",
     "файл {n} лежит вне папки, в которой запущен сервер"),
    (r"put the file in that folder and give its path relative to the model",
     "поместите файл в эту папку и укажите путь к нему относительно модели"),
    # the views (web/views.py)
    (r"no view (?P<v>'[^']*'|\S+)", "неизвестный вид графика {v}"),
    (r"give one name, e\.g\. (?P<ex>\S+)", "укажите одно имя, например {ex}"),
    (r"give two numbers, e\.g\. (?P<ex>\S+)", "укажите два номера, например {ex}"),
    (r"give one of (?!them$)(?P<items>[^:]*)",
     lambda m: "укажите одно из: " + (quoted(m["items"]) or "вариантов нет")),
    # the jobs (web/jobs.py)
    (r"no job kind (?P<v>'[^']*'|\S+)", "нет задания вида {v}"),
    (r"use synthesis", "используйте 'synthesis'"),
    (r"another job is running", "уже выполняется другое задание"),
    (r"wait for it to finish, or cancel it", "дождитесь его окончания или отмените его"),
    (r"cannot start the job: (?P<why_tr>.*)", "не удаётся запустить задание: {why_tr}"),
    (r"try again", "попробуйте ещё раз"),
    (r"no job (?P<v>'[^']*'|\S+)", "нет задания {v}"),
    (r"start a job first", "сначала запустите задание"),
    (r"the job did not stop in time and was killed",
     "задание не остановилось вовремя и было прервано принудительно"),
    (r"use fewer generations or positions", "возьмите меньше поколений или положений"),
    (r"the job stopped without a result \(out of memory\?\)",
     "задание завершилось без результата (не хватило памяти?)"),
    (r"use fewer positions or a smaller population",
     "возьмите меньше положений или меньшую популяцию"),
    # the folder served (web/safety.py, web/serve.py)
    (r"(?P<f>.+?) is not a folder", "{f} — не папка"),
    (r"give a model file or a folder", "укажите файл модели или папку"),
    (r"no file named", "не задано имя файла"),
    (r"give the path of a model file in the folder", "укажите путь к файлу модели в папке"),
    (r"(?P<p>'[^']*'|\S+) is an absolute path", "{p} — абсолютный путь"),
    (r"give a path relative to the folder the server was started in",
     "укажите путь относительно папки, в которой запущен сервер"),
    (r"(?P<p>'[^']*'|\S+) leads out of the folder", "{p} ведёт за пределы папки"),
    (r"give a path inside the folder the server was started in",
     "укажите путь внутри папки, в которой запущен сервер"),
    (r"(?P<p>'[^']*'|\S+) leads out of the folder \(a symbolic link\)",
     "{p} ведёт за пределы папки (по символической ссылке)"),
    (r"(?P<p>.+?) is not a model file", "{p} — не файл модели"),
    (r"give a file ending in (?P<list>.+)",
     lambda m: "укажите файл с окончанием " + _or_list(m["list"])),
    (r"give an? (?P<list>.+?) file or a folder",
     lambda m: f"укажите файл {_or_list(m['list'])} либо папку"),
    (r"port (?P<p>\S+) is out of range", "порт {p} вне допустимого диапазона"),
    (r"use 1 to 65535, or leave it out",
     "укажите число от 1 до 65535 или не задавайте порт"),
    (r"cannot listen on (?P<host>.+?): (?P<why_tr>.+)",
     "не удаётся принимать соединения на {host}: {why_tr}"),
    (r"give an address of this machine with --host",
     "укажите в --host адрес этого компьютера"),
    # the animation, sweep and simulation jobs (web/work.py)
    (r"use synthesis, (?P<list>.+)",
     lambda m: "используйте одно из: " + quoted("synthesis, " + m["list"])),
    (r"(?P<k>'[^']*'|\S+) is not a whole number", "{k} — не целое число"),
    (r"give a whole number of (?P<k>\S+)", "укажите целое число {k}"),
    (r"(?P<k>'[^']*'|\S+) is (?P<v>\S+), more than (?P<n>\S+)",
     "{k} равно {v}, это больше {n}"),
    (r"give (?P<k>\S+) of at most (?P<n>\S+)", "задайте {k} не больше {n}"),
    (r"(?P<k>'[^']*'|\S+) is not a list of texts", "{k} — не список строк"),
    (r"send e\.g\. (?P<ex>\{.+\})", "пришлите, например, {ex}"),
    (r"(?P<n>\d+) parameters to vary; a sweep varies one or (?P<m>\d+)",
     "параметров для изменения: {n}; параметрический анализ изменяет один или {m}"),
    (r"vary one parameter, or two for a grid",
     "изменяйте один параметр или два (для сетки)"),
    (r"the sweep has (?P<n>\d+) designs; the page runs at most (?P<m>\d+)",
     "в параметрическом анализе {n} вариантов; страница выполняет не больше {m}"),
    (r"use fewer values, or run mechloop sweep from the command line",
     "возьмите меньше значений или запустите 'mechloop sweep' из командной строки"),
    (r"(?P<n>\d+) quantities to collect; at most (?P<m>\d+)",
     "величин для сбора: {n}; допускается не больше {m}"),
    (r"collect fewer quantities", "соберите меньше величин"),
    (r"the job was cancelled", "задание отменено"),
    (r"start it again to get its result",
     "запустите его снова, чтобы получить результат"),
    (r"the job is still running", "задание ещё выполняется"),
    (r"download its file when it is done", "скачайте его файл, когда оно завершится"),
    (r"the job made no file", "задание не создало файла"),
    (r"an animation, a sweep or a simulation that finished makes one",
     "файл создают завершённые анимация, параметрический анализ или моделирование"),
    (r"the job took longer than (?P<n>\S+) s and was stopped",
     "задание длилось дольше {n} с и было остановлено"),
    (r"use fewer values, fewer positions or a shorter duration",
     "возьмите меньше значений, меньше положений или меньшую длительность"),
]
