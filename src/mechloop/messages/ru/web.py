"""Russian of the messages and fixes of the web application (src/mechloop/web/).

The messages the web application shares with the command line (``the increment needs one
parameter``, ``the model has no synthesis task``, ``the request is …``) are entries of
:mod:`mechloop.messages.ru.views`; the operating system's reasons (``Address already in
use``) too.  The form editing's messages (web/edit.py) name the key paths of the model
(``vectors[1].r``) and the values sent as written.
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
    # the form editing (web/edit.py): one value set, a key renamed or an entry deleted
    (r"the value nests too deep", "значение вложено слишком глубоко"),
    (r"at most (?P<n>\S+) levels", "уровней вложенности — не больше {n}"),
    (r"the value is not a finite number", "значение — не конечное число"),
    (r"give a finite number", "задайте конечное число"),
    (r"the key (?P<k>.+?) of the path is not a name or a number",
     "ключ {k} в пути — не имя и не число"),
    (r"the key (?P<k>.+?) is not a name or a number", "ключ {k} — не имя и не число"),
    (r"use a name", "используйте имя"),
    (r"(?P<t>\w+) is not a value of a model", "'{t}' не может быть значением модели"),
    (r"give a number, a string, true/false, null, a list or a mapping",
     "задайте число, строку, 'true'/'false', 'null', список или словарь"),
    (r"no key (?P<p>'[^']*') in the model", "в модели нет ключа {p}"),
    (r"add the entries above it first", "сначала добавьте записи уровнем выше"),
    (r"(?P<p>.+?) is an alias of another entry", "{p} — псевдоним другой записи"),
    (r"edit the anchored entry in the text", "измените в тексте запись с якорем"),
    (r"no item (?P<i>.+?) in the list at (?P<p>.+)", "в списке {p} нет элемента {i}"),
    (r"give an index 0\.\.(?P<n>\S+) \(the last adds one\)",
     "укажите индекс от 0 до {n} (последний добавляет новый элемент)"),
    (r"(?P<p>.+?) holds a single value, not entries",
     "{p} содержит одно значение, а не записи"),
    (r"set (?P<p>\S+) itself", "задайте само значение {p}"),
    (r"the item does not start its own line", "элемент списка не начинается с новой строки"),
    (r"delete it in the text", "удалите его в тексте"),
    (r"'keys' is not a list of keys", "'keys' — не список ключей"),
    (r"give the key path as a list, e\.g\. (?P<ex>\[.*\])",
     "укажите путь из ключей списком, например '{ex}'"),
    (r"the key path has (?P<n>\S+) keys", "ключей в пути: {n}"),
    (r"at most (?P<n>\S+)", "не больше {n}"),
    (r"give names and numbers only", "укажите только имена и числа"),
    (r"the text is over (?P<n>\S+) bytes", "текст длиннее {n} байт"),
    (r"keep long tables in a CSV file", "длинные таблицы храните в файле CSV"),
    (r"no key (?P<p>'[^']*') to rename", "нет ключа {p}: переименовывать нечего"),
    (r"rename an existing key", "переименуйте существующий ключ"),
    (r"the new key (?P<k>.+?) is not a name or a number",
     "новый ключ {k} — не имя и не число"),
    (r"give a name", "задайте имя"),
    (r"the key (?P<k>.+?) is there already", "ключ {k} уже есть"),
    (r"pick another key", "выберите другой ключ"),
    (r"renaming (?P<p>.+?) would not read back",
     "после переименования {p} текст не читается обратно с новым ключом"),
    (r"rename it in the text", "переименуйте его в тексте"),
    (r"no key (?P<p>'[^']*') to delete", "нет ключа {p}: удалять нечего"),
    (r"delete an existing entry", "удалите существующую запись"),
    (r"deleting (?P<p>.+?) would not read back",
     "после удаления {p} текст не читается обратно"),
    (r"the value at (?P<p>\S+) would read back as (?P<a>.+?), not (?P<b>.+)",
     "значение {p} прочиталось бы из текста как {a}, а не {b}"),
    (r"change it in the text", "измените его в тексте"),
    (r"the edited text would be over (?P<n>\S+) bytes",
     "после правки текст был бы длиннее {n} байт"),
    # the working copy (autosave) and new models from templates
    (r"cannot read the working copy: (?P<why_tr>.+)",
     "не удаётся прочитать рабочую копию: {why_tr}"),
    (r"discard it and go on from the file",
     "отбросьте её и продолжайте с файла"),
    (r"the working copy is larger than (?P<n>\S+) MiB",
     "рабочая копия больше {n} МиБ"),
    (r"keep the model under 2 MiB \(long tables go in CSV files\)",
     "модель должна быть меньше 2 МиБ (длинные таблицы выносите в файлы CSV)"),
    (r"the autosave folder leads out of the folder",
     "папка автосохранения ведёт за пределы папки"),
    (r"remove the symbolic link \.mechloop", "удалите символическую ссылку .mechloop"),
    (r"pick a model from the list", "выберите модель из списка"),
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
    # the views of the page (web/views.py)
    (r"the parameters plot needs a name", "для графика параметров нужно имя"),
    (r"give names, e\.g\. (?P<ex>\S+)", "укажите имена, например {ex}"),
    (r"give two names, e\.g\. (?P<ex>\S+)", "укажите два имени, например {ex}"),
]
