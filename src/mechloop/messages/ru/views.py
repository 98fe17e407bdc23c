"""Russian of the messages and fixes of views, output, report and the command line
(src/mechloop/views/, output/, report/, cli.py).

A value a message shows with ``!r`` (``unknown layout 'grid'``) is matched with or without
its quotes and kept as written.  The names of the Python interface (``Results``,
``mechloop.solve_dynamics``) stay as written, in quotes.  The operating system's reasons
(``Permission denied``) of a file that cannot be written are entries too.
"""

from __future__ import annotations

import re

from mechloop.messages.ru.base import Entry, quoted

#: The operating system's reasons (``strerror``) a write or a listen fails with.
OS_REASONS = {
    "No space left on device": "на устройстве не осталось места",
    "Disk quota exceeded": "превышена дисковая квота",
    "File too large": "файл слишком велик",
    "Read-only file system": "файловая система доступна только для чтения",
    "Permission denied": "доступ запрещён",
    "Operation not permitted": "операция не разрешена",
    "No such file or directory": "нет такого файла или папки",
    "Is a directory": "это папка",
    "Not a directory": "это не папка",
    "File name too long": "слишком длинное имя файла",
    "Input/output error": "ошибка ввода-вывода",
    "Too many open files": "открыто слишком много файлов",
    "Cannot allocate memory": "не удаётся выделить память",
    "Address already in use": "адрес уже занят",
    "Cannot assign requested address": "этот адрес не принадлежит компьютеру",
    "Name or service not known": "неизвестное имя узла",
    "Temporary failure in name resolution": "временный сбой при разрешении имени узла",
    "Address family not supported by protocol": "семейство адресов не поддерживается",
    "Resource temporarily unavailable": "ресурс временно недоступен",
}


def _point_signs(match: re.Match[str]) -> str:
    """The characters the report's fonts lack: ``'☃' (U+2603) in 'text'`` → ``… в …``."""
    signs = re.sub(r"(\(U\+[0-9A-F]+\)) in ", r"\1 в ", match["signs"])
    return f"в шрифтах отчёта нет знаков для {signs}"


def _overwrite(match: re.Match[str]) -> str:
    what = {"the input model": "входной файл модели {src}",
            "a table the model reads,": "таблица {src}, которую читает модель"}.get(
        match["what"], match["what"] + " {src}").format(src=match["src"])
    return f"{match['t']} — это {what}: запись затёрла бы этот файл"


def _suffix(suffix: str) -> str:
    """A file's suffix as a message shows it (``''`` or ``no suffix``: none)."""
    return "файл без расширения" if suffix in ("", "no suffix") else f"'{suffix}'"


def _animation(match: re.Match[str]) -> str:
    return f"{match['t']}: анимацию нельзя сохранить как {_suffix(match['s'])}"


def _figure(match: re.Match[str]) -> str:
    return f"{match['t']}: рисунок нельзя сохранить как {_suffix(match['s'])}"


def _unknown_format(match: re.Match[str]) -> str:
    if not match["s"]:
        return f"{match['t']}: у имени файла нет расширения, по которому выбирается формат"
    return f"{match['t']}: неизвестный формат вывода '{match['s']}'"


ENTRIES: list[Entry] = [
    # the operating system's reasons (inside "cannot write …: <reason>")
    *((re.escape(english), russian) for english, russian in OS_REASONS.items()),
    (r"copied (?P<a>\d+) of (?P<b>\d+) bytes", "скопировано байт: {a} из {b}"),
    # the command line (cli.py)
    (r"the model has no bodies, so no loads",
     "в модели нет звеньев ('bodies:'), а значит, и нагрузок"),
    (r"add bodies with masses, and forces or moments",
     "добавьте звенья с массами ('bodies:') и силы или моменты"),
    (r"the model has no simulate: section", "в модели нет раздела 'simulate:'"),
    (r"add simulate: (?P<ex>\{motor: .*\})", "добавьте раздел simulate: {ex}"),
    (r"unknown view (?P<v>'[^']*'|\S+)", "неизвестный вид графика {v}"),
    (r"no (?P<what>figure|report) language (?P<v>'[^']*'|\S+)",
     lambda m: ("нет языка рисунка" if m["what"] == "figure" else "нет языка отчёта")
     + f" {m['v']}"),
    (r"a combination needs two names", "для комбинации нужны два имени"),
    (r"the angle between two vectors needs two vector numbers",
     "для угла между двумя векторами нужны номера двух векторов"),
    (r"the increment needs one parameter", "для приращения нужен один параметр"),
    (r"give (?P<opt>-n|--names) (?P<ex>\S+)", "укажите {opt} {ex}"),
    (r"a hodograph needs a joint", "для годографа нужен шарнир"),
    (r"give --joint, one of (?P<items>.*)",
     lambda m: "укажите --joint: " + (quoted(m["items"]) or "в модели нет шарниров")),
    (r"the model has no synthesis task", "в модели нет задачи синтеза"),
    (r"add a synthesis: section, see (?P<ex>\S+)",
     "добавьте раздел 'synthesis:' (см. {ex})"),
    (r"no feasible design to write",
     "записывать нечего: не найдено ни одного допустимого решения"),
    (r"widen the bounds or change the task", "расширьте границы поиска или измените задачу"),
    (r"the web application needs (?P<pkg>\S+)", "для веб-приложения нужен пакет '{pkg}'"),
    (r"pip install \"mechloop\[web\]\"",
     "установите его командой 'pip install \"mechloop[web]\"'"),
    # display units and digits (output/display.py, views/display.py)
    (r"(?P<opt>[^\s:]+): (?P<rest_tr>unknown kind of quantity .+|.+? is not KIND=UNIT)",
     "{opt}: {rest_tr}"),
    (r"(?P<item>.+?) is not KIND=UNIT", "{item} — не пара РОД=ЕДИНИЦА"),
    (r"unknown kind of quantity (?P<k>'[^']*'|\S+) in (?P<item>'[^']*'|\S+)",
     "неизвестный род величины {k} в {item}"),
    (r"unknown kind of quantity (?P<k>'[^']*'|\S+)", "неизвестный род величины {k}"),
    (r"(?!port )(?P<opt>--?[\w.]+|\w+) (?P<v>\S+) is out of range",
     "{opt} {v} вне допустимого диапазона"),
    (r"cannot write a column in (?P<a>.+?) as (?P<b>.+)",
     "столбец в единицах {a} нельзя записать в единицах {b}"),
    (r"name a unit of the column's kind", "укажите единицу того же рода, что у столбца"),
    (r"unknown display unit (?P<k>\w+)=(?P<u>.+)",
     "неизвестная единица отображения '{k}'={u}"),
    (r"display unit (?P<k>\w+)=(?P<u>.+?) is not a unit of (?P<kind>.+)",
     "единица отображения '{k}'={u} — не единица величины '{kind}'"),
    (r"digits=(?P<v>.+?) is not a number of significant digits",
     "digits: {v} — не число значащих цифр"),
    # output files (output/paths.py, output/tables.py)
    (r"(?P<t>.+?): unknown output format '(?P<s>[^']*)'", _unknown_format),
    (r"(?P<t>.+?): cannot save a figure as '(?P<s>[^']*)'", _figure),
    (r"(?P<t>.+?) is a folder, not a file", "{t} — папка, а не файл"),
    (r"give a file name inside it, e\.g\. (?P<ex>.+)",
     "укажите имя файла в этой папке, например {ex}"),
    (r"cannot write (?P<t>.+?): the folder (?P<f>.+) does not exist",
     "нельзя записать {t}: папки {f} не существует"),
    (r"create it first \(mkdir -p (?P<f>.+)\) or choose another folder",
     "сначала создайте её ('mkdir -p {f}') или выберите другую папку"),
    (r"cannot write (?P<t>.+?): (?P<f>.+) is not a folder",
     "нельзя записать {t}: {f} — не папка"),
    (r"choose a path inside a folder", "выберите путь внутри папки"),
    (r"cannot write (?P<t>.+?): no permission to write in the folder (?P<f>.+)",
     "нельзя записать {t}: нет прав на запись в папку {f}"),
    (r"choose a folder you can write to, or change its permissions",
     "выберите папку, доступную для записи, или измените её права доступа"),
    (r"(?P<t>.+?) is (?P<what>the input model|a table the model reads,|\S+) (?P<src>.+?): "
     r"writing it would overwrite it", _overwrite),
    (r"choose another output file, or add --force to replace it",
     "выберите другой выходной файл или добавьте --force, чтобы заменить его"),
    (r"cannot write (?P<t>.+?): (?P<why_tr>.+)", "нельзя записать {t}: {why_tr}"),
    (r"free some disk space or write to another disk",
     "освободите место на диске или запишите файл на другой диск"),
    (r"the file system limits the file size: write to another disk or use Parquet",
     "файловая система ограничивает размер файла: запишите его на другой диск или "
     "в формате .parquet"),
    (r"the file system is read-only: choose a folder on a writable disk",
     "файловая система доступна только для чтения: выберите папку на диске, доступном "
     "для записи"),
    (r"check that the folder exists \(mkdir -p\) or choose another folder",
     "проверьте, что папка существует ('mkdir -p'), или выберите другую папку"),
    (r"check the path and the disk", "проверьте путь и диск"),
    (r"(?P<p>.+?) exists and holds no JSON Schema \(a model file\?\): writing the schema "
     r"would replace it", "{p} уже существует и не содержит JSON-схемы (это файл модели?): "
     "запись схемы заменила бы его"),
    (r"choose another file name, or add --force to replace the file",
     "выберите другое имя файла или добавьте --force, чтобы заменить файл"),
    (r"(?P<p>.+?): (?P<rows>[\d,]+) rows and (?P<cols>[\d,]+) columns do not fit an Excel "
     r"sheet \(at most (?P<r>[\d,]+) rows under the header and (?P<c>[\d,]+) columns\)",
     "{p}: таблица (строк: {rows}, столбцов: {cols}) не помещается на лист .xlsx (на листе "
     "под заголовком не больше строк: {r}, столбцов: {c})"),
    (r"write a \.csv or \.parquet file instead", "запишите вместо этого файл .csv или .parquet"),
    # the report (report/)
    (r"(?P<v>'[^']*'|\S+) is not a varying parameter of the model",
     "{v} — не переменный параметр модели"),
    (r"Typst could not typeset the report: (?P<why>.*)",
     "программа вёрстки 'Typst' не смогла сверстать отчёт: {why}"),
    (r"Typst typeset the report with warnings: (?P<why>.*)",
     "программа вёрстки 'Typst' сверстала отчёт с предупреждениями: {why}"),
    (r"report this as a bug of mechloop with the model file",
     "сообщите об этой ошибке разработчикам 'mechloop', приложив файл модели"),
    (r"the report's fonts have no sign for (?P<signs>.+)", _point_signs),
    (r"replace these characters in the model file \(names, captions, report texts\) by ones "
     r"in the Latin, Cyrillic or Greek alphabets or the usual mathematical signs",
     "замените эти символы в файле модели (в именах, подписях, текстах отчёта) буквами "
     "латиницы, кириллицы или греческого алфавита либо обычными математическими знаками"),
    # animations (views/animation.py)
    (r"fps (?P<v>\S+) is not a positive number", "fps {v} — не положительное число"),
    (r"give frames per second, e\.g\. fps=25, or leave it out to use the model time",
     "задайте число кадров в секунду, например fps=25, или не задавайте его, чтобы "
     "использовать время модели"),
    (r"(?P<t>.+?): cannot save an animation as '(?P<s>[^']*)'", _animation),
    # curves (views/curves.py, views/dynamics.py, views/motion.py, views/sweep.py)
    (r"cannot plot a (?P<cls>\w+)", "нельзя построить график по объекту '{cls}'"),
    (r"pass the Results of mechloop\.solve or the DynamicResults of "
     r"mechloop\.solve_dynamics", "передайте 'Results' из 'mechloop.solve' или "
     "'DynamicResults' из 'mechloop.solve_dynamics'"),
    (r"this model has no time, so nothing can be plotted against time",
     "у этой модели нет времени, поэтому графики по времени строить нельзя"),
    (r"plot against 'position' or an argument \('arg1'\), or give the model a time: "
     r"\{rpm: \.\.\.\}", "стройте графики по 'position' или по аргументу ('arg1') либо "
     "задайте модели время (time: {{rpm: ...}})"),
    (r"no quantity (?P<q>'[^']*'|\S+) in these results", "в результатах нет величины {q}"),
    (r"no quantity (?P<q>'[^']*'|\S+) in this sweep",
     "в результатах перебора нет величины {q}"),
    (r"unknown layout (?P<v>'[^']*'|\S+)", "неизвестная компоновка {v}"),
    (r"stacked panels cannot be drawn on given axes",
     "панели одна под другой нельзя нарисовать на заданных осях"),
    (r"leave out ax=, or use layout='axes'",
     "не передавайте 'ax' или задайте 'layout' равным 'axes'"),
    (r"unknown combination (?P<v>'[^']*'|\S+)", "неизвестная комбинация {v}"),
    (r"(?P<v>'[^']*'|\S+) does not name a vector", "{v} не называет вектор"),
    (r"(?P<v>'[^']*'|\S+) is not a vector parameter of this model",
     "{v} — не параметр векторов этой модели"),
    (r"a dynamics plot needs DynamicResults, not (?P<cls>\w+)",
     "для графика динамики нужны 'DynamicResults', а не '{cls}'"),
    (r"solve the model with mechloop\.solve_dynamics\(model\)",
     "решите модель функцией 'mechloop.solve_dynamics(model)'"),
    (r"reduced characteristics need a one-input machine; this model has (?P<n>\S+) drives",
     "приведённые характеристики строятся только для машины с одним входом; приводов у "
     "этой модели: {n}"),
    (r"plot the balancing loads \(plot_balancing\) instead",
     "постройте вместо них уравновешивающие нагрузки ('plot_balancing')"),
    (r"expected a Simulation, got (?P<cls>\w+)",
     "ожидался объект 'Simulation', а получен '{cls}'"),
    (r"pass the result of mechloop\.simulate\(\.\.\.\)",
     "передайте результат 'mechloop.simulate(...)'"),
    (r"the table has no quantities to plot", "в таблице нет величин для графика"),
    (r"pass the table that mechloop\.synthesis\.sweep\.sweep returns",
     "передайте таблицу, которую возвращает 'mechloop.synthesis.sweep.sweep'"),
    (r"cannot draw a sweep of (?P<n>\S+) parameters",
     "нельзя построить график перебора сразу по {n} параметрам"),
    (r"sweep one parameter \(lines\) or two \(a family of lines or a map\)",
     "перебирайте один параметр (линии) или два (семейство линий или карта линий уровня)"),
    (r"(?P<n>\S+) values of (?P<p>.+?) are too many lines for one plot",
     "значений {p}: {n} — слишком много линий для одного графика"),
    (r"draw a contour map \(contour=True, --contour\)",
     "нарисуйте карту линий уровня ('contour=True', --contour)"),
    (r"(?P<name>.+?): too few values for a contour map",
     "{name}: слишком мало значений для карты линий уровня"),
    (r"sweep at least two values of each parameter, or draw lines",
     "переберите хотя бы по два значения каждого параметра или рисуйте линии"),
    # envelopes (views/envelope.py)
    (r"add one: envelopes: (?P<ex>\[\{name: .*\])",
     "добавьте её, например: 'envelopes: {ex}'"),
    (r"name one of (?!its )(?P<items>[^:]+)", lambda m: "назовите одну из: " + quoted(m["items"])),
    # the gear sheet of the report (views/gear_sheet.py)
    (r"the file has neither a 'gear_pair:' nor a 'planetary:' section",
     "в файле нет ни раздела 'gear_pair:', ни раздела 'planetary:'"),
    # plans and trajectories (views/plan.py)
    (r"cannot draw a plan of (?P<cls>\w+)", "нельзя нарисовать план по объекту '{cls}'"),
    (r"pass the results of mechloop\.solve or mechloop\.solve_dynamics",
     "передайте результаты 'mechloop.solve' или 'mechloop.solve_dynamics'"),
    (r"unknown limits (?P<v>.+)", "неизвестные границы {v}"),
    (r"use None \(every position\), 'auto' or \(xmin, xmax, ymin, ymax\)",
     "используйте 'None' (по всем положениям), 'auto' или (x_min, x_max, y_min, y_max)"),
    (r"limits (?P<v>.+?) are not four numbers", "границы {v} — не четыре числа"),
    (r"give \(xmin, xmax, ymin, ymax\) in the plan's length unit",
     "задайте (x_min, x_max, y_min, y_max) в единицах длины плана"),
    (r"limits (?P<v>.+?) do not enclose an area", "границы {v} не ограничивают область"),
    (r"give finite \(xmin, xmax, ymin, ymax\) with xmin < xmax, ymin < ymax",
     "задайте конечные (x_min, x_max, y_min, y_max), где x_min < x_max и y_min < y_max"),
    (r"position (?P<v>.+?) is not a position number", "{v} — не номер положения"),
    (r"use an integer 0\.\.(?P<n>\S+)", "укажите целое число 0..{n}"),
    (r"no positions chosen", "не выбрано ни одного положения"),
    (r"give at least one position, or None for all",
     "задайте хотя бы одно положение или 'None' для всех"),
    (r"the axes belong to no figure", "оси не принадлежат ни одному рисунку"),
    (r"pass axes made by Figure\.add_subplot",
     "передайте оси, созданные 'Figure.add_subplot'"),
    (r"(?P<v>.+?) is not a point", "{v} — не точка"),
    (r"use (?P<forms>\{tail: K\}, .*) or 'S2'", "используйте {forms} или 'S2'"),
    (r"vector (?P<n>\S+) does not exist", "вектора {n} в модели нет"),
    (r"use one of (?P<list>\[[\d, ]*\])", "используйте один из векторов {list}"),
    (r"point (?P<v>'[^']*'|\S+) \(a joint or centre of mass\) needs dynamic results, of a "
     r"model with bodies", "для точки {v} (шарнира или центра масс) нужны результаты "
     "динамики, то есть модель со звеньями ('bodies:')"),
    (r"add bodies and joints to the model file \(see (?P<ex>\S+)\), or give the point on a "
     r"vector: head:K, tail:K or vector:K:s \(in Python: \{head: K\}, \.\.\., with the "
     r"results of solve_dynamics\)", "добавьте в файл модели звенья и шарниры (см. {ex}) "
     "или задайте точку на векторе: head:K, tail:K или vector:K:s (в программе: "
     "{{head: K}}, ... с результатами 'solve_dynamics')"),
    (r"no point named (?P<v>'[^']*'|\S+)", "нет точки с именем {v}"),
    (r"no points to trace", "нет точек для траекторий"),
    (r"give at least one point, e\.g\. (?P<ex>.+)",
     "задайте хотя бы одну точку, например {ex}"),
    # the 3-D plans of spatial models (views/spatial_plan.py, spatial_animation.py)
    (r"a 3-D plan needs the results of a model with spatial contours",
     "для объёмного плана нужны результаты модели с пространственными контурами"),
    (r"solve a model with 'spatial: true' contours by mechloop\.solve, or draw a planar "
     r"model by plot_plan", "решите модель с контурами 'spatial: true' функцией "
     "'mechloop.solve' или нарисуйте плоскую модель функцией 'plot_plan'"),
    (r"unknown views (?P<v>'[^']*'|\S+) of a 3-D plan",
     "неизвестный набор видов объёмного плана {v}"),
    (r"use 'all' \(the 3-D view and the three projections\) or '3d'",
     "используйте 'all' (объёмный вид и три проекции) или '3d' (только объёмный вид)"),
    (r"the viewing (?P<what>elevation|azimuth) (?P<v>.+?) is not a number",
     lambda m: ("угол возвышения" if m["what"] == "elevation" else "азимут")
     + f" точки зрения {m['v']} — не число"),
    (r"give the angles in degrees as finite numbers, e\.g\. (?P<e>\S+) and (?P<a>\S+)",
     "задайте углы в градусах конечными числами, например {e} и {a}"),
    (r"limits (?P<v>.+?) of a 3-D plan are neither None nor 'auto'",
     "границы объёмного плана {v} — ни 'None', ни 'auto'"),
    (r"use None \(every position\) or 'auto' \(the positions drawn\)",
     "используйте 'None' (все положения) или 'auto' (рисуемые положения)"),
    (r"(?P<v>.+?) is not a point of a 3-D plan", "{v} — не точка объёмного плана"),
    (r"use \{head: K\}, \{tail: K\} or \{vector: K, share: s\} \(head:K, tail:K or "
     r"vector:K:s on the command line\)", "используйте {{head: K}}, {{tail: K}} или "
     "{{vector: K, share: s}} (в командной строке head:K, tail:K или vector:K:s)"),
    (r"a model with spatial contours is drawn in 3-D, not in the plane",
     "модель с пространственными контурами рисуется в объёме, а не на плоскости"),
    (r"use plot_spatial_plan, plot_spatial_overlay or plot_spatial_trajectories of "
     r"mechloop\.views\.spatial_plan, or animate_spatial of "
     r"mechloop\.views\.spatial_animation", "используйте 'plot_spatial_plan', "
     "'plot_spatial_overlay' или 'plot_spatial_trajectories' из "
     "'mechloop.views.spatial_plan' либо 'animate_spatial' из "
     "'mechloop.views.spatial_animation'"),
    # the language of mechloop info / structure (cli.py)
    (r"no text language (?P<v>'[^']*'|\S+)", "нет языка текста {v}"),
    (r"use --lang en or --lang ru", "укажите --lang en или --lang ru"),
    # the interactive 3-D view's HTML file (views/spatial_html.py)
    (r"no page language (?P<v>'[^']*'|\S+)", "нет языка страницы {v}"),
    (r"use en or ru", "укажите en или ru"),
    # figures of the joint reactions of spatial models (views/spatial_reactions.py)
    (r"this model has no joint reactions", "у этой модели нет реакций в шарнирах"),
    (r"name its kinematic pairs under joints: \(type, bodies, at, axis; see "
     r"(?P<path>\S+)\)", "задайте её кинематические пары в разделе 'joints:' ('type', "
     "'bodies', 'at', 'axis'; см. {path})"),
    (r"unknown part (?P<v>'[^']*'|\S+) of a reaction", "неизвестная часть реакции {v}"),
    (r"use 'force' or 'moment'", "используйте 'force' (сила) или 'moment' (момент)"),
    (r"joint (?P<j>.+?) is spherical: its reaction has no moment",
     "шарнир {j} сферический: у его реакции нет момента"),
    (r"trace its force \(part='force'\)", "постройте годограф его силы ('part=force')"),
    # plots of the dynamics of a spatial model (views/spatial_dynamics.py)
    (r"cannot plot against (?P<v>'[^']*'|\S+) for this model",
     "по оси абсцисс нельзя откладывать {v} для этой модели"),
    (r"use one of: (?P<items>[\w, ]+)", "укажите одно из: {items}"),
    (r"reduced characteristics need a one-input machine; this model has (?P<n>\S+) "
     r"arguments", "приведённые характеристики строятся только для машины с одним "
     "входом; аргументов у этой модели: {n}"),
    (r"plot the balancing loads \(plot \.\.\. balancing\) instead",
     "постройте вместо них уравновешивающие нагрузки ('plot ... balancing')"),
    (r"the summary is not given: the chain breaks at positions (?P<where>.+)",
     "сводные характеристики не приводятся: цепь разрывается в положениях {where}"),
    (r"choose the arguments' range so that the chain closes at every position",
     "выберите диапазон аргументов, при котором цепь замыкается во всех положениях"),
    (r"'(?P<kind>\w+)' is not drawn for a model with spatial contours yet \(it needs the "
     r"machine motion, which the spatial dynamics does not give\)",
     "'{kind}' для модели с пространственными контурами пока не строится (нужно движение "
     "машины, которого пространственная динамика не даёт)"),
    (r"plot one of (?P<items>[\w, ]+), or write the dynamics table with mechloop solve",
     "постройте одно из: {items} — или запишите таблицу динамики командой "
     "'mechloop solve'"),
]
