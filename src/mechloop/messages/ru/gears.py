"""Russian of the messages and fixes of gears and cams (src/mechloop/gears/, cams/)."""

from __future__ import annotations

import re

from mechloop.messages.ru.base import Entry

#: The cam document's values that must be positive (``_Reader.positive``'s ``what``):
#: English -> the whole Russian sentence.
_POSITIVE = {
    "the pivot distance": "межосевое расстояние кулачок — коромысло должно быть "
                          "положительным",
    "the roller radius": "радиус ролика должен быть положительным",
    "the arm": "длина коромысла должна быть положительной",
    "a dwell's angle": "угол выстоя должен быть положительным",
    "the lift of a rise": "ход на фазе удаления должен быть положительным",
    "the lift of a return": "ход на фазе возврата должен быть положительным",
    "a rise's angle": "угол фазы удаления должен быть положительным",
    "a return's angle": "угол фазы возврата должен быть положительным",
    "the allowed pressure angle": "допустимый угол давления должен быть положительным",
    "the base radius": "радиус основной окружности должен быть положительным",
}
#: A cam segment's kinds (the keys of a segment in the cam document), in the genitive.
_PHASE = {"rise": "фазы удаления", "return": "фазы возврата", "dwell": "выстоя",
          "table": "табличной фазы"}


def _positive(match: re.Match[str]) -> str:
    what = match["what"]
    if what in _POSITIVE:
        return _POSITIVE[what]
    from mechloop.messages.catalogue_ru import translate

    return f"{translate(what)}: значение должно быть положительным"


def _kinds(text: str) -> str:
    """A cam segment's keys as the user wrote them, each in quotes ('none': none)."""
    if text == "none":
        return "ничего"
    return ", ".join(f"'{k.strip()}'" for k in text.split(",") if k.strip())


ENTRIES: list[Entry] = [
    # cams: the base radius (mechloop.cams.base_radius, design)
    (r"an allowed pressure angle must be between 0 and 90 deg",
     "допустимый угол давления должен быть от 0 до 90 deg"),
    (r"e\.g\. 30 deg for a translating follower, 45 (?P<u>deg )?for a rocker",
     lambda m: "например, 30 deg для поступательного толкателя, 45 " + (m["u"] or "")
     + "— для коромысла"),
    (r"the pressure angle stays within the limit for any base radius above the offset "
     r"(?P<r>.+?) m", "угол давления не превышает допустимого при любом радиусе основной "
     "окружности больше смещения оси толкателя {r} m"),
    (r"give the base radius itself \(base_radius:\)",
     "задайте сам радиус основной окружности (base_radius:)"),
    (r"give the base radius itself \(base_radius:\), or a larger min_curvature_radius",
     "задайте сам радиус основной окружности (base_radius:) или больший "
     "'min_curvature_radius'"),
    (r"a flat face perpendicular to its axis has a pressure angle of 0",
     "у плоской тарелки, перпендикулярной оси толкателя, угол давления равен 0"),
    (r"use minimum_flat_base_radius \(a convex profile\) instead",
     "используйте вместо этого 'minimum_flat_base_radius' (по выпуклости профиля)"),
    (r"no base radius keeps the pressure angle within the limit for this rocker",
     "ни при каком радиусе основной окружности угол давления этого коромысла не остаётся "
     "в допустимых пределах"),
    (r"lengthen the arm, move the pivot, lower the swing or allow a larger angle",
     "удлините коромысло, перенесите ось его качания, уменьшите угол размаха или допустите "
     "больший угол давления"),
    (r"the profile is convex for any base radius above (?P<r>.+?) m",
     "профиль выпуклый при любом радиусе основной окружности больше {r} m"),
    (r"no base radius gives this rocker's face a convex profile",
     "ни при каком радиусе основной окружности профиль кулачка под тарелкой этого "
     "коромысла не получается выпуклым"),
    (r"move the pivot farther, lower the swing or use slower laws",
     "отнесите ось качания коромысла дальше, уменьшите угол размаха или возьмите законы "
     "движения с меньшими скоростями"),
    (r"with the base radius (?P<r>.+?) m the follower leaves its geometry over the turn "
     r"\(it passes the cam centre, or the rocker swings past its limit\)",
     "при радиусе основной окружности {r} m толкатель за оборот кулачка выходит за "
     "пределы своей геометрии (проходит через центр кулачка или коромысло поворачивается "
     "за свой предел)"),
    (r"raise the base radius, or start the program at its lowest displacement",
     "увеличьте радиус основной окружности или начните закон движения с наименьшего "
     "перемещения толкателя"),
    (r"the rocker's face turns back as fast as the cam turns \(dψ/dφ reaches −1\): its "
     r"contact runs off to infinity", "тарелка коромысла поворачивается обратно так же "
     "быстро, как вращается кулачок (dψ/dφ достигает −1): точка контакта уходит в "
     "бесконечность"),
    (r"return over a larger cam angle, or by a law with a smaller peak velocity",
     "растяните возврат на больший угол поворота кулачка или возьмите закон с меньшей "
     "наибольшей скоростью"),
    # cams: the cam document (mechloop.cams.document)
    (r"(?P<what>[\w' ]+?) must be positive", _positive),
    (r"write a positive value", "запишите положительное значение"),
    (r"a rocker needs (?P<key>\w+)", "для коромысла нужен ключ '{key}'"),
    (r"a roller follower needs roller_radius", "для толкателя с роликом нужен ключ "
     "'roller_radius'"),
    (r"add (?P<key>\w+): \(a length\)", "добавьте {key}: (длина)"),
    (r"add roller_radius: (?P<v>\S+)", "добавьте roller_radius: {v}"),
    (r"the segments span (?P<a>.+?) deg, not one turn \(360 deg\)",
     "фазы охватывают {a} deg, а не полный оборот (360 deg)"),
    (r"make the segment angles add up to 360", "сделайте сумму углов фаз равной 360"),
    (r"the follower does not end where it starts \(net (?P<kind>rise|return) of "
     r"(?P<v>.+?) SI units\)",
     lambda m: "толкатель не возвращается в начальное положение (" + (
         "удаление" if m["kind"] == "rise" else "возврат") + f" в сумме {m['v']} в "
     "единицах СИ)"),
    (r"make the returns undo the rises",
     "сделайте суммарный ход возврата равным суммарному ходу удаления"),
    (r"a table starts at \[0, 0\] \(the segment's start\)",
     "таблица начинается с точки [0, 0] (начало фазы)"),
    (r"write the first point as \[0, 0\]", "запишите первую точку как [0, 0]"),
    (r"the table's angles must increase", "углы в таблице должны возрастать"),
    (r"sort the points by angle", "упорядочьте точки по возрастанию угла"),
    (r"a table ends where it starts",
     "таблица заканчивается на том же перемещении, с которого начинается"),
    (r"end a rise above 0, a return below 0 \(or use a dwell\)",
     "закончите удаление выше 0, а возврат — ниже 0 (или используйте выстой)"),
    (r"a cam document holds a cam: mapping",
     "файл кулачкового механизма должен содержать отображение cam:"),
    (r"a pressure angle is below 90 deg", "угол давления должен быть меньше 90 deg"),
    (r"give the base radius or the allowed pressure angle",
     "задайте радиус основной окружности или допустимый угол давления"),
    (r"add base_radius: (?P<r>\S+), or pressure_angle: (?P<a>\S+) for the smallest base "
     r"radius", "добавьте base_radius: {r} или, чтобы получить наименьший радиус основной "
     "окружности, pressure_angle: {a}"),
    (r"a flat face's base radius follows from its convexity, not from a pressure angle",
     "радиус основной окружности кулачка с плоской тарелкой следует из выпуклости "
     "профиля, а не из угла давления"),
    (r"remove pressure_angle \(the base radius follows from min_curvature_radius\)",
     "удалите 'pressure_angle' (радиус основной окружности следует из "
     "'min_curvature_radius')"),
    (r"the base radius must lie between (?P<a>.+?) and (?P<b>.+?) m for this follower",
     "радиус основной окружности для этого толкателя должен лежать между {a} и {b} m"),
    (r"a roller's base radius exceeds the offset; a rocker's lies between "
     r"\|pivot_distance − arm\| and pivot_distance \+ arm, a rocker face's between "
     r"face_offset and face_offset \+ pivot_distance",
     "у толкателя с роликом радиус основной окружности больше смещения оси ('offset'); у "
     "коромысла он лежит между |'pivot_distance' − 'arm'| и 'pivot_distance' + 'arm', у "
     "коромысла с тарелкой — между 'face_offset' и 'face_offset' + 'pivot_distance'"),
    # the segment's schema (SegmentSpec._one_kind: "Value error, …")
    (r"a segment is exactly one of rise, return, dwell or table \(got (?P<got>[\w, ]*)\)",
     lambda m: "фаза задаётся ровно одним из ключей 'rise', 'return', 'dwell' или 'table' "
     f"(задано: {_kinds(m['got'])})"),
    (r"a (?P<kind>rise|return) needs its angle and law",
     lambda m: f"для {_PHASE[m['kind']]} ('{m['kind']}') нужны угол ('angle') и закон "
     "движения ('law')"),
    (r"a (?P<kind>dwell|table) takes no angle or law",
     lambda m: f"для {_PHASE[m['kind']]} ('{m['kind']}') не задают ни угол ('angle'), ни "
     "закон движения ('law')"),
    # cams: figures and the vector model (mechloop.cams.plots, vector_model)
    (r"draw the program, profile, curvature or plan instead",
     "постройте вместо этого 'program', 'profile', 'curvature' или 'plan'"),
    (r"no cam view (?P<v>'[^']*'|.+)", "нет вида кулачкового механизма {v}"),
    (r"(?P<file>.+?): cannot save an animation as '(?P<s>[^']*)'",
     lambda m: f"{m['file']}: анимацию нельзя сохранить как " + (
         "файл без расширения" if m["s"] == "no suffix" else f"'{m['s']}'")),
    (r"only a translating follower can be written as a vector model",
     "векторной моделью можно записать только механизм с поступательным толкателем"),
    (r"a rocker's arm angle is the sum of two arguments \(−φ and ψ\)",
     "угол коромысла — сумма двух аргументов (−φ и ψ)"),
    (r"the vector model needs segments that start at whole degrees",
     "для векторной модели фазы должны начинаться на целых градусах"),
    (r"round the segment angles to whole degrees", "округлите углы фаз до целых градусов"),
    (r"the vector model has no law (?P<v>'[^']*'|.+)", "в векторной модели нет закона {v}"),
    # gears: a pair (mechloop.gears.centre_distance, involute, pair, sliding, tables)
    (r"the shifts are so negative that the working pressure angle would be zero or less",
     "коэффициенты смещения настолько отрицательны, что угол зацепления получился бы "
     "нулевым или отрицательным"),
    (r"make the sum of the shifts x1 \+ x2 larger",
     "увеличьте сумму коэффициентов смещения x1 + x2"),
    (r"the centre distance is too small for these gears: no working pressure angle fits it",
     "межосевое расстояние слишком мало для этих колёс: ему не соответствует ни один угол "
     "зацепления"),
    (r"take a centre distance above a0·cos α = (?P<v>.+)",
     "возьмите межосевое расстояние больше a0·cos α = {v}"),
    (r"the involute function is defined for angles 0 to 90°: a negative or non-finite "
     r"value has no angle", "эвольвентная функция определена для углов от 0 до 90°: "
     "отрицательному или не конечному значению угол не соответствует"),
    (r"check the shifts and the centre distance",
     "проверьте коэффициенты смещения и межосевое расстояние"),
    (r"a circle inside the base circle has no involute",
     "у окружности внутри основной окружности нет эвольвенты"),
    (r"take a diameter at least the base diameter d_b",
     "возьмите диаметр не меньше основного диаметра d_b"),
    (r"module (?P<v>.+?): not a positive number", "модуль {v}: не положительное число"),
    (r"teeth (?P<z>.+?): a gear has at least one tooth",
     "числа зубьев {z}: у колеса должен быть хотя бы один зуб"),
    (r"give the shifts x = \(x1, x2\), or the centre distance a with the pinion's shift x1",
     "задайте коэффициенты смещения x = (x1, x2) или межосевое расстояние a вместе с "
     "коэффициентом смещения шестерни x1"),
    (r"the (?P<gear>pinion|wheel)'s tip circle falls inside its base circle \(tips "
     r"shortened by Δy·m = (?P<v>.+?)\): no involute is left to mesh",
     lambda m: "окружность вершин " + ("шестерни" if m["gear"] == "pinion" else "колеса")
     + " оказывается внутри основной окружности (вершины укорочены на Δy·m = "
     f"{m['v']}): для зацепления не остаётся эвольвенты"),
    (r"take a smaller centre distance or smaller shifts",
     "возьмите меньшее межосевое расстояние или меньшие коэффициенты смещения"),
    (r"specific sliding is infinite at N_1 and N_2",
     "удельное скольжение бесконечно в точках N_1 и N_2"),
    (r"take points strictly between the base circles' tangent points",
     "берите точки строго между точками касания линии зацепления с основными "
     "окружностями"),
    (r"no pinion shift between (?P<a>.+?) and (?P<b>.+?) balances the specific sliding "
     r"for this centre distance", "ни один коэффициент смещения шестерни от {a} до {b} не "
     "выравнивает удельные скольжения при этом межосевом расстоянии"),
    (r"change the centre distance or give the shifts",
     "измените межосевое расстояние или задайте коэффициенты смещения"),
    (r"no circle of (?P<d>.+?) mm cuts an involute of the pair",
     "ни одна окружность диаметром {d} mm не пересекает эвольвенты передачи"),
    (r"take diameters between d_b and d_a: pinion (?P<a>.+?), wheel (?P<b>.+?) mm",
     "возьмите диаметры между d_b и d_a: шестерня {a}, колесо {b} mm"),
    # gears: the gear document and command (mechloop.gears.document, commands)
    (r"give a gear file or options like --module, not both",
     "задайте либо файл зубчатой передачи, либо параметры вроде --module, но не то и "
     "другое вместе"),
    (r"drop (?P<opts>.+?) or the file", "уберите {opts} или файл"),
    (r"no gear data: give a file or the options",
     "нет данных зубчатой передачи: задайте файл или параметры командной строки"),
    (r"e\.g\. (?P<cmd>mechloop gear \w+ \S+)", "например, '{cmd}'"),
    (r"--model writes the 2K-H schemes \(simple, two-row\) as vector models; the wolfrom "
     r"train is not written", "--model записывает векторными моделями схемы 2K-H "
     "(однорядную и двухрядные); механизм Вольфрома ('wolfrom') так не "
     "записывается"),
    (r"drop --model", "уберите --model"),
    (r"a pinion shift alone leaves the wheel's open",
     "одно лишь смещение шестерни оставляет смещение колеса неопределённым"),
    (r"give centre_distance too, or write shifts: \[x1, x2\]",
     "задайте также 'centre_distance' или запишите shifts: [x1, x2]"),
    (r"both pinion_shift and shifts are given", "заданы и 'pinion_shift', и 'shifts'"),
    (r"keep one of them", "оставьте что-то одно"),
    (r"'no_undercut' chooses the shifts, so the centre distance follows from them",
     "'no_undercut' сам выбирает коэффициенты смещения, и межосевое расстояние следует из "
     "них"),
    (r"remove centre_distance, or write shifts: balanced",
     "удалите 'centre_distance' или запишите 'shifts: balanced'"),
    (r"the shifts (?P<x>.+?) give the centre distance (?P<a>.+?), not (?P<b>.+)",
     "при коэффициентах смещения {x} межосевое расстояние равно {a}, а не {b}"),
    (r"remove centre_distance, or make the shifts sum to (?P<v>.+?) \(or write shifts: "
     r"balanced\)", "удалите 'centre_distance' или сделайте сумму коэффициентов смещения "
     "равной {v} (или запишите 'shifts: balanced')"),
    (r"balanced shifts need their sum, which the centre distance fixes",
     "для смещений, выравнивающих удельные скольжения ('balanced'), нужна их сумма, а её "
     "задаёт межосевое расстояние"),
    (r"add centre_distance \(mm\)", "добавьте 'centre_distance' (mm)"),
    (r"the file has no '(?P<key>[^']*)' section", "в файле нет раздела '{key}'"),
    (r"add one \(see (?P<ex>[^)]*)\)", "добавьте его (см. {ex})"),
    # gears: planetary trains (mechloop.gears.document, planetary, wolfrom, tooth_search)
    (r"the input (?P<m>.+?) is the member held fixed",
     "входное звено {m} — это и есть неподвижное звено"),
    (r"take another input of a, b and h", "выберите другое входное звено из a, b и h"),
    (r"neither tooth numbers nor a target ratio",
     "не заданы ни числа зубьев, ни требуемое передаточное отношение"),
    (r"add teeth: (?P<t>\{[^{}]*\}) or target_ratio: (?P<r>\S+)",
     "добавьте teeth: {t} или target_ratio: {r}"),
    (r"a ring e belongs to the wolfrom scheme only",
     "второй эпицикл e есть только в схеме Вольфрома ('wolfrom')"),
    (r"remove e, or write scheme: wolfrom", "удалите e или запишите 'scheme: wolfrom'"),
    (r"the wolfrom train holds ring b and is driven by the sun a \(its output is ring e\)",
     "в механизме Вольфрома неподвижен эпицикл b, а ведущее звено — солнечное колесо a "
     "(выходное звено — эпицикл e)"),
    (r"remove fixed: and input:", "удалите fixed: и input:"),
    (r"no design of the (?P<s>.+?) scheme meets the ratio (?P<r>.+?) within (?P<t>.+?) %",
     "ни один вариант схемы '{s}' не даёт передаточного отношения {r} с точностью {t} %"),
    (r"widen search\.tolerance or teeth_max, change the number of planets, or try another "
     r"scheme", "увеличьте 'search.tolerance' или 'teeth_max', измените число сателлитов "
     "или попробуйте другую схему"),
    (r"unknown planetary scheme (?P<s>'[^']*'|.+)",
     "неизвестная схема планетарного механизма {s}"),
    (r"fixed (?P<f>'[^']*'|.+?) and input (?P<i>'[^']*'|.+?): take two different members "
     r"of a, b and h", "неподвижное звено {f} и входное звено {i}: выберите два разных "
     "звена из a, b и h"),
    (r"the (?P<s>.+?) scheme needs the tooth numbers of (?P<need>[\w, ]+); missing "
     r"(?P<miss>.+)", "для схемы '{s}' нужны числа зубьев {need}; не хватает {miss}"),
    (r"(?P<k>.+?) planets: write a whole number of planets, 1 or more",
     "число сателлитов {k}: задайте целое число сателлитов, не меньше 1"),
    (r"with these teeth i_ab\^h = 1: a and b turn alike about the carrier, so with "
     r"(?P<m>.+?) fixed nothing can turn", "при этих числах зубьев i_ab^h = 1: "
     "относительно водила a и b вращаются одинаково, поэтому при неподвижном звене {m} "
     "механизм не может двигаться"),
    (r"change a tooth number of one row \(or hold the carrier h\)",
     "измените число зубьев в одном из рядов (или сделайте неподвижным водило h)"),
    (r"with these teeth z_b z_f = z_g z_e: the output ring e would stand still whatever "
     r"the sun does", "при этих числах зубьев z_b z_f = z_g z_e: выходной эпицикл e стоял "
     "бы на месте при любом вращении солнечного колеса"),
    (r"change a tooth number of the second stage \(f or e\)",
     "измените число зубьев второй ступени (f или e)"),
    (r"teeth_max (?P<a>.+?) is below teeth_min (?P<b>.+)",
     "'teeth_max' = {a} меньше 'teeth_min' = {b}"),
    (r"raise teeth_max", "увеличьте 'teeth_max'"),
    (r"(?P<n>.+?) combinations of teeth (?P<a>.+?) to (?P<b>.+?) are too many to try",
     "сочетаний чисел зубьев от {a} до {b} слишком много для перебора: {n}"),
    (r"narrow teeth_min … teeth_max \(120 values at most for a two-row scheme\)",
     "сузьте диапазон 'teeth_min' … 'teeth_max' (для двухрядной схемы — не больше 120 "
     "значений)"),
    (r"narrow teeth_min … teeth_max \(120 values at most\)",
     "сузьте диапазон 'teeth_min' … 'teeth_max' (не больше 120 значений)"),
]
