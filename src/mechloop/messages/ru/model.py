"""Russian of the messages and fixes of the model's files and checks (src/mechloop/model/):
the vector model's checks (roles, arguments, links, contours, units and ranges), the group
files (points, links, masses, dyads and triads, the input) and the synthesis task."""

from __future__ import annotations

import re

from mechloop.messages.ru.base import KIND, KINDS, Entry, accusative, quoted

#: A user's name as a message shows it: quoted by ``repr`` ('AB', "it's") or bare (AB).
NAME = r"'[^']*'|\"[^\"]*\"|[^\s,:;()]+"


def _q(value: str) -> str:
    """A user's name (or a list of names) in quotes, as a Russian message shows it: a name
    already quoted (by ``repr``) or a list in brackets stays as written."""
    value = value.strip()
    if value[:1] in "'\"[":
        return value
    return ", ".join(f"'{item}'" for item in value.split(", "))


def _quoting(template: str, *names: str):
    """A template whose groups ``names`` are the user's names, put in quotes."""
    def fill(match: re.Match[str]) -> str:
        values = {k: _q(v) if k in names else v for k, v in match.groupdict().items()
                  if v is not None}
        return template.format(**values)
    return fill


def _gen(match: re.Match[str]) -> str:
    """The kind of quantity of ``match`` (group ``k_kind``) in the genitive."""
    return KINDS[match["k_kind"]][1]


def _position_key(match: re.Match[str]) -> str:
    """"start position 7" of a law: the law's key as the model file writes it."""
    where = {"start": "начальное положение", "end": "конечное положение"}.get(match["key"])
    head = where or f"'{match['key']}': положение"
    return (f"{head} {match['p']} вне расчётных положений {match['a']}..{match['b']}")


def _on_links(match: re.Match[str]) -> str:
    """"P is on AB, BC": the point and the link (or links) it lies on."""
    links = match["links"]
    return f"{_q(match['n'])} лежит на " + ("звеньях " if "," in links else "звене ") + _q(links)


def _choose(match: re.Match[str]) -> str:
    """"use one of: A, groups[0].at[1] (what they are)": the names to choose from (key
    paths of a group file too), in quotes."""
    from mechloop.messages.catalogue_ru import translate  # the catalogue holds this module

    return f"допустимо: {quoted(match['items'])} ({translate(match['what'])})"


def _engine_keys(match: re.Match[str]) -> str:
    """"a 4-stroke engine takes exhaust, firing, intake; missing intake; not scavenge"."""
    text = f"{match['n']}-тактному двигателю нужны ключи {quoted(match['own'])}"
    if match["miss"]:
        text += f"; не хватает: {quoted(match['miss'])}"
    if match["extra"]:
        text += f"; лишние: {quoted(match['extra'])}"
    return text


#: Numbers of function parameters a contour needs (2 planar, 3 spatial; in digits or
#: words): nominative and genitive.
_COUNT = {"2": ("два", "двух"), "3": ("три", "трёх"), "two": ("два", "двух"),
          "three": ("три", "трёх")}
_KIND_DAT = {"spatial": "пространственному", "planar": "плоскому"}
#: What ``refuse_spatial`` refuses (model/spatial.py), as the object of «не реализовано».
_REFUSED = {
    "the existence check over the input interval": "проверка существования на интервале входа",
    "solving chosen positions of many designs": "решение выбранных положений многих проектов",
    "solving many designs at once": "одновременное решение многих проектов",
    "the sensitivity to the dimensions": "чувствительность к размерам",
    "the solve over an intermediate argument": "решение по промежуточному аргументу",
}


def _functions_count(match: re.Match[str]) -> str:
    """"contour 2 has 1 function parameter(s) (r3); a spatial contour needs exactly 3"."""
    listed = "нет" if match["list"] == "none" else match["list"]
    kind = _KIND_DAT.get(match["kind"], match["kind"])
    return (f"в контуре {match['c']} искомых параметров ('function'): {match['n']} "
            f"({listed}); {kind} контуру нужно ровно {match['want']}")


def _refused(match: re.Match[str]) -> str:
    """"solving many designs at once is not built for a model with spatial contours yet"."""
    from mechloop.messages.catalogue_ru import translate  # the catalogue holds this module

    what = _REFUSED.get(match["what"]) or translate(match["what"])
    return f"для модели с пространственными контурами пока не реализовано: {what}"


ENTRIES: list[Entry] = [
    # the vector model's checks (model/check.py, model/display.py, model/limits.py)
    (rf"(?P<v>{NAME}) is not a role", "{v} — не роль параметра"),
    (r"(?P<key>\w+) position (?P<p>-?[\w.]+) is outside the calculation positions "
     r"(?P<a>\d+)\.\.(?P<b>[\w.]+)", _position_key),
    (r"model time advances by (?P<d>\S+) s from position (?P<a>\S+) to (?P<b>\S+); the "
     r"shortest step is (?P<m>\S+) s", "время модели растёт на {d} с от положения {a} к "
     "положению {b}; наименьший допустимый шаг — {m} с"),
    (r"give times in seconds, spread over the positions",
     "задайте время в секундах, распределив его по положениям"),
    (r"digits and decimals both given", "заданы и 'digits', и 'decimals'"),
    (r"the file is larger than (?P<n>\S+) MiB, the limit for a model file",
     "файл больше {n} МиБ — предела для файла модели"),
    (r"put long tables in a CSV file \(\{csv: table\.csv\}\) and keep the model small",
     "вынесите длинные таблицы в CSV-файл ({{csv: table.csv}}), чтобы файл модели "
     "оставался небольшим"),
    # numbers and units (model/numbers.py, model/units.py, model/schema.py)
    (r"(?P<v>\S+) is outside the range of a model value \((?P<range_tr>[^()]*)\)",
     "{v} вне диапазона значений модели ({range_tr})"),
    (r"a finite number between (?P<a>\S+) and (?P<b>\S+)", "конечное число от {a} до {b}"),
    (r"a quantity of (?P<n>\S+) characters \(a number and a unit are at most (?P<m>\S+)\)",
     "величина из {n} символов (число с единицей — не длиннее {m})"),
    (r"a quantity of (?P<n>\S+) characters", "величина из {n} символов"),
    (r"the ratio '(?P<v>[^']*)' divides by 0", "в отношении '{v}' деление на 0"),
    (rf"(?P<u>{NAME}) is not a unit of a length of at most (?P<n>\S+) characters with "
     r"small powers", "{u} — не единица: запись единицы не длиннее {n} символов, а степени "
     "в ней небольшие"),
    (rf"unknown unit (?P<u>{NAME})", "неизвестная единица {u}"),
    (rf"(?P<u>{NAME}) is not (?:an? )?(?P<k_kind>{KIND}) unit",
     lambda m: f"{m['u']} — не единица {_gen(m)}"),
    (r"write a number and a unit like '(?P<ex>[^']*)' or '2 kg\*m\^2'",
     "запишите число и единицу, например '{ex}' или '2 kg*m^2'"),
    (r"write a number and a unit like '(?P<ex>[^']*)'",
     "запишите число и единицу, например '{ex}'"),
    (rf"cannot read (?P<v>{NAME}) as (?:an? )?(?P<k_kind>{KIND}): only units take powers, by "
     r"a small number", lambda m: f"не удаётся прочитать {m['v']} как "
     f"{accusative(KINDS[m['k_kind']][0])}: в степень возводят только единицы, и лишь в "
     "небольшую"),
    (rf"cannot read (?P<v>{NAME}) as (?:an? )?(?P<k_kind>{KIND})",
     lambda m: f"не удаётся прочитать {m['v']} как {accusative(KINDS[m['k_kind']][0])}"),
    (rf"(?P<v>{NAME}) has no (?P<k_kind>{KIND}) unit",
     lambda m: f"{m['v']}: нет единицы {_gen(m)}"),
    (rf"write a plain number \(model units\) or a number with an? (?P<k_kind>{KIND}) unit "
     r"\((?P<units>[^)]*)\)", lambda m: "запишите просто число (в единицах модели) или "
     f"число с единицей {_gen(m)}: {m['units']}"),
    (rf"(?P<v>{NAME}) is not (?:an? )?(?P<k_kind>{KIND})",
     lambda m: f"{m['v']} — не {KINDS[m['k_kind']][0]}"),
    (rf"(?P<v>{NAME}) is outside the range of (?:an? )?(?P<k_kind>{KIND}) \("
     r"(?P<range>[^()]*), in the file's units and in (?P<si>[^()]*)\)",
     lambda m: f"{m['v']} вне диапазона {_gen(m)} ("
     + re.sub(r"a finite number between (\S+) and (\S+)", r"конечное число от \1 до \2",
              m["range"]) + f" в единицах файла и в {m['si']})"),
    (rf"write (?:an? )?(?P<k_kind>{KIND}) like '(?P<ex>[^']*)'",
     lambda m: f"запишите {accusative(KINDS[m['k_kind']][0])} в виде '{m['ex']}'"),
    # links, contours and coupled blocks (model/structure.py)
    (r"(?P<p>\S+) links to (?P<q>\S+) with ratio (?P<r>\S+), and (?P<q2>\S+) is solved in "
     r"the same block as contour (?P<c>\S+): a ratio onto an angle of its own coupled block "
     r"is not supported", "{p} ссылается на {q} с передаточным отношением {r}, а {q2} "
     "находится в том же блоке, что и контур {c}: отношение к углу своего же связанного "
     "блока не поддерживается"),
    (r"link (?P<p>\S+) to an angle that an earlier contour solves, to an argument or a "
     r"constant, or use ratio 1", "сошлитесь из {p} на угол, который находит предыдущий "
     "контур, на аргумент или постоянную либо задайте отношение 1 ('ratio: 1')"),
    (r"(?P<p>\S+) links to (?P<q>\S+) with ratio (?P<r>\S+); a ratio is a finite number, "
     r"not 0", "{p} ссылается на {q} с отношением {r}; отношение ('ratio') — конечное "
     "число, не равное 0"),
    (r"give the transmission ratio \(e\.g\. -z1/z2 for an external gear pair\), or remove "
     r"'ratio' for a rigid link", "задайте передаточное отношение (например, -z1/z2 для "
     "внешнего зацепления) или удалите 'ratio' для жёсткой связи"),
    (r"(?P<p>\S+) \((?P<pk_kind>length|angle)\) links to (?P<q>\S+) \((?P<qk_kind>length|"
     r"angle)\); a link joins parameters of the same kind",
     lambda m: (f"{m['p']} ({KINDS[m['pk_kind']][0]}) ссылается на {m['q']} "
                f"({KINDS[m['qk_kind']][0]}); ссылка соединяет параметры одного рода")),
    (r"(?P<p>\S+) links to (?P<q>\S+), but vector (?P<v>\S+) is not defined",
     "{p} ссылается на {q}, но вектор {v} не задан"),
    (r"contour (?P<c>\S+) has (?P<n>\S+) function \w+ \((?P<list>[^)]*)\); a planar "
     r"contour needs exactly 2 \(contours solved together as a coupled block: 2 per "
     r"contour in all, each contour linking to the others' functions\)",
     lambda m: (f"в контуре {m['c']} искомых параметров ('function'): {m['n']} ("
                f"{'нет' if m['list'] == 'none' else m['list']}); плоскому контуру нужно ровно 2 "
                "(для контуров, решаемых вместе связанным блоком, — по 2 на контур, и "
                "каждый контур ссылается на искомые параметры других)")),
    (r"(?P<p>\S+) is not an unknown of the coupled block of contours (?P<list>.+)",
     "{p} — не неизвестная связанного блока контуров {list}"),
    (r"guess some of (?P<list>.+)",
     "задайте начальные приближения для некоторых из неизвестных: {list}"),
    # intermediate arguments and envelopes (model/intermediate.py)
    (r"a model has at most one intermediate argument \(argument (?P<n>\S+) is one\)",
     "в модели может быть не больше одного промежуточного аргумента (аргумент {n} уже "
     "промежуточный)"),
    (r"sweep one argument inside the positions; give the others as tables or laws",
     "перебирайте внутри положений один аргумент; остальные задайте таблицами или "
     "законами"),
    (r"argument (?P<n>\S+) is the first argument, which the positions follow \(derivatives "
     r"are taken along it\): it cannot be intermediate", "аргумент {n} — первый аргумент, "
     "по нему идут положения (и берутся производные): он не может быть промежуточным"),
    (r"give the motion over the positions as a lower-numbered argument \(e\.g\. 1\) and "
     r"sweep a higher-numbered one", "задайте движение по положениям аргументом с меньшим "
     "номером (например, 1), а перебирайте аргумент с большим номером"),
    (r"the sweep starts and ends at the same value",
     "перебор начинается и заканчивается одним и тем же значением"),
    (r"give 'to' different from 'from'", "задайте 'to', отличное от 'from'"),
    (rf"envelope (?P<n>{NAME}) is named twice", "имя огибающей {n} встречается дважды"),
    (r"give every envelope its own name", "дайте каждой огибающей своё имя"),
    (r"no vector (?P<v>\S+) in the model", "в модели нет вектора {v}"),
    (r"use vectors of (?P<list>.+)", "используйте векторы из {list}"),
    (r"the model has no intermediate argument", "в модели нет промежуточного аргумента"),
    (r"say which intermediate argument the envelope sweeps",
     "укажите, какой промежуточный аргумент перебирает огибающая"),
    (r"declare one: arguments: \{K: \{intermediate: \{from: \.\., to: \.\., count: \.\.\}\}\}",
     "объявите его: arguments: {{K: {{intermediate: {{from: .., to: .., count: ..}}}}}}"),
    (r"argument (?P<n>\S+) is not an intermediate argument",
     "аргумент {n} — не промежуточный аргумент"),
    (r"declare it with \{intermediate: \{from: \.\., to: \.\., count: \.\.\}\}",
     "объявите его так: {{intermediate: {{from: .., to: .., count: ..}}}}"),
    (r"use one of (?P<list>\[[\d, ]*\])", "используйте один из аргументов {list}"),
    (r"the end of vectors (?P<list>.+?) does not depend on argument (?P<n>\S+): its curve "
     r"is a single point in every position", "конец векторов {list} не зависит от "
     "аргумента {n}: в каждом положении его кривая вырождается в точку"),
    (r"list the vectors up to one the intermediate argument turns or stretches \(e\.g\. "
     r"the roller's radius\)", "перечислите векторы вплоть до того, который промежуточный "
     "аргумент поворачивает или растягивает (например, радиуса ролика)"),
    # group files: names of points and links (model/groups/names.py, core.py, build.py)
    (rf"(?P<what>point|link) (?P<n>{NAME}) is already defined at (?P<at>\S+)",
     lambda m: ("точка" if m["what"] == "point" else "звено") + f" {_q(m['n'])} уже задан"
     + ("а" if m["what"] == "point" else "о") + f" в '{m['at']}'"),
    (r"'ground' names the fixed link", "'ground' — имя стойки (неподвижного звена)"),
    (r"give the link another name", "дайте звену другое имя"),
    (rf"no link named (?P<n>{NAME})", "нет звена с именем {n}"),
    (rf"no moving link named (?P<n>{NAME})", "нет подвижного звена с именем {n}"),
    (rf"no point named (?P<n>{NAME})", "нет точки с именем {n}"),
    (rf"unknown point (?P<n>{NAME})", "неизвестная точка {n}"),
    (rf"point (?P<n>{NAME}) is not defined yet", "точка {n} ещё не задана"),
    (rf"point (?P<n>{NAME}) is on link (?P<k>{NAME}), defined at (?P<at>\S+): attach this "
     r"group after that one", _quoting("точка {n} лежит на звене {k}, заданном в '{at}': "
     "присоедините эту группу после той", "n", "k")),
    (rf"point (?P<n>{NAME}) is on link (?P<k>{NAME}), which no group defines",
     _quoting("точка {n} лежит на звене {k}, которое не задаёт ни одна группа", "n", "k")),
    (rf"(?P<n>{NAME}) is defined by (?P<where>\S+) \((?P<at>[^()]*)\): a group can only "
     r"use points of the ground, the input and earlier groups — move this group after "
     r"that one", _quoting("точка {n} задана в '{where}' ('{at}'): группа может "
                           "использовать только точки стойки, входного звена и предыдущих "
                           "групп — перенесите эту группу после той", "n")),
    (rf"point (?P<n>{NAME}) joins links (?P<links>.+?): which one is meant is not clear",
     lambda m: f"точка {_q(m['n'])} соединяет звенья "
     + " и ".join(map(_q, m["links"].split(" and "))) + ": неясно, какое из них имеется в виду"),
    (r"write (?P<options>[\w.]+(?: or [\w.]+)+)",
     lambda m: "напишите " + " или ".join(map(_q, m["options"].split(" or ")))),
    (rf"point (?P<n>{NAME}) is not on link (?P<k>{NAME})", "точка {n} не лежит на звене {k}"),
    (r"(?P<n>[^\s,:;]+) is on (?P<links>[^\s,:;]+(?:, [^\s,:;]+)*)", _on_links),
    (r"both attachments are (?P<n>\S+)", _quoting("обе точки присоединения — {n}", "n")),
    (r"attach the group's links at two different points",
     "присоедините звенья группы в двух разных точках"),
    (r"use one of: (?P<items>[\w.\[\], ]+) \((?P<what>[^()]*)\)", _choose),
    (r"dimensions as the file spells them", "размеры так, как они записаны в файле"),
    (r"named points", "именованные точки"),
    (r"the model was not built from this mechanism: its vectors or contours differ",
     "модель построена не по этому механизму: её векторы или контуры другие"),
    (r"pass the model that build_model\(mech\) returned \(its constants may be changed, "
     r"not its vectors\)", "передайте модель, которую вернула 'build_model(mech)' (менять "
     "в ней можно постоянные, но не векторы)"),
    # group files: building the vector model (model/groups/builder.py, files.py, dims)
    (r"report this: the generated model is invalid",
     "сообщите об этом разработчикам: построенная модель неверна"),
    (r"a fixed point is a ground point", "неподвижная точка — это точка стойки ('ground')"),
    (r"move (?P<n>\S+) under ground: with its coordinates \[x, y\]",
     _quoting("перенесите {n} в раздел ground: с её координатами [x, y]", "n")),
    (r"an? (?P<k>\w+) group has one assembly \((?P<why_tr>[^()]*)\)",
     "у группы {k} один вариант сборки ({why_tr})"),
    (r"its slide passes through the guide's pivot",
     "линия её ползуна проходит через шарнир направляющей"),
    (r"its two slides meet in one point", "две её линии скольжения пересекаются в одной точке"),
    (r"its slot and guide meet in one point", "её паз и направляющая пересекаются в одной точке"),
    (r"remove variant \(or write 1\)", "удалите 'variant' (или напишите 1)"),
    (r"'(?P<k>[^']*)' belongs to a vector model, and this file describes the mechanism by "
     r"'groups'", "'{k}' относится к векторной модели, а этот файл описывает механизм "
     "группами ('groups')"),
    (r"remove '(?P<k>[^']*)' \(the groups generate it\), or remove 'groups' and write the "
     r"vector model", "удалите '{k}' (его строят группы) или удалите 'groups' и запишите "
     "векторную модель"),
    (r"a group file names its dimensions in vary:; mechloop writes dimensions: into the "
     r"vector model", "в файле групп размеры перечисляют в vary:, а раздел dimensions: "
     "программа записывает в векторную модель сама"),
    (r"remove dimensions:", "удалите раздел dimensions:"),
    (rf"no dimension named (?P<n>{NAME})", "нет размера с именем {n}"),
    (r"(?P<n>\S+) moves nothing: no contour passes that ground point",
     _quoting("{n} ничего не двигает: ни один контур не проходит через эту точку стойки",
              "n")),
    (r"vary a point that a group uses", "варьируйте точку, которую использует какая-либо "
     "группа"),
    (rf"(?P<n>{NAME}) is a ground point that no vector reaches",
     _quoting("{n} — точка стойки, до которой не доходит ни один вектор", "n")),
    (r"trace a point of a link", "возьмите точку подвижного звена"),
    # group files: the input, dyads, triads, points and masses
    (r"argument (?P<n>\S+) is not defined", "аргумент {n} не задан"),
    (r"add it under arguments: \(e\.g\. (?P<ex>.+?)\) or use one that exists",
     "добавьте его в arguments: (например, {ex}) или используйте существующий"),
    (r"the crank's pivot (?P<n>\S+) is not a ground point",
     _quoting("опорная точка кривошипа {n} — не точка стойки", "n")),
    (r"pivot the crank on a point of ground:", "поставьте опору кривошипа в точку из ground:"),
    (r"the input slider's guide must be fixed in the ground",
     "направляющая входного ползуна должна быть неподвижной (проходить через стойку)"),
    (r"run it through a ground point", "проведите её через точку стойки"),
    (r"the slot runs along the guide, so the yoke's position along it is not determined",
     "паз направлен вдоль направляющей, поэтому положение кулисы вдоль неё не определено"),
    (r"give the slot an angle to the guide \(90 for a Scotch yoke\)",
     "задайте угол паза к направляющей (90 для синусного механизма)"),
    (r"a triad's sliding leg runs along a ground guide here",
     "поводок триады с ползуном может здесь двигаться только по направляющей на стойке"),
    (r"run the guide through a ground point \(a guide on a moving link is not supported in "
     r"a triad\)", "проведите направляющую через точку стойки (направляющая на подвижном "
     "звене в триаде не поддерживается)"),
    (r"two legs share a joint", "у двух поводков общий шарнир"),
    (r"give each leg its own joint on the middle link",
     "дайте каждому поводку свой шарнир на среднем звене"),
    (rf"(?P<n>{NAME}) is not a joint of this triad or a moving point its legs are pinned to",
     "{n} — не шарнир этой триады и не подвижная точка, к которой присоединены её поводки"),
    (r"give approximate positions of (?P<items>.+)",
     _quoting("задайте приближённые положения точек {items}", "items")),
    (r"no approximate position of (?P<items>.+?): a triad has up to six assemblies, and "
     r"these pick one", _quoting("нет приближённого положения точек {items}: у триады до шести "
     "вариантов сборки, и эти положения выбирают один из них", "items")),
    (r"add (?P<n>\S+): \[x, y\] \(where it is at position 0, roughly\) under guess:",
     "добавьте {n}: [x, y] (где примерно точка находится в положении 0) в раздел guess:"),
    (r"point (?P<n>\S+) is measured from (?P<o>\S+), which is listed after it",
     _quoting("точка {n} отложена от {o}, а та записана после неё", "n", "o")),
    (r"list (?P<o>\S+) before (?P<n>\S+) under points:",
     _quoting("запишите {o} раньше {n} в разделе points:", "n", "o")),
    (rf"link (?P<n>{NAME}) has no first point to measure from",
     "у звена {n} нет первой точки, от которой откладывать"),
    (r"give from: a point of the link", "задайте from: точку этого звена"),
    (rf"(?P<o>\S+) is not a fixed point of link (?P<n>{NAME})",
     _quoting("{o} — не точка, закреплённая на звене {n}", "o", "n")),
    (r"measure from one of (?P<items>.+)",
     _quoting("откладывайте от одной из точек: {items}", "items")),
    (rf"link (?P<n>{NAME}) has no second point, so no line to take a share of",
     "у звена {n} нет второй точки, поэтому нет линии, на которой отложить долю ('share')"),
    (r"give a point name or \{from: X, distance: d, angle: φ\}",
     "укажите имя точки или {{from: X, distance: d, angle: φ}}"),
    (rf"(?P<p>{NAME}) is not a point of link (?P<n>{NAME})", "{p} — не точка звена {n}"),
    (rf"link (?P<n>{NAME}) has no vector with a fixed tail to place this point from",
     "у звена {n} нет вектора с закреплённым на звене началом, от которого можно отложить "
     "эту точку"),
    (r"define a point there \(points: \{S: \{link: (?P<n>.+?), from: \.\.\., distance: "
     r"\.\.\., angle: \.\.\.\}\}\) and name it", "задайте там точку (points: {{S: {{link: "
     "{n}, from: ..., distance: ..., angle: ...}}}}) и укажите её имя"),
    (rf"link (?P<n>{NAME}) has a mass but no centre of mass",
     "у звена {n} задана масса, но нет центра масс"),
    (r"add center: a point name, \{share: 0\.5\} or \{from: A, distance: d, angle: φ\}",
     "добавьте center: имя точки, {{share: 0.5}} или {{from: A, distance: d, angle: φ}}"),
    (rf"'rod' needs the length of the link, and (?P<n>{NAME}) has no second point",
     "для 'rod' нужна длина звена, а у звена {n} нет второй точки"),
    (r"give the moment of inertia as a number", "задайте момент инерции числом"),
    # the synthesis task (model/synthesis.py)
    (r"there is no contour (?P<c>\S+)", "контура {c} нет"),
    (r"contours are 1\.\.(?P<n>\S+)", "контуры модели: 1..{n}"),
    (r"contour (?P<c>\S+) does not start at fixed coordinates",
     "начало контура {c} не задано постоянными координатами"),
    (r"give it start: \[x, y\] to vary them",
     "задайте ему start: [x, y], чтобы варьировать их"),
    (r"vectors are (?P<list>\[[^\]]*\]|\S+)", "векторы модели: {list}"),
    (r"(?P<p>\S+) needs vector (?P<v>\S+) with a constant length and angle",
     _quoting("для {p} нужен вектор {v} с постоянными длиной и углом", "p")),
    (r"set r(?P<a>\w+) and a(?P<b>\w+) themselves instead",
     "задайте вместо этого сами r{a} и a{b}"),
    (r"(?P<p>\S+) is a function of its contour, not a dimension",
     "{p} — искомый параметр ('function') своего контура, а не размер"),
    (r"vary a constant, a link's delta or an argument's offset",
     "варьируйте постоянную, смещение ссылки ('delta') или смещение аргумента ('offset')"),
    (rf"dimension (?P<n>{NAME}) sets both lengths and angles",
     "размер {n} задаёт и длины, и углы"),
    (r"give it targets of one kind", "пусть он задаёт величины одного рода"),
    (r"(?P<p>\S+) is a length: only an angle is periodic",
     _quoting("{p} — длина: периодическим бывает только угол", "p")),
    (r"give it bounds \[low, high\]", "задайте ему границы [нижняя, верхняя]"),
    (r"(?P<p>\S+): a link's ratio is not a design variable \(a transmission ratio is fixed "
     r"by the tooth counts\)", "{p}: передаточное отношение ссылки — не проектная "
     "переменная (его задают числа зубьев)"),
    (r"vary (?P<p>\S+) \(the link's delta\), or try each ratio in a model of its own",
     "варьируйте {p} (смещение ссылки) или попробуйте каждое отношение в отдельной модели"),
    (rf"(?P<p>{NAME}) is neither a constant of the model nor a named dimension",
     "{p} — не постоянная модели и не именованный размер"),
    (r"vary 'r3' / 'a5' \(a constant, a link's delta, an argument's offset\), 'start2\.x' / "
     r"'start2\.y', or a name under dimensions:", "варьируйте 'r3' / 'a5' (постоянную, "
     "смещение ссылки, смещение аргумента), 'start2.x' / 'start2.y' или имя из раздела "
     "dimensions:"),
    (rf"(?P<p>\S+) is also set by dimension (?P<n>{NAME})",
     _quoting("{p} уже задан размером {n}", "p", "n")),
    (rf"vary (?P<a>{NAME}) or (?P<b>\S+), not both",
     _quoting("варьируйте {a} или {b}, но не оба", "a", "b")),
    (r"the bounds \[(?P<lo>[^,\]]*), (?P<hi>[^\]]*)\] are empty",
     "границы [{lo}, {hi}] задают пустой интервал"),
    (r"write \[low, high\] with low < high",
     "запишите [нижняя, верхняя], где нижняя граница меньше верхней"),
    (r"positions (?P<list>.+?) are outside 0\.\.(?P<n>\S+)", "положения {list} вне 0..{n}"),
    (r"give positions of the model", "укажите положения модели"),
    (r"with timing, a list of targets has one point per position \((?P<n>\S+)\)",
     "при 'timing: true' в списке целей по одной точке на каждое положение ({n})"),
    (r"or map positions to points: \{0: \[x, y\], 5: \[x, y\]\}",
     "или сопоставьте положениям точки: {{0: [x, y], 5: [x, y]}}"),
    (r"with timing: free the targets are a list: the synthesis chooses where each is "
     r"reached", "при 'timing: free' цели задают списком: синтез сам выбирает, где "
     "достигается каждая"),
    (r"write targets: \[\[x, y\], \.\.\.\], or timing: true to keep the positions",
     "запишите targets: [[x, y], ...] или 'timing: true', чтобы сохранить положения"),
    (r"timing: free varies the value of argument 1, and the model has none",
     "'timing: free' варьирует значение аргумента 1, а в модели его нет"),
    (r"add arguments: \{1: \{table: \.\.\.\}\}(?P<alt>, or timing: false)?",
     lambda m: "добавьте arguments: {1: {table: ...}}"
     + (" или задайте 'timing: false'" if m["alt"] else "")),
    (r"contour (?P<c>\S+) tracks its variant \(auto\); timing: free solves the targets' "
     r"inputs apart from the positions, where a tracked variant is not defined",
     "контур {c} отслеживает свой вариант сборки ('auto'); при 'timing: free' входы "
     "целей находятся отдельно от положений, а там отслеживаемый вариант не определён"),
    (r"contour (?P<c>\S+) tracks its variant \(auto\); a timed curve is solved at the "
     r"targets' inputs apart from the positions, where a tracked variant is not defined",
     "контур {c} отслеживает свой вариант сборки ('auto'); кривая с заданным временем "
     "решается при входах целей отдельно от положений, а там отслеживаемый вариант не "
     "определён"),
    (r"contour (?P<c>\S+) tracks its variant \(auto\): its circuit is not a choice",
     "контур {c} отслеживает свой вариант сборки ('auto'): его ветвь не выбирается"),
    (r"give the contour variant: 1 or 2", "задайте контуру variant: 1 или 2"),
    (r"give it variant: 1 or 2, or leave it out of circuits",
     "задайте ему variant: 1 или 2 либо уберите его из 'circuits'"),
    (r"(?P<k>\w+) applies to timing: free only", "'{k}' действует только при 'timing: free'"),
    (r"remove (?P<k>\w+), or set timing: free", "удалите '{k}' или задайте 'timing: free'"),
    (r"(?P<n>\S+) weights for (?P<m>\S+) targets", "весов {n}, а целей {m}"),
    (r"give one per target", "задайте по одному весу на цель"),
    (r"(?P<k>\S+) is a number of the machine's steady cycle, and the model has no machine: "
     r"section", "'{k}' — величина установившегося цикла машины, а в модели нет раздела "
     "machine:"),
    (r"the flywheel is sized only for a wanted speed fluctuation", "маховик подбирается "
     "только под заданный коэффициент неравномерности хода"),
    (r"give machine: \{delta: \.\.\.\}", "задайте machine: {{delta: ...}}"),
    (r"add machine: \{delta: \.\.\.\} \(see (?P<ex>[^()]*)\)",
     "добавьте machine: {{delta: ...}} (см. {ex})"),
    (r"criterion (?P<n>.+?) has no max, min or minimize",
     "у критерия '{n}' нет ни 'max', ни 'min', ни 'minimize'"),
    (r"give one of them", "задайте один из них"),
    (r"(?P<n>\S+) is not a variable of the task", _quoting("{n} — не переменная задачи", "n")),
    (r"the variables are (?P<list>.+?): add (?P<n>\S+) to vary, or leave it out of the start",
     _quoting("переменные задачи: {list}; добавьте {n} в 'vary' или уберите его из 'start'",
              "list", "n")),
    (r"(?P<n>\S+) = (?P<v>\S+) is outside its bounds \[(?P<lo>[^,\]]*), (?P<hi>[^\]]*)\]",
     _quoting("{n} = {v} вне своих границ [{lo}, {hi}]", "n")),
    (r"give a value within the bounds, or widen vary\.(?P<n>\S+) on purpose",
     "задайте значение в пределах границ или сознательно расширьте 'vary.{n}'"),
    (r"a curve with timing: true reaches target k where argument 1 equals t_k, and the "
     r"model has no argument 1", "кривая при 'timing: true' проходит цель k там, где "
     "аргумент 1 равен t_k, а в модели нет аргумента 1"),
    (r"frame \(shape only\) applies to a path without timing",
     "'frame' (только форма) применяется к траектории без 'timing'"),
    (r"remove frame, or set timing: false", "удалите 'frame' или задайте 'timing: false'"),
    (r"a workspace fixes where the mechanism lies, and frame leaves its placement free",
     "рабочая область ('workspace') закрепляет положение механизма, а 'frame' оставляет "
     "его размещение свободным"),
    (r"remove the workspace or the frame", "удалите 'workspace' или 'frame'"),
    (r"a point's coordinate depends on the placement, which frame leaves free",
     "координата точки зависит от размещения, которое 'frame' оставляет свободным"),
    (r"remove the criterion or the frame", "удалите критерий или 'frame'"),
    # checks of the model's sections by its schema (pydantic's "Value error, …"): loads,
    # elements, expressions, tables, motors, group legs, engines
    (r"give either 'share' \(a fraction of the length\) or 'along' \(a distance from the "
     r"tail\)", "задайте либо 'share' (долю длины), либо 'along' (расстояние от начала "
     "вектора)"),
    (r"the (?P<what>\w+) of the table must increase",
     lambda m: {"lengths": "длины", "speeds": "скорости"}.get(m["what"], f"'{m['what']}'")
     + " в таблице должны возрастать"),
    (r"give either stiffness and free_length \(a linear spring\) or a table of \[length, "
     r"tension\]", "задайте либо 'stiffness' и 'free_length' (линейная пружина), либо "
     "таблицу пар [длина, усилие]"),
    (r"give either a coefficient or a table of \[speed, tension\]",
     "задайте либо коэффициент ('coefficient'), либо таблицу пар [скорость, усилие]"),
    (r"the speeds of a damper's table start at 0 or above \(the table is mirrored for "
     r"negative speeds\)", "скорости в таблице демпфера начинаются с 0 или больше (для "
     "отрицательных скоростей таблица отражается симметрично)"),
    (r"an expression of at most (?P<n>\S+) characters",
     "выражение должно быть не длиннее {n} символов"),
    (rf"cannot read (?P<v>{NAME}): (?P<why_tr>.*)", "не удаётся прочитать выражение {v}: "
     "{why_tr}"),
    (r"invalid syntax(?: \(<unknown>, line \d+\))?", "синтаксическая ошибка"),
    (r"'(?P<c>.)' was never closed(?: \(<unknown>, line \d+\))?", "скобка '{c}' не закрыта"),
    (r"unmatched '(?P<c>.)'(?: \(<unknown>, line \d+\))?", "лишняя скобка '{c}'"),
    (r"(?:invalid decimal literal|invalid character '.*?' \(U\+\w+\))"
     r"(?: \(<unknown>, line \d+\))?", "неверная запись числа или символа"),
    (r"(?:unexpected EOF while parsing|incomplete input|invalid syntax\. Perhaps you forgot "
     r"a comma\?)(?: \(<unknown>, line \d+\))?", "выражение записано не полностью"),
    (r"operator (?P<op>\w+) is not allowed", "операция '{op}' не допускается"),
    (r"comparison (?P<op>\w+) is not allowed", "сравнение '{op}' не допускается"),
    (rf"(?P<v>{NAME}) is not a number", "{v} — не число"),
    (rf"unknown name (?P<n>{NAME}): use t, rK, aK, drK, daK, pi and the functions ?"
     r"(?P<f>.*)", lambda m: f"неизвестное имя {m['n']}: используйте t, rK, aK, drK, daK, "
     f"pi и функции {quoted(m['f'])}".rstrip()),
    (r"only calls like sin\(x\) of ?(?P<f>.*)",
     lambda m: f"допускаются только вызовы вида sin(x) функций {quoted(m['f'])}".rstrip()),
    (r"(?P<k>\w+) is not allowed in an expression",
     "конструкция '{k}' в выражении не допускается"),
    (r"a leg is pinned \(\{at: A, length: l\}\) or slides \(\{guide: \{through: O, angle: "
     r"φ\}\}\): give at and length, or guide", "поводок либо присоединён шарниром "
     "({{at: A, length: l}}), либо скользит ({{guide: {{through: O, angle: φ}}}}): задайте "
     "'at' и 'length' или 'guide'"),
    (r"a leg is pinned \(at, length\) or slides \(guide\), not both", "поводок либо "
     "присоединён шарниром ('at', 'length'), либо скользит ('guide'), но не то и другое "
     "сразу"),
    (r"a driven leg is a drive between its two points, not a link: remove its link",
     "ведущий поводок — это привод между двумя его точками, а не звено: удалите его 'link'"),
    (r"a leg needs link: its name", "поводку нужен link: его имя"),
    (r"the mechanism needs one input: give input: \(a crank or a slider\), or drive one leg "
     r"of a triad \(length: \{argument: 1\}\)", "механизму нужен один вход: задайте input: "
     "(кривошип или ползун) или сделайте ведущим один поводок триады (length: "
     "{{argument: 1}})"),
    (r"a triad's leg is driven and there is an input: drive the mechanism once \(remove "
     r"input:, or give the leg a length\)", "поводок триады ведущий, а вход тоже задан: "
     "механизм приводится в движение один раз (удалите input: или задайте поводку "
     "постоянную длину)"),
    (r"an? (?P<n>\S+)-stroke engine takes (?P<own>[^;]+)(?:; missing (?P<miss>[^;]+))?"
     r"(?:; not (?P<extra>[^;]+))?", _engine_keys),
    (r"give either engine: \{\.\.\.\} or compressor: \{\.\.\.\}",
     "задайте либо engine: {{...}}, либо compressor: {{...}}"),
    (rf"unknown law (?P<v>{NAME})", "неизвестный закон {v}"),
    (r"(?P<path>.+?) is larger than (?P<n>\S+) MiB, the limit for a table",
     "{path} больше {n} МиБ — предела для таблицы"),
    (r"give fewer rows \(one per calculation position at most\)",
     "сократите число строк (не больше одной на расчётное положение)"),
    (r"cannot read (?P<path>\S+) \((?P<why_tr>[^()]*)\)", "не удаётся прочитать {path} "
     "({why_tr})"),
    (r"cannot read (?P<path>.+?) as CSV \((?P<why_tr>.*)\)",
     "не удаётся прочитать {path} как CSV ({why_tr})"),
    (r"No columns to parse from file", "в файле нет столбцов"),
    (r"Error tokenizing data\. C error: Expected (?P<a>\d+) fields in line (?P<n>\d+), saw "
     r"(?P<b>\d+)\s*", "в строке {n} полей {b}, а ожидалось {a}"),
    (r"Permission denied", "нет прав доступа"),
    (r"Is a directory", "это папка, а не файл"),
    (r"No such file or directory", "нет такого файла или папки"),
    (r"(?P<path>\S+) has no value column (?P<c>\S+)", "в {path} нет столбца значений {c}"),
    (r"use 1\.\.(?P<n>\S+) or a header name",
     "укажите номер столбца от 1 до {n} или имя из заголовка"),
    (rf"(?P<path>\S+) has no column (?P<c>{NAME})", "в {path} нет столбца {c}"),
    (r"(?P<file>.+?), line (?P<line>\S+): (?P<k>.*) is outside the range of a position and "
     r"a model value \((?P<range_tr>[^()]*)\)", "{file}, строка {line}: {k} вне диапазона "
     "номера положения и значения модели ({range_tr})"),
    (r"table has (?P<n>\S+) values, expected (?P<m>\S+)",
     "в таблице значений: {n}, а ожидалось {m}"),
    (r"rated_rpm must be below synchronous_rpm \(a motor has a positive slip at its rated "
     r"load\)", "'rated_rpm' должна быть меньше 'synchronous_rpm' (при номинальной нагрузке "
     "скольжение двигателя положительно)"),
    (r"give exactly one characteristic: kloss, linear, table or constant \(got "
     r"(?P<got>[^()]*)\)", lambda m: "задайте ровно одну характеристику: 'kloss', "
     "'linear', 'table' или 'constant' (задано: "
     + ("ни одной" if m["got"] == "none" else quoted(m["got"])) + ")"),
    (r"the speeds of the motor table must increase",
     "скорости в таблице двигателя должны возрастать"),
    (r"give duration \(s\) or cycles: the run needs an end",
     "задайте 'duration' (с) или 'cycles': у расчёта должен быть конец"),
    (r"give motor \(one input\) or motors \(one per input\), not both",
     "задайте 'motor' (один вход) или 'motors' (по одному на вход), но не оба"),
    (r"give either box or polygon", "задайте либо 'box', либо 'polygon'"),
    (r"give either column or point \(with coordinate\)",
     "задайте либо 'column', либо 'point' (с 'coordinate')"),
    (r"a point criterion needs coordinate: x or y", "критерию по точке нужен coordinate: x "
     "или y"),
    (r"give one task: path, function or motion",
     "задайте одну задачу: 'path', 'function' или 'motion'"),
    # spatial contours (model/plane.py, model/spatial.py, model/structure.py)
    (r"give the plane's normal \[nx, ny, nz\], or its two angles a and b",
     "задайте нормаль плоскости [nx, ny, nz] или два её угла a и b"),
    (r"the plane's normal is zero", "нормаль плоскости нулевая"),
    (r"'(?P<k>[^']*)' is not solved for a model with spatial contours yet \(their "
     r"dynamics reads bodies, joints, forces, moments and gravity only\)", "'{k}' пока не "
     "решается для модели с пространственными контурами (их динамика учитывает только "
     "звенья, кинематические пары, силы, моменты и силу тяжести)"),
    (r"remove '(?P<k>[^']*)', or solve the planar part as a separate model",
     "удалите '{k}' или решите плоскую часть как отдельную модель"),
    (r"contour (?P<c>\S+) is planar; a convention of parameter ranges applies to a spatial "
     r"contour", "контур {c} плоский; соглашение о диапазонах параметров ('convention') "
     "применяется к пространственному контуру"),
    (r"remove 'convention'", "удалите 'convention'"),
    (r"contour (?P<c>\S+) is spatial; a plane applies to a planar contour",
     "контур {c} пространственный; плоскость ('plane') задаётся только плоскому контуру"),
    (r"remove 'plane', or 'spatial: true'", "удалите 'plane' или 'spatial: true'"),
    (r"contour (?P<c>\S+) has a plane, but no contour of the model is spatial: a plane "
     r"places a planar contour beside spatial ones", "у контура {c} задана плоскость "
     "('plane'), но в модели нет пространственных контуров: плоскость размещает плоский "
     "контур рядом с пространственными"),
    (r"remove 'plane' \(a planar model lies in the XY plane\)",
     "удалите 'plane' (плоская модель лежит в плоскости XY)"),
    (r"a planar contour lists vector numbers \(a minus sign subtracts a vector only in a "
     r"spatial contour\)", "плоский контур перечисляет номера векторов (знак минус вычитает "
     "вектор только в пространственном контуре)"),
    (r"vector (?P<v>\S+) has a rotation β \(b\) but its contour (?P<c>\S+) is planar \(the "
     r"XY plane, β = 0\)", "у вектора {v} задано вращение β (b), но его контур {c} плоский "
     "(плоскость XY, β = 0)"),
    (r"vector (?P<v>\S+) has a rotation β \(b\), but no contour of the model is spatial",
     "у вектора {v} задано вращение β (b), но в модели нет пространственных контуров"),
    (r"add 'spatial: true' to (?P<w>that|its) contour, or remove 'b'",
     lambda m: f"добавьте 'spatial: true' в {'этот' if m['w'] == 'that' else 'его'} контур "
     "или удалите 'b'"),
    (r"contour (?P<c>\S+) has (?P<n>\S+) function parameter\(s\) \((?P<list>[^()]*)\); a "
     r"(?P<kind>\w+) contour needs exactly (?P<want>\S+)", _functions_count),
    (r"mark (?P<n>\S+) of its parameters 'function' \(the unknowns of this loop\)",
     lambda m: f"отметьте {_COUNT.get(m['n'], (m['n'],))[0]} его параметра как 'function' "
     "(неизвестные этого контура)"),
    (r"make all but (?P<n>\S+) of them constants, arguments or links to earlier contours",
     lambda m: f"сделайте все, кроме {_COUNT.get(m['n'], (m['n'], m['n']))[1]}, "
     "постоянными, аргументами или ссылками на предыдущие контуры"),
    (r"contour (?P<c>\S+) has the three rotations (?P<list>.+?) unknown \(module Pr20\): it "
     r"has infinitely many solutions \(a one-parameter family\)", "в контуре {c} неизвестны "
     "все три вращения {list} (модуль Pr20): у него бесконечно много решений "
     "(однопараметрическое семейство)"),
    (r"give one of these β a value \(a constant, an argument or a link\): the other two are "
     r"then module Pr18/Pr19 or the planar Pl4 in the XZ plane", "задайте одному из этих β "
     "значение (постоянную, аргумент или ссылку): тогда два других решаются модулем "
     "Pr18/Pr19 или плоским модулем Pl4 в плоскости XZ"),
    (r"contour (?P<c>\S+) is module (?P<m>\S+), which has (?P<n>\S+) solution\(s\); variant "
     r"(?P<v>\S+) does not apply", "контур {c} — модуль {m}, число его решений: {n}; "
     "вариант {v} неприменим"),
    (r"contour (?P<c>\S+) is module (?P<m>\S+), which has at most two solutions; variant "
     r"(?P<v>\S+) does not apply", "контур {c} — модуль {m}, у которого не больше двух "
     "решений; вариант {v} неприменим"),
    (r"set 'variant' to 1\.\.(?P<n>\S+) or 'auto'",
     "задайте 'variant' от 1 до {n} или 'auto'"),
    (r"set 'variant' to 1, 2 or 'auto'", "задайте 'variant': 1, 2 или 'auto'"),
    (r"remove 'guess' and choose the branch with 'variant'",
     "удалите 'guess' и выберите ветвь решения ключом 'variant'"),
    (r"(?P<what>.+?) is not built for a model with spatial contours yet", _refused),
    (r"solve it with mechloop\.solve \(mechloop solve\), or vary its dimensions with "
     r"mechloop sweep", "решите её функцией 'mechloop.solve' ('mechloop solve') или "
     "варьируйте её размеры командой 'mechloop sweep'"),
    # a joint's axis in a model with spatial contours (model/dynamic.py)
    (r"a joint's axis is a vector number K \(along vector K\) or a direction \[x, y, z\]",
     "ось пары — номер вектора K (вдоль вектора K) или направление [x, y, z]"),
    (r"the joints' reactions need the bodies they connect, and the model has no bodies",
     "для реакций в парах нужны соединяемые ими звенья, а звеньев в модели нет"),
    (r"list the moving bodies under bodies:, or remove joints",
     "перечислите подвижные звенья в 'bodies:' или удалите 'joints'"),
]
