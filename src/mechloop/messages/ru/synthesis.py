"""Russian of the messages and fixes of synthesis, engines, the solver, the bundled
examples, structure and spatial (src/mechloop/synthesis/, engines/, solve/, bundled/,
structure/, spatial/, modules/)."""

from __future__ import annotations

import re

from mechloop.messages.ru.base import KIND, Entry, quoted

#: A Python repr of the user's text: 'x', or "x" when it holds an apostrophe (or a word
#: without quotes, as the coverage test's samples fill such a hole).
_Q = r"'[^']*'|\"[^\"]*\"|\S+"


def _names(text: str) -> str:
    """"a, b or c" (names the user types: columns, keys, reductions) each in quotes, the
    last one joined by «или»."""
    items = [item.strip() for item in re.split(r", | or ", text) if item.strip()]
    if len(items) < 2:
        return quoted(text)
    return ", ".join(f"'{item}'" for item in items[:-1]) + f" или '{items[-1]}'"


def _place(place: str, case: str) -> str:
    """A place in the model data (the sweep's key path so far): "the model" in Russian
    (``case``: «в» + prepositional, or genitive), any other path in quotes."""
    if place == "the model":
        return "в модели" if case == "in" else "модели"
    return f"в '{place}'" if case == "in" else f"'{place}'"


def _did_you_mean(guess: str | None) -> str:
    """"did you mean a or b? " (the close matches of a misspelt name) in Russian."""
    if not guess:
        return ""
    match = re.fullmatch(r"did you mean (?P<g>.+?)\? ?", guess)
    if match is None:
        return guess
    return f"возможно, имелось в виду {_names(match['g'])}? "


def _course(known: str) -> str:
    """``course tasks 1..31 or `` (the numbers of the course's tasks) in Russian."""
    match = re.fullmatch(r"course tasks (?P<a>\S+)\.\.(?P<b>\S+) or ", known)
    if match is not None:
        return f"номер задания курса ({match['a']}..{match['b']}) или "
    return known


def _solving(what: str) -> str:
    """"1,001 positions of 12 designs" as the object of «расчёт»."""
    match = re.fullmatch(r"(?P<p>[\d,]+) positions(?: of (?P<d>[\d,]+) designs)?", what)
    if match is None:
        return f"расчёт {what}"
    designs = f", проектов: {match['d']}" if match["d"] else ""
    return f"расчёт (положений: {match['p']}{designs})"


_EXPONENTS = {"compression exponent": "показатель политропы сжатия",
              "expansion exponent": "показатель политропы расширения"}
_NOT_SOLVED = {"rates": "скорости (первые производные)",
               "accelerations": "ускорения (вторые производные)"}

#: The ends of a vector as the spatial dynamics' messages name them.
_END = {"tail": "начало", "head": "конец"}


ENTRIES: list[Entry] = [
    # the bundled examples (mechloop examples, mechloop new)
    (r"the bundled examples are not installed", "встроенные примеры не установлены"),
    (r"reinstall mechloop \(pip install --force-reinstall mechloop\)",
     "переустановите пакет ('pip install --force-reinstall mechloop')"),
    (r"no bundled example is called (?P<n>" + _Q + ")", "нет встроенного примера {n}"),
    (r"give (?P<known>.*?)a file name that `mechloop examples` lists",
     lambda m: f"укажите {_course(m['known'])}имя файла из списка 'mechloop examples'"),
    (r"(?P<n>" + _Q + r") matches (?P<k>\S+) examples: (?P<shown>.*)",
     "под {n} подходит несколько примеров ({k}): {shown}"),
    (r"give more of the name, or the course task number",
     "уточните имя или укажите номер задания курса"),
    (r"(?P<p>.+?) already exists \(a project document of (?P<ex>.+?)\): mechloop new does "
     r"not overwrite", "{p} уже существует (документ проекта примера {ex}): 'mechloop new' "
     "не перезаписывает файлы"),
    (r"give another folder, or remove the file first",
     "укажите другую папку или сначала удалите файл"),
    (r"(?P<p>.+?) already exists: mechloop new does not overwrite",
     "{p} уже существует: 'mechloop new' не перезаписывает файлы"),
    (r"give another folder or file name, or remove the file first",
     "укажите другую папку или другое имя файла либо сначала удалите файл"),
    (r"the folder (?P<p>.+?) does not exist", "папка {p} не существует"),
    (r"create it first, or give an existing folder",
     "сначала создайте её или укажите существующую папку"),
    (r"(?P<p>.+?) does not end in (?P<s>\S+)", "имя {p} не оканчивается на {s}"),
    (r"name the copy \*(?P<s>\S+), or give a folder", "назовите копию *{s} или укажите папку"),
    # (the output's own refusals of "cannot write ...: ..." are the views' entries)
    (r"cannot write (?P<p>[^:]+): (?!the folder |no permission )(?!.* is not a folder$)"
     r"(?P<why_tr>.*)", "не удаётся записать {p}: {why_tr}"),
    (r"Permission denied", "нет прав доступа"),
    (r"No such file or directory", "нет такого файла или папки"),
    (r"Read-only file system", "файловая система только для чтения"),
    (r"No space left on device", "на диске не осталось места"),
    (r"Is a directory", "это папка"),
    (r"give a folder you can write to", "укажите папку, в которую у вас есть право записи"),
    # engines: the indicator diagram of an engine or a compressor
    (r"the bore must be positive, got (?P<v>.+)",
     "диаметр цилиндра должен быть положительным, а задано {v}"),
    (r"give the cylinder's diameter", "задайте диаметр цилиндра"),
    (r"(?P<name>[\w.]+) must be positive, got (?P<v>.+)",
     "значение '{name}' должно быть положительным, а задано {v}"),
    (r"give a positive (?!(?:" + KIND + r")$)(?P<name>[\w.]+)",  # a kind: the common entries
     "задайте положительное значение '{name}'"),
    (r"an engine has 2 or 4 strokes, got (?P<v>.+)",
     "у двигателя 2 или 4 такта, а задано {v}"),
    (r"give strokes: 2 or strokes: 4", "задайте strokes: 2 или strokes: 4"),
    (r"the compression ratio must exceed 1, got (?P<v>.+)",
     "степень сжатия должна быть больше 1, а задано {v}"),
    (r"typical: 8 to 11 \(spark ignition\), 14 to 22 \(diesel\)",
     "обычно: от 8 до 11 (искровое зажигание), от 14 до 22 (дизель)"),
    (r"the pressure ratio λ and the pre-expansion ρ are at least 1",
     "степень повышения давления λ и степень предварительного расширения ρ — не меньше 1"),
    (r"λ = 1 is combustion at constant pressure, ρ = 1 at constant volume",
     "λ = 1 — сгорание при постоянном давлении, ρ = 1 — при постоянном объёме"),
    (r"the (?P<what>[\w ]+?) must exceed 1, got (?P<v>.+)",
     lambda m: (_EXPONENTS.get(m["what"], f"параметр '{m['what']}'") + " должен быть "
                f"больше 1, а задано {m['v']}")),
    (r"typical: (?P<a>[\d.]+) to (?P<b>[\d.]+) \(compression\), (?P<c>[\d.]+) to "
     r"(?P<d>[\d.]+) \(expansion\)", "обычно: от {a} до {b} (сжатие), от {c} до {d} "
     "(расширение)"),
    (r"typical: (?P<a>[\d.]+) to (?P<b>[\d.]+)", "обычно: от {a} до {b}"),
    (r"a four-stroke cycle needs its exhaust pressure",
     "четырёхтактному циклу нужно давление выпуска"),
    (r"give exhaust: \(e\.g\. (?P<ex>[^)]*)\)", "задайте exhaust: (например, {ex})"),
    (r"a four-stroke engine has no exhaust port share",
     "у четырёхтактного двигателя нет выпускных окон (доли хода 'exhaust_port')"),
    (r"leave out exhaust_port \(it is for strokes: 2\)",
     "уберите 'exhaust_port' (он только для strokes: 2)"),
    (r"a two-stroke engine exhausts through its port into the scavenging pressure: it has "
     r"no exhaust line", "двухтактный двигатель выпускает газы через окна при давлении "
     "продувки: линии выпуска у него нет"),
    (r"leave out exhaust; give exhaust_port", "уберите 'exhaust' и задайте 'exhaust_port'"),
    (r"the exhaust port's share of the stroke is in \[0, 1\), got (?P<v>.+)",
     "доля хода, на которой открыты выпускные окна, лежит в [0, 1), а задано {v}"),
    (r"the pre-expansion ρ = (?P<v>\S+) ends beyond where expansion ends",
     "предварительное расширение ρ = {v} заканчивается дальше конца расширения"),
    (r"keep ρ ≤ (?P<v>\S+) \(V at the end of expansion over V_c\)",
     "задайте ρ ≤ {v} (отношение объёма V в конце расширения к V_c)"),
    (r"the discharge pressure must exceed the suction pressure",
     "давление нагнетания должно быть больше давления всасывания"),
    (r"give discharge > suction", "задайте 'discharge' > 'suction'"),
    (r"the clearance gas re-expands over the whole stroke: the compressor delivers nothing",
     "газ из мёртвого пространства расширяется на всём ходе: компрессор ничего не подаёт"),
    (r"lower clearance or discharge \(volumetric efficiency 1 − c·\(π\^\(1/n_e\) − 1\) "
     r"must be > 0\)", "уменьшите 'clearance' или 'discharge' (объёмный коэффициент "
     "1 − c·(π^(1/n_e) − 1) должен быть > 0)"),
    (r"the exhaust port opens (?P<v>\S+) deg after top dead centre",
     "выпускные окна открываются через {v} deg после верхней мёртвой точки"),
    (r"give an angle between 0 and 180 deg \(typical: 100 to 120\)",
     "задайте угол от 0 до 180 deg (обычно от 100 до 120)"),
    (r"the gas force needs the piston's whole stroke, but the crank turns by (?P<v>\S+) "
     r"deg over the positions", "для силы давления газов нужен весь ход поршня, а "
     "кривошип поворачивается по положениям лишь на {v} deg"),
    (r"let the crank's argument cover at least a whole turn",
     "пусть аргумент кривошипа охватывает хотя бы полный оборот"),
    (r"the gas force needs the crank's angle to grow from position to position",
     "для силы давления газов угол кривошипа должен расти от положения к положению"),
    (r"give the crank's argument increasing values",
     "задайте аргументу кривошипа возрастающие значения"),
    (r"head is \+1 or -1, got (?P<v>.+)", "'head' — это +1 или -1, а задано {v}"),
    (r"\+1: x is largest at top dead centre", "+1: x наибольший в верхней мёртвой точке"),
    (r"a four-stroke cycle takes two turns of the crank, but its angle spans (?P<v>\S+) "
     r"deg over the positions", "четырёхтактный цикл занимает два оборота кривошипа, а "
     "его угол по положениям охватывает лишь {v} deg"),
    (r"let the crank's argument cover 720 deg \(and time: \{rpm: \.\.\., turns: 2\}\)",
     "пусть аргумент кривошипа охватывает 720 deg (и time: {{rpm: ..., turns: 2}})"),
    (r"the piston does not move: its stroke is zero", "поршень не движется: его ход равен нулю"),
    (r"name the parameter that places the piston \(piston: rK\)",
     "укажите параметр, задающий положение поршня (piston: rK)"),
    # solving many designs (solve_designs) and the memory they need
    (r"the (?P<what>.+?) were not solved: these results come from solve_designs\(\.\.\., "
     r"derivatives=False\), which solves positions only",
     lambda m: (_NOT_SOLVED.get(m["what"], f"'{m['what']}'") + " не вычислялись: эти "
                "результаты получены 'solve_designs(..., derivatives=False)', которая "
                "решает только положения")),
    (r"call solve_designs\(\.\.\., derivatives=True\)",
     "вызовите 'solve_designs(..., derivatives=True)'"),
    (r"positions (?P<list>.+?) were not solved", "положения {list} не решались"),
    (r"solve them: solve_designs\(\.\.\., positions=\.\.\.\)",
     "решите их: 'solve_designs(..., positions=...)'"),
    (r"positions must increase within 0\.\.(?P<n>\S+)",
     "номера положений должны возрастать в пределах 0..{n}"),
    (r"pass sorted, distinct position numbers",
     "передайте упорядоченные неповторяющиеся номера положений"),
    (r"a contour with variant auto follows its neighbours: it is solved at every position",
     "контур с вариантом 'auto' следует за соседними положениями: он решается в каждом "
     "положении"),
    (r"give its variant as 1 or 2", "задайте его вариант сборки: 1 или 2"),
    (r"a coupled block is continued from position to position: it is solved at every "
     r"position", "связанный блок продолжается от положения к положению: он решается в "
     "каждом положении"),
    (r"solve every position \(positions=None\)", "решайте все положения ('positions=None')"),
    (r"(?P<names>.+?) is scaled by a link ratio, so its whole turns are followed from "
     r"position to position: it is solved at every position", "{names}: угол умножается "
     "на передаточное отношение ссылки, поэтому его полные обороты отслеживаются от "
     "положения к положению: он решается в каждом положении"),
    (r"inputs need the shape \(D, K\), got (?P<s>.+)",
     "входным значениям ('inputs') нужна форма (D, K), а получена {s}"),
    (r"pass one row of argument values per design",
     "передайте по одной строке значений аргументов на проект"),
    (r"every varied parameter needs one value per design",
     "каждому варьируемому параметру нужно по одному значению на проект"),
    (r"pass 1-D arrays of one length \(got shapes (?P<s>.*)\)",
     "передайте одномерные массивы одной длины (получены формы {s})"),
    (r"inputs need one row per design \((?P<n>[^)]*)\) and a model with argument 1",
     "входным значениям ('inputs') нужно по строке на проект ({n}) и модель с аргументом 1"),
    (r"got inputs of shape (?P<s>.+)", "получены входные значения формы {s}"),
    (r"cannot vary (?P<names>.+?): only constants, link deltas and argument offsets can "
     r"differ between designs", "нельзя варьировать {names}: между проектами могут "
     "различаться только постоянные, приращения ссылок ('delta') и смещения аргументов "
     "('offset')"),
    (r"vary a parameter whose role is a number, a link or an argument",
     "варьируйте параметр, роль которого — число, ссылка или аргумент"),
    (r"the model has no argument (?P<k>\S+)", "в модели нет аргумента {k}"),
    (r"use one of (?P<list>\[[^\]]*\])", "используйте один из: {list}"),
    (r"solving (?P<what>.+?) needs about (?P<need>.+?) of memory; this machine has "
     r"(?P<avail>.+?) available", lambda m: (f"{_solving(m['what'])} требует около "
                                             f"{m['need']} памяти; на этой машине "
                                             f"доступно {m['avail']}")),
    (r"use fewer positions \(at most about (?P<n>\S+) here\)(?P<d> or fewer designs)?",
     lambda m: (f"возьмите меньше положений (здесь не больше примерно {m['n']})"
                + (" или меньше проектов" if m["d"] else ""))),
    # the model's checks: four-bar types, arguments, intermediate arguments, envelopes
    (r"the model has no four-bar loop driven by a crank \(a Pl4 contour whose only moving "
     r"known vector is a constant length turned by an argument\), so its four-bar type is "
     r"undefined", "в модели нет шарнирного четырёхзвенника с кривошипом (контура Pl4, "
     "в котором единственный подвижный известный вектор имеет постоянную длину и "
     "поворачивается аргументом), поэтому тип четырёхзвенника не определён"),
    (r"remove '(?P<k>[^']*)', or model the four-bar as one contour crank, coupler, rocker, "
     r"frame", "удалите '{k}' или опишите четырёхзвенник одним контуром: кривошип, шатун, "
     "коромысло, стойка"),
    (r"the model has no time and argument (?P<k>\S+) does not change at positions "
     r"(?P<list>.+?): derivatives with respect to it are undefined there",
     "у модели нет времени, а аргумент {k} не меняется в положениях {list}: производные "
     "по нему там не определены"),
    (r"give the model a time \(time: \{rpm: \.\.\.\} or time: \{table: \.\.\.\}\)",
     "задайте модели время (time: {{rpm: ...}} или time: {{table: ...}})"),
    (r"the model has no intermediate argument",
     "в модели нет промежуточного аргумента ('intermediate')"),
    (r"declare one: (?P<ex>arguments: .*)", "объявите его: {ex}"),
    (r"sweeping argument (?P<k>\S+) over (?P<n>\S+) values in (?P<p>\S+) positions needs "
     r"about (?P<g>\S+) GiB of memory; this machine has (?P<a>\S+) GiB available",
     "перебор аргумента {k} по {n} значениям в {p} положениях требует около {g} GiB "
     "памяти; на этой машине доступно {a} GiB"),
    (r"sweep fewer values \(at most about (?P<n>\S+) here\) or use fewer positions",
     "возьмите меньше значений (здесь не больше примерно {n}) или меньше положений"),
    (r"(?P<names>.+?) is scaled by a link ratio: its whole turns are followed along the "
     r"positions, which the envelope's points \(each at its own position\) do not have "
     r"\(not built\)", "{names}: угол умножается на передаточное отношение ссылки, и его "
     "полные обороты отслеживаются вдоль положений, а у точек огибающей (каждая в своём "
     "положении) такой последовательности нет (огибающая не построена)"),
    (r"link the ratio to an argument or a constant, or leave out the envelope of this chain",
     "свяжите отношение с аргументом или постоянной либо не стройте огибающую этой цепи"),
    (r"contour (?P<c>\S+) follows its variant from position to position \(auto\); an "
     r"envelope point is solved at its own position alone", "контур {c} выбирает вариант "
     "сборки по соседним положениям ('auto'), а точка огибающей решается только в своём "
     "положении"),
    (r"give the contour's variant as 1 or 2", "задайте вариант сборки контура: 1 или 2"),
    (r"a(?P<n>\S+) \(body (?P<b>\S+)\) is linked with a ratio to a(?P<m>\S+), which is in "
     r"no body: the gear it meshes with is not a link of the mechanism",
     "a{n} (звено {b}) связан передаточным отношением с a{m}, который не входит ни в одно "
     "звено: парное ему зубчатое колесо — не звено механизма"),
    (r"add vector (?P<v>\S+) to the body of the driving gear",
     "добавьте вектор {v} в звено ведущего колеса"),
    # synthesis: the task, the targets, the criteria, the search
    (r"contour (?P<c>\S+) is solved by no module, which has one circuit",
     "контуру {c} не соответствует ни один модуль с двумя ветвями сборки"),
    (r"contour (?P<c>\S+) is solved by (?P<m>.+?), which has one circuit",
     "контур {c} решается модулем {m}, у которого одна ветвь сборки"),
    (r"list contours of Pl3 or Pl4 modules", "перечислите контуры модулей Pl3 или Pl4"),
    (r"design (?P<i>\([^)]*\)|\S+) \((?P<bad>\S+) of (?P<n>\S+) fail\): (?P<msg_tr>.*)",
     "проект {i} (не решаются {bad} из {n}): {msg_tr}"),
    (r"x1 = x0: the input range is empty", "x1 = x0: диапазон входа пуст"),
    (r"give x0 ≠ x1", "задайте x0 ≠ x1"),
    (r"f\(x1\) = f\(x0\): the output range is empty, so ψ cannot be mapped from y",
     "f(x1) = f(x0): диапазон выхода пуст, поэтому ψ нельзя получить из y"),
    (r"choose a range \[x0, x1\] over which f changes",
     "выберите диапазон [x0, x1], на котором f меняется"),
    (r"unknown scheduler (?P<s>.+)", "неизвестный планировщик {s}"),
    (r"use 'serial', 'processes' or the address of a running dask\.distributed scheduler, "
     r"e\.g\. '(?P<ex>[^']*)'", "укажите 'serial', 'processes' или адрес запущенного "
     "планировщика 'dask.distributed', например '{ex}'"),
    (r"cannot reach the dask scheduler at (?P<a>\S+) \((?P<why>.*)\)",
     "нет связи с планировщиком 'dask' по адресу {a} ({why})"),
    (r"start one with 'dask scheduler' and attach workers with 'dask worker (?P<a>[^']*)', "
     r"or use the 'processes' scheduler", "запустите его командой 'dask scheduler' и "
     "подключите исполнителей командой 'dask worker {a}' или используйте планировщик "
     "'processes'"),
    (r"the dask scheduler at (?P<a>\S+) has no workers",
     "у планировщика 'dask' по адресу {a} нет исполнителей"),
    (r"attach some with 'dask worker (?P<a>[^']*)'",
     "подключите их командой 'dask worker {a}'"),
    (r"cannot evaluate (?P<t>" + _Q + r"): (?P<why>.*)", "не удаётся вычислить {t}: {why}"),
    (r"use (?P<names>.+?) and functions like sin, log10, sqrt",
     lambda m: f"используйте {quoted(m['names'])} и функции вроде 'sin', 'log10', 'sqrt'"),
    (r"the model has no synthesis task", "в модели нет задачи синтеза"),
    (r"add a synthesis: section \(see (?P<ex>[^)]*)\)",
     "добавьте раздел 'synthesis:' (см. {ex})"),
    (r"a relative target needs a value at position 0",
     "относительной цели ('relative') нужно значение в положении 0"),
    (r"add position 0 to the table, or set relative: false",
     "добавьте положение 0 в таблицу или задайте 'relative: false'"),
    (r"timing: free needs argument 1 to run one way over the positions \(its range is where "
     r"the targets may be reached\)", "при 'timing: free' аргумент 1 должен меняться "
     "монотонно по положениям (его диапазон — область, где могут достигаться цели)"),
    (r"give argument 1 a monotonic table or law",
     "задайте аргументу 1 монотонную таблицу или закон"),
    (r"no column (?P<c>" + _Q + r") in the tables of this model",
     "в таблицах этой модели нет столбца {c}"),
    (r"did you mean [^'?]+\?", lambda m: _did_you_mean(m[0]).rstrip()),
    (r"see the columns of mechloop solve and energy",
     "см. столбцы команд 'mechloop solve' и 'mechloop energy'"),
    (r"the starts of contours refer to each other in a cycle",
     "начала контуров ('start') ссылаются друг на друга по кругу"),
    (r"start one of them at the origin or at \[x, y\]",
     "начните один из них в начале координат или в точке [x, y]"),
    (r"an array of starting designs has shape (?P<s>.+?), not \(S, V\) or \(V,\) with "
     r"V = (?P<v>\S+)", "массив начальных проектов имеет форму {s}, а не (S, V) или (V,) "
     "при V = {v}"),
    (r"give one column per variable: (?P<names>.*)",
     lambda m: f"задайте по одному столбцу на переменную: {quoted(m['names'])}"),
    (r"r(?P<n>\S+) is driven by argument (?P<k>\S+), which a scaled placement cannot scale",
     "r{n} задаётся аргументом {k}, а масштабируемое размещение не может его "
     "масштабировать"),
    (r"set frame: \{scale: false\}", "задайте 'frame: {{scale: false}}'"),
    # parameter sweeps (mechloop sweep)
    (r"cannot read the range (?P<t>" + _Q + r") \((?P<why>.*)\)",
     "не удаётся прочитать диапазон {t} ({why})"),
    (r"cannot read the range (?P<t>" + _Q + ")", "не удаётся прочитать диапазон {t}"),
    (r"write start:stop:count, e\.g\. (?P<ex>.*)",
     "запишите 'начало:конец:количество', например {ex}"),
    (r"the count (?P<c>" + _Q + r") of the range (?P<t>" + _Q + r") is not a whole number",
     "количество {c} в диапазоне {t} — не целое число"),
    (r"the range (?P<t>" + _Q + r") has no values", "в диапазоне {t} нет значений"),
    (r"give a count of 1 or more", "задайте количество не меньше 1"),
    (r"an empty value in (?P<t>" + _Q + ")", "пустое значение в {t}"),
    (r"separate values by commas: 1000,2000,3000, or give a range 1000:4000:7",
     "разделяйте значения запятыми: 1000,2000,3000 — или задайте диапазон 1000:4000:7"),
    (r"give start and stop as numbers or in one kind of unit, e\.g\. (?P<ex>.*)",
     "задайте начало и конец числами или в единицах одного рода, например {ex}"),
    (r"cannot read (?P<t>" + _Q + r") as PATH=VALUES",
     "не удаётся прочитать {t} как ПУТЬ=ЗНАЧЕНИЯ"),
    (r"write e\.g\. time\.rpm=1000:4000:7 or vectors\.2\.r=0\.15,0\.2,0\.25",
     "например: 'time.rpm=1000:4000:7' или 'vectors.2.r=0.15,0.2,0.25'"),
    (r"(?P<p>[^:\s]+): no values to sweep", "{p}: нет значений для перебора"),
    (r"give a list of values or a range start:stop:count",
     "задайте список значений или диапазон 'начало:конец:количество'"),
    (r"cannot read the parameter path (?P<t>" + _Q + ")",
     "не удаётся прочитать путь к параметру {t}"),
    (r"write keys separated by dots, as in the model file: vectors\.3\.r, time\.rpm, "
     r"bodies\.2\.mass", "запишите ключи через точку, как в файле модели: 'vectors.3.r', "
     "'time.rpm', 'bodies.2.mass'"),
    (r"(?P<path>[^:\s]+): (?P<place>the model|\S+) has no key (?P<k>" + _Q + ")",
     lambda m: f"{m['path']}: {_place(m['place'], 'in')} нет ключа {m['k']}"),
    (r"use one of the keys of (?P<place>the model|\S+): (?P<valid>.*)",
     lambda m: (f"используйте один из ключей {_place(m['place'], 'of')}: "
                + ("их нет" if m["valid"] == "none" else quoted(m["valid"])))),
    (r"(?P<path>[^:\s]+): (?P<place>the model|\S+) is a list of (?P<n>\S+) item\(s\), (?P<k>" + _Q
     + r") is not one of its indices",
     lambda m: (f"{m['path']}: {_place(m['place'], 'of')} — список (элементов: {m['n']}), "
                f"и {m['k']} — не его индекс")),
    (r"use an index 0\.\.(?P<n>\S+)", "используйте индекс 0..{n}"),
    (r"the model has no (?P<place>\S+); add one to the model first",
     "список '{place}' в модели пуст; сначала добавьте в него элемент"),
    (r"(?P<path>[^:\s]+): (?P<place>the model|\S+) is not set in this model",
     "{path}: ключ '{place}' в этой модели не задан"),
    (r"add '(?P<k>[^']*):' to the model first, then sweep (?P<path>.+)",
     "сначала добавьте '{k}:' в модель, затем перебирайте '{path}'"),
    (r"(?P<path>[^:\s]+): (?P<place>the model|\S+) is a single value \((?P<v>.*)\), it has no key "
     r"(?P<k>" + _Q + ")", lambda m: (f"{m['path']}: {_place(m['place'], 'of')} — одно "
                                      f"значение ({m['v']}), ключа {m['k']} у него нет")),
    (r"sweep (?P<place>.+) itself", "перебирайте сам параметр '{place}'"),
    (r"(?P<path>\S+) is a group of settings, not a number",
     "'{path}' — группа настроек, а не число"),
    (r"name one of its keys: (?P<keys>.*)",
     lambda m: f"укажите один из его ключей: {quoted(m['keys'])}"),
    (r"(?P<path>\S+) is a list, not a number", "'{path}' — список, а не число"),
    (r"name one of its items: (?P<a>\S+) \.\. (?P<b>\S+)",
     "укажите один из его элементов: '{a}' .. '{b}'"),
    (r"sweep a number", "перебирайте число"),
    (r"(?P<path>[^:\s]+): cannot read (?P<v>" + _Q + r") as a value in (?P<u>.+?) "
     r"\((?P<why>.*)\)", "{path}: не удаётся прочитать {v} как значение в {u} ({why})"),
    (r"write a number \(in (?P<u>.+?), the model's unit\) or a number with a unit of the "
     r"same kind, e\.g\. '(?P<ex>[^']*)'", "запишите число (в {u}, единицах модели) или "
     "число с единицей того же рода, например '{ex}'"),
    (r"a sweep varies one or two parameters, not (?P<n>\S+)",
     "перебор варьирует один или два параметра, а не {n}"),
    (r"give one parameter \(a line\) or two \(a grid\), e\.g\. (?P<ex>.*)",
     "задайте один параметр (линия) или два (сетка), например {ex}"),
    (r"(?P<path>\S+) is varied twice", "'{path}' варьируется дважды"),
    (r"vary each parameter once", "варьируйте каждый параметр один раз"),
    (r"at=(?P<k>\S+): no position (?P<k2>\S+); the positions are 0\.\.(?P<n>\S+)",
     "'at={k}': нет положения {k2}; положения: 0..{n}"),
    (r"use at=K with K from 0 to (?P<n>\S+)", "используйте 'at=K' при K от 0 до {n}"),
    (r"unknown reduction (?P<r>" + _Q + ")", "неизвестная свёртка столбца {r}"),
    (r"(?P<g>(?:did you mean .+?\? )?|\S*)use one of (?P<list>.+?), or at=K \(the value at "
     r"position K\)", lambda m: (f"{_did_you_mean(m['g'])}используйте одну из свёрток: "
                                 f"{quoted(m['list'])} или 'at=K' (значение в положении K)")),
    (r"cannot read the quantity (?P<q>" + _Q + ")", "не удаётся прочитать величину {q}"),
    (r"write COLUMN:REDUCTION, e\.g\. (?P<ex>.*)",
     lambda m: f"запишите СТОЛБЕЦ:СВЁРТКА, например {_names(m['ex'])}"),
    (r"no column (?P<c>" + _Q + r") in the results of this model",
     "в результатах этой модели нет столбца {c}"),
    (r"(?P<g>(?:did you mean .+?\? )?)columns: (?P<cols>.*?)(?P<extra>; dynamic columns "
     r"\(M_bal, J_red, R<joint>, \.\.\.\) need a model with bodies)?",
     lambda m: (f"{_did_you_mean(m['g'])}столбцы: {quoted(m['cols'])}"
                + ("; столбцы динамики (M_bal, J_red, R<шарнир>, ...) есть только у модели "
                   "со звеньями ('bodies:')" if m["extra"] else ""))),
    (r"no quantity to collect", "не задано ни одной величины для сбора"),
    (r"name at least one, e\.g\. (?P<ex>.*)",
     lambda m: f"назовите хотя бы одну, например {_names(m['ex'])}"),
    (r"a quantity is collected twice", "величина собирается дважды"),
    (r"collect each quantity once", "собирайте каждую величину один раз"),
    (r"(?P<q>[^:\s]+):(?P<r>\S+): no position (?P<k>\S+); the positions of this model are "
     r"0\.\.(?P<n>\S+)", "'{q}:{r}': нет положения {k}; положения этой модели: 0..{n}"),
    (r"a grid needs a two-parameter sweep; this one has (?P<n>\S+)",
     "для сетки нужен перебор двух параметров, а здесь их {n}"),
    (r"sweep two parameters", "перебирайте два параметра"),
    # spatial contours (spatial/solve.py)
    (r"pass 1-D arrays of one length", "передайте одномерные массивы одной длины"),
    # coupled blocks of spatial contours (spatial/blocks.py)
    (r"contour (?P<c>\S+) is solved in a coupled block, whose variant is 1 \(a negative "
     r"Jacobian determinant\) or 2 \(positive\); variant (?P<v>\S+) does not apply",
     "контур {c} решается в связанном блоке, у которого вариант 1 (отрицательный "
     "определитель матрицы Якоби) или 2 (положительный); вариант {v} неприменим"),
    # spatial dynamics (spatial/bodies.py, spatial/loads.py, spatial/dynamics.py)
    (r"vectors (?P<a>\S+) and (?P<b>\S+) of body (?P<n>\S+) turn relative to each other, so "
     r"they are not fixed in one body", "векторы {a} и {b} звена {n} поворачиваются друг "
     "относительно друга, поэтому они не закреплены в одном звене"),
    (r"list in a body only vectors that move together \(split it into bodies\)",
     "указывайте в звене только векторы, движущиеся вместе (разделите его на звенья)"),
    (r"'rod' needs the centre on the body's first vector \(the rod's axis, e1\), of constant "
     r"length", "для 'rod' центр масс должен лежать на первом векторе звена (оси стержня, "
     "e1) постоянной длины"),
    (r"give the tensor: inertia: \[Jx, Jy, Jz\]", "задайте тензор: inertia: [Jx, Jy, Jz]"),
    (r"a body of a model with spatial contours needs its inertia tensor, not one moment of "
     r"inertia", "звену модели с пространственными контурами нужен тензор инерции, а не "
     "один момент инерции"),
    (r"give inertia: \[Jx, Jy, Jz\] \(principal, in the body frame\) or the 3×3 tensor "
     r"\[\[Jxx, Jxy, Jxz\], \[Jxy, Jyy, Jyz\], \[Jxz, Jyz, Jzz\]\]",
     "задайте inertia: [Jx, Jy, Jz] (главные моменты в системе координат звена) или "
     "тензор 3×3 [[Jxx, Jxy, Jxz], [Jxy, Jyy, Jyz], [Jxz, Jyz, Jzz]]"),
    (r"an inertia tensor is \[Jx, Jy, Jz\] or 3 rows of 3",
     "тензор инерции — это [Jx, Jy, Jz] или 3 строки по 3 числа"),
    (r"give inertia: \[Jx, Jy, Jz\] or \[\[Jxx, Jxy, Jxz\], \[Jxy, Jyy, Jyz\], \[Jxz, Jyz, "
     r"Jzz\]\]", "задайте inertia: [Jx, Jy, Jz] или [[Jxx, Jxy, Jxz], [Jxy, Jyy, Jyz], "
     "[Jxz, Jyz, Jzz]]"),
    (r"an inertia tensor is symmetric \(Jxy = Jyx, \.\.\.\)",
     "тензор инерции симметричен (Jxy = Jyx, ...)"),
    (r"make the rows and columns equal", "сделайте строки равными столбцам"),
    (r"these moments of inertia belong to no body \(each principal moment is ≥ 0 and at most "
     r"the sum of the other two\)", "таких моментов инерции не бывает ни у какого тела "
     "(каждый главный момент ≥ 0 и не больше суммы двух других)"),
    (r"check the values and their signs", "проверьте значения и их знаки"),
    (r"body (?P<n>\S+) lists vector (?P<v>\S+), which is not defined",
     "в звене {n} указан вектор {v}, который не задан"),
    (r"'across' has no side in a model with spatial contours",
     "у 'across' нет стороны в модели с пространственными контурами"),
    (r"place the centre on the vector \(share or along\)",
     "поместите центр масс на вектор ('share' или 'along')"),
    (r"vector (?P<v>\S+) changes length, so this point is not fixed in the body",
     "вектор {v} меняет длину, поэтому эта точка не закреплена в звене"),
    (r"put the centre at the (?P<end>\S+) of vector (?P<v>\S+), or on a vector of "
     r"constant length", lambda m: "поместите центр масс в "
     f"{_END.get(m['end'], m['end'])} вектора {m['v']} или на вектор постоянной длины"),
    (r"the vectors of body (?P<n>\S+) are parallel, so its spin about them is not known: its "
     r"tensor must be symmetric about them", "векторы звена {n} параллельны, поэтому его "
     "вращение вокруг них неизвестно: тензор должен быть симметричен относительно них"),
    (r"give inertia: \[J_axis, J, J\] \(J_axis about the vectors' line\)",
     "задайте inertia: [J_axis, J, J] (J_axis — относительно линии векторов)"),
    (r"the model has no moving body", "в модели нет подвижных звеньев"),
    (r"list the moving bodies with their vectors",
     "перечислите подвижные звенья с их векторами"),
    (r"a direction needs a non-zero component",
     "у направления должна быть ненулевая составляющая"),
    (r"give \[x, y, z\] with at least one component not 0",
     "задайте [x, y, z], где хотя бы одна составляющая не 0"),
    (r"expressions and indicator diagrams are not read for a model with spatial contours "
     r"yet", "выражения и индикаторные диаграммы пока не читаются для модели с "
     "пространственными контурами"),
    (r"give a number, a table or law over the positions, or a table over a parameter \{of: "
     r"a1, table: \[\[value, load\], \.\.\.\]\}", "задайте число, таблицу или закон по "
     "положениям либо таблицу по параметру {{of: a1, table: [[значение, нагрузка], ...]}}"),
    (r"'when' is not read for a model with spatial contours yet",
     "'when' пока не читается для модели с пространственными контурами"),
    (r"remove 'when'", "удалите 'when'"),
    (r"in a model with spatial contours a force along a vector has no angle to it",
     "в модели с пространственными контурами у силы вдоль вектора нет угла к нему"),
    (r"remove 'angle', or give 'direction: \[x, y, z\]'",
     "удалите 'angle' или задайте 'direction: [x, y, z]'"),
    # the structure of a spatial model (structure/spatial.py)
    (r"body (?P<b>\d+) is joined to the ground by no pair found from the contours \(they "
     r"pass between its vectors and the others' through vectors of no body\)",
     "звено {b} не соединено со стойкой ни одной парой, найденной по контурам (контуры "
     "переходят от его векторов к векторам других звеньев через векторы, не входящие ни в "
     "одно звено)"),
    (r"list the vectors that meet it in the bodies they belong to, so that a contour "
     r"passes from one body to another at each pair", "перечислите сходящиеся с ним "
     "векторы в звеньях, которым они принадлежат, чтобы контур переходил от звена к звену "
     "в каждой паре"),
    (r"the planar structural analysis \(Chebyshev's count, Assur groups\) does not apply "
     r"to a model with spatial contours", "плоский структурный анализ (формула Чебышева, "
     "группы Ассура) не применим к модели с пространственными контурами"),
    (r"use mechloop\.structure\.spatial\.spatial_structure\(model\)",
     "используйте 'mechloop.structure.spatial.spatial_structure(model)'"),
    # the structure of a spatial model without bodies (structure/spatial_vectors.py)
    (r"the model has no bodies, and vector (?P<v>\d+) changes length: the contours alone "
     r"do not tell which links hold its ends \(a slider on its guide, a piston in its "
     r"cylinder\)", "в модели нет звеньев ('bodies:'), а вектор {v} меняет длину: по одним "
     "контурам нельзя сказать, какие звенья несут его концы (ползун на направляющей, "
     "поршень в цилиндре)"),
    (r"the model has no bodies, and vector (?P<v>\d+), linked to vector (?P<w>\d+), turns "
     r"relative to it: the two are no rigid link, so the contours alone do not give the "
     r"structure", "в модели нет звеньев ('bodies:'), а вектор {v}, связанный с вектором "
     "{w}, поворачивается относительно него: они не образуют одного жёсткого звена, и по "
     "одним контурам строение не определено"),
    (r"the model has no bodies, and the link of vectors (?P<vs>[\d, ]+) is joined to the "
     r"ground by no pair the contours give", "в модели нет звеньев ('bodies:'), а звено из "
     "векторов {vs} не соединено со стойкой ни одной парой, которую дают контуры"),
    (r"the model has no bodies, and three or more links taken from its vectors meet at one "
     r"point of a contour: which pairs they form is ambiguous", "в модели нет звеньев "
     "('bodies:'), а три звена или больше, взятые из её векторов, сходятся в одной точке "
     "контура: какие пары они образуют, неоднозначно"),
    (r"add bodies: naming the vectors of each link \(with ends: \{K: head\} for the link "
     r"that holds the head of a vector K of varying length\), and joints: for its pairs",
     lambda m: "задайте 'bodies:' с векторами каждого звена ('ends: {K: head}' для звена, "
     "несущего конец вектора K переменной длины) и 'joints:' для его пар"),
]
