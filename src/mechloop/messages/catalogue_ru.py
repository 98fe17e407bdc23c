"""Russian for the library's error messages and fixes, as a catalogue of patterns.

The library builds its messages as English f-strings with the user's values inside (keys,
names, numbers, paths).  Each entry here is a compiled pattern that matches one such message
whole, with named groups for the values, and the Russian template they go back into.  A
group whose name ends in ``_tr`` holds English text of its own (a nested message) and is
translated too; one ending in ``_or`` is a list of the user's values joined by "or"/"and";
one ending in ``_kind`` is a kind of quantity (``length``, ``angle``, …).  A text that no
entry matches is tried clause by clause (split at ``"; "``); what still matches nothing is
returned unchanged — English, but never lost.  Pydantic's own messages (schema validation:
a wrong type, a value out of range, a value not among the allowed ones) are entries too.
"""

from __future__ import annotations

import re

from mechloop.messages.ru import AREAS
from mechloop.messages.ru.base import KIND as _KIND
from mechloop.messages.ru.base import KINDS, Entry
from mechloop.messages.ru.base import accusative as _as
from mechloop.messages.ru.base import or_words as _or
from mechloop.messages.ru.base import quoted as _quoted

ENTRIES: list[Entry] = [
    # reading the file
    (r"file not found", "файл не найден"),
    (r"check the path \(mechloop check examples/\.\.\. \)",
     "проверьте путь (например, 'mechloop check examples/...')"),
    (r"cannot read the file: (?P<why>.*)", "не удаётся прочитать файл: {why}"),
    (r"check the path and its permissions", "проверьте путь и права доступа к файлу"),
    (r"byte (?P<byte>0x[0-9a-f]+) at column (?P<col>\d+) is not UTF-8 text",
     "байт {byte} в столбце {col} — не текст в кодировке UTF-8"),
    (r"save the file as UTF-8 \(or remove the character\)",
     "сохраните файл в кодировке UTF-8 (или удалите этот символ)"),
    (r"YAML syntax error: (?P<what_tr>.*?) \((?P<ctx_tr>while [^()]*)\)",
     "синтаксическая ошибка YAML: {what_tr} ({ctx_tr})"),
    (r"YAML syntax error: (?P<what_tr>.*)", "синтаксическая ошибка YAML: {what_tr}"),
    (r"while (?:parsing|reading|scanning) (?P<thing_tr>[^()]*?) that starts at "
     r"line (?P<line>\d+)", "при разборе: {thing_tr}, начало в строке {line}"),
    (r"while (?:parsing|reading|scanning) (?P<thing_tr>[^()]*)",
     "при разборе: {thing_tr}"),
    (r"a (?P<thing_tr>flow mapping|block mapping|mapping|flow sequence|block sequence|"
     r"sequence|quoted scalar|plain scalar|block scalar|simple key|directive|"
     r"a block collection|block collection|flow node|block node|node)", "{thing_tr}"),
    (r"flow mapping", "отображение в фигурных скобках"),
    (r"block mapping", "отображение с отступами"),
    (r"mapping", "отображение"),
    (r"flow sequence", "список в квадратных скобках"),
    (r"block sequence", "список с отступами"),
    (r"sequence", "список"),
    (r"quoted scalar", "строка в кавычках"),
    (r"(plain|block) scalar", "значение"),
    (r"simple key", "ключ"),
    (r"(block collection|a block collection|flow node|block node|node|directive)",
     "элемент документа"),
    (r"expected (?P<a>'[^']*'|<[^>]*>) or (?P<b>'[^']*'|<[^>]*>), but got (?P<got>'[^']*'"
     r"|<[^>]*>)", "ожидалось {a} или {b}, а найдено {got}"),
    (r"expected (?P<a>'[^']*'|<[^>]*>), but found (?P<got>'[^']*'|<[^>]*>)",
     "ожидалось {a}, а найдено {got}"),
    (r"expected (?P<a>[^,]*), but found (?P<got>'[^']*'|<[^>]*>)",
     "ожидалось: {a}; найдено {got}"),
    (r"mapping values are not allowed here", "здесь не может стоять значение ключа (':')"),
    (r"found character (?P<c>'.*') that cannot start any token",
     "символ {c} не может начинать элемент"),
    (r"found unexpected end of stream", "неожиданный конец файла"),
    (r"could not find expected ':'", "не найдено ожидаемое ':'"),
    (r"found undefined alias (?P<a>'[^']*')", "неизвестная ссылка {a}"),
    (r"found unknown escape character (?P<c>'.*')", "неизвестный экранированный символ {c}"),
    (r"found a tab character where an indentation space is expected",
     "символ табуляции там, где ожидается отступ пробелами"),
    (r"found the key (?P<key>.*) twice", "ключ {key} встречается дважды"),
    (r"found a list or mapping as a key", "ключом стоит список или отображение"),
    (r"fix the YAML syntax at that line \(indentation, a missing ':' or an unclosed "
     r"bracket\)", "исправьте синтаксис YAML в этой строке (отступы, пропущенное ':' или "
     "незакрытая скобка)"),
    (r"a key is a name or a number: write 'key: value'",
     "ключ — это имя или число: пишите 'ключ: значение'"),
    (r"the file does not hold a model mapping", "в файле нет отображения с данными модели"),
    (r"start with keys like (?P<keys_or>'positions:', 'vectors:' and 'contours:') \(see "
     r"(?P<ex>[^)]*)\)", "начните с ключей {keys_or} (см. {ex})"),
    (r"a model is a mapping of keys", "модель — это отображение ключей"),
    (r"see (?P<ex>examples/\S+)", "см. {ex}"),
    (r"this file is a cam design, not a vector model",
     "этот файл — проект кулачкового механизма, а не векторная модель"),
    (r"use mechloop cam FILE", "используйте 'mechloop cam ФАЙЛ'"),
    (r"the document expands to more than (?P<n>[\d,]+) items \(aliases count each time "
     r"they are used\)", "документ разворачивается более чем в {n} элементов (ссылка "
     "считается при каждом использовании)"),
    (r"write the values out instead of repeating anchors \(&name / \*name\) inside each "
     r"other", "выпишите значения вместо вложенных повторов якорей (&имя / *имя)"),
    (r"the document nests more than (?P<n>\d+) levels deep",
     "вложенность документа больше {n} уровней"),
    (r"a model needs only a few levels: remove the extra brackets or indentation",
     "модели нужно лишь несколько уровней: уберите лишние скобки или отступы"),
    (r"a value of (?P<n>[\d,]+) characters \(the limit is (?P<max>[\d,]+)\)",
     "значение длиной {n} символов (предел — {max})"),
    (r"shorten it: numbers and units are short, and long tables belong in a CSV file",
     "сократите его: числа и единицы короткие, а длинные таблицы помещают в CSV-файл"),
    (r"the file is (?P<n>[\d,]+) bytes \(the limit is (?P<max>[\d,]+)\)",
     "размер файла {n} байт (предел — {max})"),
    (r"(?P<n>[\d,]+) more problems not listed", "не показано ещё проблем: {n}"),
    (r"fix the ones above, then check the file again",
     "исправьте показанные выше и проверьте файл снова"),
    # schema validation (the messages pydantic gives, and mechloop's rewrites of them)
    (r"'(?P<key>[^']*)' is required", "требуется ключ '{key}'"),
    (r"unknown key '(?P<key>[^']*)'", "неизвестный ключ '{key}'"),
    (r"Field required", "обязательное поле отсутствует"),
    (r"Extra inputs are not permitted", "лишний ключ не допускается"),
    (r"add it", "добавьте его"),
    (r"remove it, or check its spelling", "удалите его или проверьте написание"),
    (r"Value error, (?P<inner_tr>.*)", "{inner_tr}"),
    (r"Assertion failed, (?P<inner_tr>.*)", "{inner_tr}"),
    (r"Input should be (?P<vals_or>(?:'[^']*'|-?[\d.]+)(?:, (?:'[^']*'|-?[\d.]+))* or "
     r"(?:'[^']*'|-?[\d.]+))", "допустимые значения: {vals_or}"),
    (r"Input should be (?P<val>'[^']*'|-?[\d.]+)", "допустимое значение: {val}"),
    (r"Unable to parse input string as an integer, exceeded maximum size",
     "не удаётся прочитать строку как целое число: слишком много цифр"),
    (r"Input should be a valid number, unable to parse string as a number",
     "нужно число, а строку не удаётся прочитать как число"),
    (r"Input should be a valid number", "нужно число"),
    (r"Input should be a valid integer, unable to parse string as an integer",
     "нужно целое число, а строку не удаётся прочитать как целое число"),
    (r"Input should be a valid integer, got a number with a fractional part",
     "нужно целое число, а у этого числа есть дробная часть"),
    (r"Input should be a valid integer", "нужно целое число"),
    (r"Input should be a finite number", "нужно конечное число"),
    (r"Input should be a valid string", "нужна строка"),
    (r"Input should be a valid boolean", "нужно значение 'true' или 'false'"),
    (r"Input should be a valid boolean, unable to interpret input",
     "нужно значение 'true' или 'false'"),
    (r"Input should be a valid dictionary", "нужно отображение (ключ: значение)"),
    (r"Input should be a valid dictionary or instance of (?P<cls>\w+)",
     "нужно отображение (ключ: значение)"),
    (r"Input should be a valid list", "нужен список"),
    (r"Input should be a valid tuple", "нужен список"),
    (r"Input should be (?P<op>greater than or equal to|greater than|less than or equal to|"
     r"less than) (?P<bound>\S+)",
     lambda m: {"greater than or equal to": "нужно значение не меньше ",
                "greater than": "нужно значение больше ",
                "less than or equal to": "нужно значение не больше ",
                "less than": "нужно значение меньше "}[m["op"]] + m["bound"]),
    (r"List should have at least (?P<n>\d+) items? after validation, not (?P<got>\d+)",
     "в списке нужно не меньше элементов: {n}; в нём {got}"),
    (r"List should have at most (?P<n>\d+) items? after validation, not (?P<got>\d+)",
     "в списке нужно не больше элементов: {n}; в нём {got}"),
    (r"Tuple should have at (?P<op>least|most) (?P<n>\d+) items? after validation, not "
     r"(?P<got>\d+)", lambda m: ("в списке нужно " + ("не меньше" if m["op"] == "least"
                                 else "не больше") + f" элементов: {m['n']}; в нём {m['got']}")),
    (r"String should have at most (?P<n>\d+) characters?",
     "строка должна быть не длиннее {n} символов"),
    (r"String should have at least (?P<n>\d+) characters?",
     "строка должна быть не короче {n} символов"),
    (r"String should match pattern '(?P<p>.*)'", "строка должна соответствовать шаблону '{p}'"),
    (r"(?P<v>\S+) is not a finite number", "{v} — не конечное число"),
    (r"write a finite number", "запишите конечное число"),
    (r"write a whole number", "запишите целое число"),
    (r"write a number", "запишите число"),
    (r"use one of the allowed values", "используйте одно из допустимых значений"),
    (r"use a larger value", "используйте значение побольше"),
    (r"use a smaller value", "используйте значение поменьше"),
    (r"add more items", "добавьте элементы"),
    (r"write a finite number of a physical size \(model units\)",
     "запишите конечное число физически разумной величины (в единицах модели)"),
    (r"write the ratio as teeth over teeth, e\.g\. (?P<ex>.*)",
     "запишите отношение как зубья через зубья, например {ex}"),
    (r"write a number and a unit, e\.g\. (?P<ex>.*)",
     "запишите число и единицу, например {ex}"),
    (r"shorten it: a unit is a short name like 'mm' or 'kN\*m'",
     "сократите: единица — это короткое имя вроде 'mm' или 'kN*m'"),
    (r"write the parameter as 'a' or 'r' and a vector number, e\.g\. 'a2'",
     "запишите параметр как 'a' или 'r' и номер вектора, например 'a2'"),
    (r"write a number or a fraction of tooth counts, e\.g\. (?P<ex>.*)",
     "запишите число или дробь из чисел зубьев, например {ex}"),
    (r"write e\.g\. (?P<ex_or>.*)", "например: {ex_or}"),
    (r"e\.g\. (?P<ex_or>.*)", "например: {ex_or}"),
    (r"a table position must be a whole number",
     "номер положения в таблице должен быть целым числом"),
    (r"write positions as 0, 1, 2, \.\.\.", "пишите положения как 0, 1, 2, ..."),
    (r"(?P<n>[\d,]+) positions; a model has at most (?P<max>[\d,]+)",
     "положений: {n}; в модели их не больше {max}"),
    (r"use fewer positions \(a smooth curve needs a few hundred to a few thousand\)",
     "возьмите меньше положений (для гладкой кривой хватает от сотен до нескольких тысяч)"),
    # units
    (r"unknown unit '(?P<u>[^']*)'", "неизвестная единица '{u}'"),
    (r"'(?P<u>[^']*)' is not an? (?P<k_kind>" + _KIND + r") unit",
     lambda m: f"'{m['u']}' — не единица {KINDS[m['k_kind']][1]}"),
    (r"use an? (?P<k_kind>" + _KIND + r") unit: (?P<units>.*)",
     lambda m: f"используйте единицу {KINDS[m['k_kind']][1]}: {m['units']}"),
    (r"'(?P<v>[^']*)' is not an? (?P<k_kind>" + _KIND + r")",
     lambda m: f"'{m['v']}' — не {KINDS[m['k_kind']][0]}"),
    (r"cannot read '(?P<v>[^']*)' as an? (?P<k_kind>" + _KIND + r")",
     lambda m: f"не удаётся прочитать '{m['v']}' как {_as(KINDS[m['k_kind']][0])}"),
    (r"write a number, or a number and a unit like '(?P<ex>[^']*)'",
     "запишите число или число с единицей, например '{ex}'"),
    # vectors, contours, links, arguments
    (r"'(?P<v>[^']*)' is not a role", "'{v}' — не роль параметра"),
    (r"did you mean '(?P<v>[^']*)'\?", "возможно, имелось в виду '{v}'?"),
    (r"make all but two of them constants, arguments or links to earlier contours",
     "сделайте все, кроме двух, постоянными, аргументами или ссылками на предыдущие контуры"),
    (r"mark two of its parameters 'function' \(the unknowns of this loop\)",
     "отметьте два его параметра как 'function' (неизвестные этого контура)"),
    (r"(?P<p>[ra]\d+) links to (?P<q>[ra]\d+), but vector (?P<v>\d+) is not defined",
     "{p} ссылается на {q}, но вектор {v} не задан"),
    (r"link to a vector that exists, or add the vector",
     "сошлитесь на существующий вектор или добавьте этот вектор"),
    (r"(?P<p>[ra]\d+) \((?P<pk_kind>length|angle)\) links to (?P<q>[ra]\d+) \("
     r"(?P<qk_kind>length|angle)\); a link joins parameters of the same kind",
     lambda m: (f"{m['p']} ({KINDS[m['pk_kind']][0]}) ссылается на {m['q']} "
                f"({KINDS[m['qk_kind']][0]}); ссылка соединяет параметры одного рода")),
    (r"link to (?P<p>[ra]\d+) instead", "сошлитесь вместо этого на {p}"),
    (r"links form a cycle: (?P<chain>.*)", "ссылки образуют цикл: {chain}"),
    (r"one parameter in the chain must be a constant, an argument or a function",
     "один параметр цепочки должен быть постоянным, аргументом или искомым ('function')"),
    (r"position (?P<p>\d+) is outside the calculation positions (?P<a>\d+)\.\.(?P<b>\d+)",
     "положение {p} вне расчётных положений {a}..{b}"),
    (r"use positions between (?P<a>\d+) and (?P<b>\d+), or raise 'positions'",
     "используйте положения от {a} до {b} или увеличьте 'positions'"),
    (r"the table lists (?P<n>\d+) values?, but the model has (?P<m>\d+) positions "
     r"\((?P<r>[\d.]+)\)", "в таблице значений: {n}, а положений в модели: {m} ({r})"),
    (r"give (?P<n>\d+) values, or a sparse mapping \{position: value\}",
     "задайте {n} значений или разреженное отображение {{положение: значение}}"),
    (r"a table is a mapping of position: value, or a list with one value per position",
     "таблица — это отображение положение: значение или список с одним значением на "
     "положение"),
    (r"(?P<p>[ra]\d+) uses argument (?P<n>\d+), which is not defined",
     "{p} использует аргумент {n}, который не задан"),
    (r"add argument (?P<n>\d+) under 'arguments:' or use one that exists",
     "добавьте аргумент {n} в 'arguments:' или используйте существующий"),
    (r"argument (?P<n>\d+) drives no vector parameter",
     "аргумент {n} не задаёт ни одного параметра векторов"),
    (r"use it in a vector \(e\.g\. (?P<ex>[^)]*)\) or remove it",
     "используйте его в векторе (например, {ex}) или удалите"),
    (r"contour (?P<c>\d+) lists vector (?P<v>\d+), which is not defined",
     "контур {c} содержит вектор {v}, который не задан"),
    (r"add vector (?P<v>\d+) under 'vectors:' or remove it from the contour",
     "добавьте вектор {v} в 'vectors:' или удалите его из контура"),
    (r"vector (?P<v>\d+) is in no contour", "вектор {v} не входит ни в один контур"),
    (r"add it to the 'vectors' list of a contour, or remove it",
     "добавьте его в список 'vectors' какого-либо контура или удалите"),
    (r"vector (?P<v>\d+) is in contours (?P<a>\d+) and (?P<b>\d+); a vector belongs to one "
     r"contour", "вектор {v} входит в контуры {a} и {b}; вектор принадлежит одному контуру"),
    (r"in contour (?P<c>\d+) use a new vector linked to it: (?P<ex>.*)",
     "в контуре {c} возьмите новый вектор со ссылкой на него: {ex}"),
    (r"contour (?P<c>\d+) is module (?P<m>\w+), which has one solution; variant (?P<v>\d+) "
     r"does not apply", "контур {c} — модуль {m} с единственным решением; вариант {v} "
     "неприменим"),
    (r"remove 'variant' or set it to 1", "удалите 'variant' или задайте 1"),
    (r"model time must increase from position to position",
     "время модели должно возрастать от положения к положению"),
    (r"give at least the first and the last position with increasing times, e\.g\. "
     r"(?P<ex>.*)", "задайте хотя бы первое и последнее положения с возрастающим временем, "
     "например {ex}"),
    (r"the law ends at position (?P<e>\d+), not after its start (?P<s>\d+)",
     "закон заканчивается в положении {e}, не позже своего начала {s}"),
    (r"make the end position larger than the start",
     "сделайте положение конца больше положения начала"),
    # solving and the machine's motion
    (r"machine motion needs the whole cycle, but the chain breaks or the force analysis "
     r"is singular at some positions", "для движения машины нужен весь цикл, но в "
     "некоторых положениях цепь разрывается или силовой расчёт вырожден"),
    (r"remove the chain break first \(mechloop solve lists the positions\): check the "
     r"dimensions, the variant and the argument range", "сначала устраните разрыв цепи "
     "('mechloop solve' перечисляет положения): проверьте размеры, вариант и диапазон "
     "аргумента"),
    (r"machine motion needs the input to advance at every position of the cycle",
     "для движения машины вход должен продвигаться вперёд в каждом положении цикла"),
    (r"make the argument's table or law increase from position 0 to N",
     "сделайте таблицу или закон аргумента возрастающими от положения 0 до N"),
    (r"j_red must be positive at every position",
     "приведённый момент инерции j_red должен быть положителен в каждом положении"),
    (r"the machine has no moving mass at some positions \(its reduced moment of inertia "
     r"is zero there\): give the moving bodies masses and moments of inertia "
     r"\(bodies: mass:, inertia:\)", "в некоторых положениях у машины нет движущихся "
     "масс (приведённый момент инерции там равен нулю): задайте подвижным звеньям массы "
     "и моменты инерции (bodies: mass:, inertia:)"),
    (r"the machine stops: at omega_mean = (?P<w>\S+) (?P<u>\S+) the kinetic energy falls "
     r"to zero near q = (?P<q>\S+); steady running needs omega_mean > (?P<w2>\S+) "
     r"(?P<u2>\S+)", "машина останавливается: при ω_ср = {w} {u} кинетическая энергия "
     "падает до нуля около q = {q}; для установившегося движения нужно ω_ср > {w2} {u2}"),
    (r"raise the speed \(time: \{rpm: \.\.\.\}\), lower the loads, or give the moving "
     r"bodies more inertia \(a flywheel mass on the input link\)", "повысьте скорость "
     "(time: {{rpm: ...}}), уменьшите нагрузки или добавьте подвижным звеньям инерции "
     "(маховая масса на входном звене)"),
    (r"friction: the reactions did not settle in (?P<n>\d+) iterations \(the mechanism may "
     r"be self-locking at some positions\)", "трение: реакции не установились за {n} "
     "итераций (в некоторых положениях механизм может самотормозиться)"),
    (r"lower the coefficient of friction there \(friction\.coefficient, or a joint's "
     r"friction\) or check the pin radii and slider lengths", "уменьшите там коэффициент "
     "трения (friction.coefficient или трение шарнира) либо проверьте радиусы цапф и "
     "длины ползунов"),
    # output files
    (r"unknown output format '(?P<s>[^']*)'", "неизвестный формат вывода '{s}'"),
    (r"use a file name ending in (?P<list_or>.*)", "укажите имя файла с окончанием {list_or}"),
    # numbers out of range, CSV tables
    (r"(?P<v>\S+) is outside the range of a model value \(a finite number between "
     r"(?P<a>\S+) and (?P<b>\S+)\)", "{v} вне диапазона значений модели (конечное число "
     "от {a} до {b})"),
    (r"(?P<file>.+?), line (?P<line>\d+): (?P<k>.*) is outside the range of a position and "
     r"a model value \(a finite number between (?P<a>\S+) and (?P<b>\S+)\)",
     "{file}, строка {line}: {k} вне диапазона номера положения и значения модели "
     "(конечное число от {a} до {b})"),
    (r"write a whole position number and a finite value of a physical size \(model units\)",
     "запишите целый номер положения и конечное значение физически разумной величины (в "
     "единицах модели)"),
    (r"(?P<file>.+?), line (?P<line>\d+): not a position number and a value",
     "{file}, строка {line}: это не номер положения и значение"),
    (r"every row is an integer position and a number",
     "каждая строка — целый номер положения и число"),
    (r"(?P<path>.+?) is not a CSV file", "{path} — не CSV-файл"),
    (r"give the path of a CSV file, relative to the model file",
     "укажите путь к CSV-файлу относительно файла модели"),
    (r"CSV file (?P<path>.+?) not found", "CSV-файл {path} не найден"),
    (r"give the path relative to the model file", "укажите путь относительно файла модели"),
    (r"cannot read (?P<path>.+?) as CSV \((?P<why>.*)\)",
     "не удаётся прочитать {path} как CSV ({why})"),
    (r"write a header line, then position,value rows",
     "запишите строку заголовка, затем строки положение,значение"),
    (r"(?P<path>\S+) is (?P<v>\S+); a length here must be positive",
     "{path} равно {v}; длина здесь должна быть положительной"),
    (r"give a positive length", "задайте положительную длину"),
    (r"contour (?P<c>\d+) lists vector (?P<v>\d+) twice",
     "контур {c} содержит вектор {v} дважды"),
    (r"list each vector once", "перечислите каждый вектор один раз"),
    (r"unacceptable character (?P<c>#x[0-9a-fA-F]+): special characters are not allowed"
     r"(?P<rest>.*)", lambda m: f"недопустимый символ {m['c']}: специальные символы не "
     "допускаются"),
    (r"for the next token", "следующий элемент"),
    # group files (mechloop.model.groups): points and links by name
    (r"unknown point '(?P<n>[^']*)'", "неизвестная точка '{n}'"),
    (r"no link named '(?P<n>[^']*)'", "нет звена с именем '{n}'"),
    (r"no moving link named '(?P<n>[^']*)'", "нет подвижного звена с именем '{n}'"),
    (r"no point named '(?P<n>[^']*)'", "нет точки с именем '{n}'"),
    (r"point '(?P<n>[^']*)' is not defined yet", "точка '{n}' ещё не задана"),
    (r"point '(?P<n>[^']*)' is not on link '(?P<k>[^']*)'",
     "точка '{n}' не лежит на звене '{k}'"),
    (r"(?P<what>point|link) '(?P<n>[^']*)' is already defined at (?P<at>\S+)",
     lambda m: ("точка" if m["what"] == "point" else "звено") + f" '{m['n']}' уже задан"
     + ("а" if m["what"] == "point" else "о") + f" в {m['at']}"),
    (r"give every (?P<what>point|link) its own name",
     lambda m: "дайте каждой точке своё имя" if m["what"] == "point" else
     "дайте каждому звену своё имя"),
    (r"did you mean '(?P<v>[^']*)'\? (?P<rest_tr>.*)", "возможно, имелось в виду '{v}'? "
     "{rest_tr}"),
    (r"use one of: none yet(?: \((?P<what_tr>[^)]*)\))?", "допустимых пока нет"),
    (r"use one of: (?P<items>[\w, ]+) \((?P<what_tr>[^)]*)\)",
     lambda m: f"допустимо: {_quoted(m['items'])} ({translate(m['what_tr'])})"),
    (r"the ground points, the input's joint, joints of earlier groups and points on links",
     "неподвижные точки, шарнир входного звена, шарниры предыдущих групп и точки на "
     "звеньях"),
    # synthesis
    (r"give a task \(path, function or motion\) or a criterion to minimize",
     "задайте задачу ('path', 'function' или 'motion') или критерий для минимизации"),
    (r"(?P<n>[\d,]+) more values of this table cannot be read",
     "не удаётся прочитать ещё значений этой таблицы: {n}"),
    (r"fix the values above the same way", "исправьте значения выше так же"),
    (r"the table is empty", "таблица пуста"),
    (r"give at least one 'position: value' pair",
     "задайте хотя бы одну пару 'положение: значение'"),
    (r"argument (?P<n>\d+) drives both lengths and angles",
     "аргумент {n} задаёт и длины, и углы"),
    (r"give lengths and angles separate arguments", "задайте длинам и углам разные аргументы"),
    (r"use a position between (?P<a>\d+) and (?P<b>\d+)", "укажите положение от {a} до {b}"),
    (r"vector number (?P<n>-?\d+) is not positive", "номер вектора {n} не положителен"),
    (r"number vectors 1, 2, 3, \.\.\.", "нумеруйте векторы 1, 2, 3, ..."),
    (r"(?P<p>[ra]\d+) links to (?P<q>[ra]\d+), a function that no contour solves",
     "{p} ссылается на {q} — искомый параметр, который не решает ни один контур"),
    (r"add vector (?P<v>\d+) to a contour", "добавьте вектор {v} в какой-либо контур"),
    (r"contour (?P<c>\d+) is solved in closed form \(module (?P<m>\w+)\); a guess applies "
     r"only to a coupled block", "контур {c} решается в замкнутом виде (модуль {m}); "
     "начальное приближение ('guess') применяется только к связанному блоку"),
    (r"remove 'guess' and choose the assembly with 'variant'",
     "удалите 'guess' и выберите сборку ключом 'variant'"),
    (r"unknown law '(?P<v>[^']*)'", "неизвестный закон '{v}'"),
    # display units and digits (--units, --digits, the display: section)
    (r"(?P<opt>--\w+): (?P<rest_tr>.*)", "{opt}: {rest_tr}"),
    (r"unknown display unit (?P<k>\w+)=(?P<u>'[^']*')",
     "неизвестная единица отображения '{k}'={u}"),
    (r"display unit (?P<k>\w+)=(?P<u>'[^']*') is not a unit of (?P<kind>\w+)",
     "единица отображения '{k}'={u} — не единица величины '{kind}'"),
    (r"(?P<k>\w+) takes an? (?P<kind>\w+) unit: (?P<units>.*)",
     "для '{k}' нужна единица величины '{kind}': {units}"),
    (r"unknown kind of quantity '(?P<k>[^']*)' in '(?P<item>[^']*)'",
     "неизвестный род величины '{k}' в '{item}'"),
    (r"unknown kind of quantity '(?P<k>[^']*)'", "неизвестный род величины '{k}'"),
    (r"use one of (?P<items>[\w, ]+) \(or omega, epsilon, work\)",
     lambda m: "допустимо: " + _quoted(m["items"] + ", omega, epsilon, work")),
    (r"use one of (?P<items>[\w, ]+), or a quotient of them such as (?P<ex>.*)",
     lambda m: "допустимо: " + _quoted(m["items"]) + ", или их частное, например "
     + _or(m["ex"])),
    (r"'(?P<item>[^']*)' is not KIND=UNIT", "'{item}' — не пара РОД=ЕДИНИЦА"),
    (r"write pairs like (?P<ex>'[^']*')", "пишите пары вида {ex}"),
    (r"(?P<opt>--\w+) (?P<v>\S+) is out of range", "{opt} {v} вне допустимого диапазона"),
    (r"use (?P<a>\d+) to (?P<b>\d+)", "используйте от {a} до {b}"),
    (r"--digits and --decimals both given", "заданы и --digits, и --decimals"),
    (r"give either significant digits or decimals",
     "задайте либо значащие цифры, либо знаки после запятой"),
    (r"digits=(?P<v>\S+) is not a number of significant digits",
     "digits={v} — не число значащих цифр"),
    (r"use an integer from (?P<a>\d+) to (?P<b>\d+)", "укажите целое число от {a} до {b}"),
    # dynamics views
    (r"no joint '?(?P<j>[^' ]+)'? in this model", "в модели нет шарнира '{j}'"),
    (r"this model has no machine motion", "у этой модели нет движения машины"),
    (r"add machine: \{delta: (?P<d>\S+)\} to a one-input model with a time, then solve it "
     r"again", "добавьте machine: {{delta: {d}}} в модель с одним входом и временем и "
     "решите её снова"),
    (r"this model has no drive, so there is no balancing load",
     "у этой модели нет привода, поэтому нет уравновешивающей нагрузки"),
    (r"drive a body by a model argument", "задайте движение звена аргументом модели"),
    (r"the model has no envelopes", "в модели нет огибающих"),
    (r"the model has several envelopes", "в модели несколько огибающих"),
    (r"no envelope '?(?P<n>[^']*)'?", "нет огибающей '{n}'"),
    # the plot and report commands' refusals
    (r"unknown view '(?P<v>[^']*)'", "неизвестный вид '{v}'"),
    (r"use one of vectors (?P<items>[\d, ]+)", "допустимые векторы: {items}"),
    (r"use one of:? (?P<items>[\w, ]+)", lambda m: "допустимо: " + _quoted(m["items"])),
    (r"use one of:? (?P<items>[\w, ]+); dynamic columns \((?P<cols>[^)]*)\) need "
     r"mechloop\.solve_dynamics", lambda m: "допустимо: " + _quoted(m["items"]) + "; "
     f"столбцы динамики ({m['cols']}) есть только у модели со звеньями ('bodies:')"),
    (r"no quantity '(?P<q>[^']*)' in these results", "в результатах нет величины '{q}'"),
    (r"no quantity '(?P<q>[^']*)' in this sweep", "в результатах перебора нет величины '{q}'"),
    (r"(?P<n>\d+) curves asked for one plot \((?P<list>.*)\); at most (?P<max>\d+) fit",
     "на одном графике запрошено кривых: {n} ({list}); помещается не больше {max}"),
    (r"split them over several plots", "разнесите их на несколько графиков"),
    (r"nothing to plot", "нечего рисовать"),
    (r"name at least one quantity, e\.g\. (?P<ex>.*)", "назовите хотя бы одну величину, "
     "например {ex}"),
    (r"position (?P<p>-?\d+) is outside the model's positions",
     "положение {p} вне положений модели"),
    (r"use (?P<a>\d+)\.\.(?P<b>\d+)", "используйте {a}..{b}"),
    (r"position (?P<p>-?\d+) is not a calculation position",
     "положение {p} — не расчётное положение"),
    (r"use a position from (?P<a>\d+) to (?P<b>\d+)", "укажите положение от {a} до {b}"),
    (r"(?P<n>\w+) has no value at position (?P<p>\d+) \(the chain breaks there\)",
     "у {n} нет значения в положении {p} (там цепь разрывается)"),
    (r"choose a position where the mechanism assembles",
     "выберите положение, в котором механизм собирается"),
    (r"no vector (?P<v>\d+) in this model", "в модели нет вектора {v}"),
    (r"there is no vector (?P<v>\d+)", "вектора {v} нет"),
    (r"vectors are (?P<list>\[.*\])", "векторы модели: {list}"),
    (r"'(?P<v>[^']*)' does not name a vector", "'{v}' не называет вектор"),
    (r"give a vector number \(3\) or its angle \('a3'\)",
     "укажите номер вектора (3) или его угол ('a3')"),
    (r"'(?P<v>[^']*)' is not a vector parameter of this model",
     "'{v}' — не параметр векторов этой модели"),
    (r"'(?P<v>[^']*)' is not a varying parameter of the model",
     "'{v}' — не переменный параметр модели"),
    (r"'(?P<v>[^']*)' needs a model with bodies", "для '{v}' нужна модель со звеньями ('bodies:')"),
    (r"add bodies \(see (?P<ex>[^)]*)\)", "добавьте звенья в 'bodies:' (см. {ex})"),
    (r"unknown combination '(?P<v>[^']*)'", "неизвестная комбинация '{v}'"),
    (r"cannot take the (?P<op>\w+) of (?P<a>.*) and (?P<b>.*): their units do not match",
     "нельзя взять '{op}' от {a} и {b}: их единицы не согласованы"),
    (r"combine quantities of the same kind \(a length with a length\)",
     "сочетайте величины одного рода (длину с длиной)"),
    (r"cannot raise (?P<a>.*) to the varying power (?P<b>\w+): the unit of the result would "
     r"change from position to position", "нельзя возвести {a} в переменную степень {b}: "
     "единица результата менялась бы от положения к положению"),
    (r"raise a plain number \(e\.g\. a ratio\) to it, or use a constant exponent",
     "возводите в неё безразмерное число (например, отношение) или возьмите постоянный "
     "показатель"),
    (r"cannot save a figure as '(?P<s>[^']*)'", "рисунок нельзя сохранить как '{s}'"),
    (r"a report is a \.pdf or a \.docx file", "отчёт — это файл .pdf или .docx"),
    (r"no (?P<what>figure|report) language '(?P<v>[^']*)'",
     lambda m: ("нет языка рисунка" if m["what"] == "figure" else "нет языка отчёта")
     + f" '{m['v']}'"),
    (r"use --lang en or --lang ru", "укажите --lang en или --lang ru"),
    (r"use 'en' or 'ru'", "укажите 'en' или 'ru'"),
    # a message told about a file: the file's path, then the message
    (r"(?P<file>[^\s:]+\.[A-Za-z0-9]+): (?P<rest_tr>.*)", "{file}: {rest_tr}"),
]


def _report_entries() -> list[Entry]:
    """The report command's refusals (``e_…`` of :data:`mechloop.report.words.TEXT`), whose
    Russian the report already has: the English template as the pattern, its ``{field}``
    as a group."""
    from mechloop.report.words import TEXT

    entries: list[Entry] = []
    for key, english in TEXT["en"].items():
        if key.startswith("e_") and key in TEXT["ru"]:
            pattern = re.sub(r"\\\{(\w+)\\\}", r"(?P<\1>.+?)", re.escape(english))
            entries.append((pattern, TEXT["ru"][key]))
    return entries


# the entries of each area of the library (mechloop.messages.ru) first: each matches its own
# messages only, and wins over a common entry that would leave part of one in English
ENTRIES[:0] = [entry for area in AREAS for entry in area.ENTRIES]
ENTRIES[-1:-1] = _report_entries()  # before the last entry (a file's path, then a message)

_COMPILED = [(re.compile(pattern, re.DOTALL), template) for pattern, template in ENTRIES]


def lookup(text: str) -> str | None:
    """The Russian of one whole message or fix, or None when no entry matches it."""
    for pattern, template in _COMPILED:
        match = pattern.fullmatch(text)
        if match is None:
            continue
        if callable(template):
            return template(match)
        values = {}
        for name, value in match.groupdict().items():
            if value is not None and name.endswith("_tr"):
                value = translate(value)
            elif value is not None and name.endswith("_or"):
                value = _or(value)
            values[name] = value
        try:
            return template.format(**values)
        except (KeyError, IndexError, ValueError):  # a faulty entry (tests check them all)
            return None
    return None


def translate(text: str) -> str:
    """``text`` in Russian: the whole text, else each clause (split at ``"; "``) by the
    catalogue; a clause no entry matches stays as written."""
    whole = lookup(text)
    if whole is not None:
        return whole
    parts = text.split("; ")
    if len(parts) == 1:
        return text
    return "; ".join(lookup(part) or part for part in parts)


def has_russian(text: str) -> bool:
    """Whether the catalogue has Russian for the whole of ``text`` (every clause)."""
    return lookup(text) is not None or all(lookup(p) is not None for p in text.split("; "))
