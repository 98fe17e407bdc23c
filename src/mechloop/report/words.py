"""The words of the report in English and Russian: titles of the sections, captions,
table headers and cells, sentences of the conclusion and the title page.

Every text the report builds is taken from :data:`TEXT` by its key (a ``{field}`` is
filled with symbols, numbers and the user's names), so a Russian report holds no English
words but symbols, unit names and the user's own names.
"""

from __future__ import annotations

import re

from mechloop.views.figure import ViewError

TEXT: dict[str, dict[str, str]] = {
    "en": {
        "lang": "en",
        # title page
        "kind": "Course project",
        "course": "Theory of machines and mechanisms",
        "title": "Kinematic and dynamic analysis of the mechanism",
        "student": "Student", "group": "Group", "supervisor": "Supervisor",
        # sections
        "s_parameters": "Model parameters",
        "s_formula": "Calculation formula",
        "s_increment": "Increment of the output parameter {name} and its 1st and 2nd "
                       "derivatives",
        "s_angles": "Angle differences of the links",
        "s_dependence": "Dependence of the driven link on the driving link",
        "s_masses": "Mass characteristics, forces and moments",
        "s_reduced": "Reduced loads and inertia characteristics",
        "s_reduced_sub": "Reduced characteristics",
        "s_balancing": "Balancing load",
        "s_summary": "Summary characteristics and energy",
        "s_motion": "Machine motion",
        "s_reactions": "Reactions in the kinematic pairs",
        "s_hodograph": "Hodograph of the reaction in joint {name}",
        "s_centres": "Centres of mass",
        "s_breaks": "Check of the kinematic chain for a break",
        "s_conclusion": "Conclusion",
        "s_appendix": "Values of the parameters at every position",
        # captions
        "t_general": "General data of the model",
        "t_vectors": "Vectors of the model (r — length, α — angle from the X axis)",
        "t_arguments": "Arguments of the model",
        "t_contours": "Contours of the model",
        "f_plan": "Vector scheme of the mechanism in the intermediate position {position}",
        "f_structure": "Structure of the vector model",
        "f_increment": "Increment of {name} from position {position} and its 1st and 2nd "
                       "derivatives",
        "f_angle": "Angle between vectors {a} and {b}",
        "f_dependence": "{names} against {against}",
        "t_bodies": "Bodies: mass characteristics",
        "t_pairs": "Kinematic pairs",
        "t_forces": "Forces",
        "t_moments": "Moments",
        "t_other": "Gravity, springs, dampers and friction",
        "f_reduced": "Reduced inertia, its derivative and the reduced load",
        "f_balancing": "Balancing load by kinetostatics and by virtual power",
        "f_summary": "Summary characteristics: works and energy",
        "t_summary_loads": "Work and power of the loads over the cycle",
        "t_summary_totals": "Works, efficiency and energy over the cycle",
        "f_motion": "Machine motion over the cycle",
        "f_reactions": "Reactions in the joints",
        "f_hodograph": "Hodograph of the reaction in joint {name}",
        "f_centres": "Trajectories of the centres of mass",
        "t_appendix": "Values at every position ({part} of {parts})",
        # table headers
        "h_quantity": "quantity", "h_value": "value",
        "h_number": "No.", "h_name": "name", "h_role": "role", "h_kind": "kind",
        "h_law": "law or range", "h_unit": "unit", "h_vectors": "vectors",
        "h_module": "module", "h_variant": "variant", "h_functions": "functions",
        "h_mass": "m", "h_inertia": "J", "h_centre": "centre of mass",
        "h_bodies": "bodies", "h_point": "point", "h_along": "along vector",
        "h_friction": "f", "h_body": "body", "h_magnitude": "magnitude",
        "h_direction": "direction", "h_position": "position",
        # general data
        "g_name": "model", "g_description": "description",
        "g_positions": "calculation positions",
        "g_positions_v": "0…{n} ({count} positions)",
        "g_units": "units of the results",
        "g_time": "model time",
        "g_time_rpm": "input speed {speed}, turns over the positions: {turns}",
        "g_time_table": "a table of time over the positions, {start} … {stop}",
        "g_time_none": "none: the derivatives are analogs with respect to argument 1",
        "g_size": "contours, vectors",
        # roles and kinds
        "constant": "constant", "function": "function", "argument": "argument {k}",
        "link": "linked", "angle": "angle", "length": "length",
        "a_table": "table of {count} values: {span}",
        "a_law": "law {law} from position {a} to {b}: {span}",
        "a_csv": "table from {file}: {span}",
        "a_intermediate": "intermediate: {count} values {span} in every position",
        "a_values": "{span}",
        "revolute": "revolute", "prismatic": "prismatic", "inferred": " (inferred)",
        "spherical": "spherical (ball joint)", "cylindrical": "cylindrical",
        "p_tail": "tail of vector {v}", "p_head": "head of vector {v}",
        "p_share": "on vector {v}, {share} of its length from the tail",
        "p_along": "on vector {v}, {along} from the tail",
        "p_across": ", {across} to its left",
        "d_absolute": "{angle} from the X axis",
        "d_along": "vector {v} turned by {angle}",
        "v_constant": "{value}",
        "v_table": "table over the positions: {span}",
        "v_parameter": "table over {name}: {span}",
        "v_expression": "expression {text}: {span}",
        "v_indicator": "gas force of the indicator diagram (piston {piston}): {span}",
        "v_when": "; acts while {name} {sign}",
        "grows": "grows", "falls": "falls",
        "o_gravity": "gravity", "o_gravity_v": "g = {g}, direction {angle} from the X axis",
        "o_spring": "spring {name}", "o_damper": "damper {name}",
        "o_spring_v": "bodies {a}–{b}, stiffness {k}, free length {l0}, preload {p}",
        "o_spring_table": "bodies {a}–{b}, force by a table of {count} points",
        "o_damper_v": "bodies {a}–{b}, coefficient {c}",
        "o_damper_table": "bodies {a}–{b}, force by a table of {count} points",
        "o_friction": "friction in the joints",
        "o_friction_v": "coefficient {f}",
        "none": "—",
        # breaks
        "no_angles": "No angle difference of adjacent vectors varies.",
        "no_breaks": "The kinematic chain does not break at any position.",
        "breaks_intro": "The kinematic chain breaks; the plots show gaps there and the "
                        "values of those positions are left empty:",
        "break_contour": "contour {n} ({module})",
        "break_block": "the coupled block of contours {list}",
        "break_at": "{where} breaks at positions {positions}: {reason}.",
        "break_between": "contour {n} ({module}) cannot be assembled between positions "
                         "{a} and {b} (argument 1 {x} and {y}): no solution at {at}.",
        "break_at_value": "argument 1 = {x}",
        "break_range": "argument 1 from {x} to {y}",
        "position_broken": "position {position} breaks",
        # conclusion
        "stroke": "Range of the output parameter {name}: {value} ({low} … {high}).",
        "extreme_rate": "Extremes of the 1st derivative of {name}: {low} … {high}.",
        "extreme_accel": "Extremes of the 2nd derivative of {name}: {low} … {high}.",
        "peak_bal": "Peak balancing load {name}: {value} (at position {position}).",
        "peak_reaction": "Peak reaction: joint {name}, {value} (at position {position}).",
        "reduced_range": "Reduced inertia {name}: {low} … {high}; its derivative "
                         "{dname}: {dlow} … {dhigh}.",
        "efficiency": "Mechanical efficiency over the cycle: η = {value}.",
        "no_efficiency": "No load does net positive work over the cycle: the efficiency "
                         "is undefined.",
        "flywheel": "Flywheel for the coefficient of speed fluctuation δ = {delta}: "
                    "moment of inertia {value}.",
        "cycle_breaks": "WARNING: the chain breaks in the cycle ({where}). The cycle "
                        "figures — work over the cycle, loss coefficient ψ, efficiency η, "
                        "flywheel and δ — are not valid and are not given; the summary "
                        "figure leaves out the steps next to the breaks. Remove the break "
                        "first.",
        "chain_break": "break",
        # the report command
        "e_position_range": "--position {position} is not a calculation position (0 to "
                            "{last})",
        "e_position_broken": "--position {position}: the chain breaks at that position",
        "e_position_hint": "use a position where the chain assembles: {good}",
        "e_all_broken": "the chain breaks at every position: fix the model first",
        "progress": "figures",
        "wrote": "wrote {path}",
        "warning": "warning",
    },
    "ru": {
        "lang": "ru",
        "kind": "Курсовой проект",
        "course": "Теория механизмов и машин",
        "title": "Кинематический и динамический анализ механизма",
        "student": "Студент", "group": "Группа", "supervisor": "Руководитель",
        "s_parameters": "Параметры модели",
        "s_formula": "Расчётная формула",
        "s_increment": "Приращение параметра выходного звена {name} и его 1-я и 2-я "
                       "производные",
        "s_angles": "Разность углов звеньев",
        "s_dependence": "Зависимость параметров ведомого звена от параметра ведущего "
                        "звена",
        "s_masses": "Массовые характеристики, силы и моменты, действующие на механизм",
        "s_reduced": "Приведённые нагрузки и инерционные характеристики",
        "s_reduced_sub": "Приведённые характеристики",
        "s_balancing": "Уравновешивающая нагрузка",
        "s_summary": "Сводные характеристики и энергия",
        "s_motion": "Движение машины",
        "s_reactions": "Реакции в кинематических парах",
        "s_hodograph": "Годограф реакции в шарнире {name}",
        "s_centres": "Координаты центров масс",
        "s_breaks": "Проверка кинематической цепи на разрыв",
        "s_conclusion": "Вывод о работе механизма",
        "s_appendix": "Значения параметров во всех положениях",
        "t_general": "Общие данные модели",
        "t_vectors": "Векторы модели (r — длина, α — угол от оси X)",
        "t_arguments": "Аргументы модели",
        "t_contours": "Контуры модели",
        "f_plan": "Векторная схема механизма в промежуточном положении {position}",
        "f_structure": "Структура векторной модели",
        "f_increment": "Приращение {name} от положения {position} и его 1-я и 2-я "
                       "производные",
        "f_angle": "Угол между векторами {a} и {b}",
        "f_dependence": "{names} в зависимости от {against}",
        "t_bodies": "Звенья: массовые характеристики",
        "t_pairs": "Кинематические пары",
        "t_forces": "Силы",
        "t_moments": "Моменты",
        "t_other": "Сила тяжести, пружины, демпферы и трение",
        "f_reduced": "Приведённый момент инерции, его производная и приведённая нагрузка",
        "f_balancing": "Уравновешивающая нагрузка: кинетостатика и метод мощностей",
        "f_summary": "Сводные характеристики: работы и энергия",
        "t_summary_loads": "Работа и мощность нагрузок за цикл",
        "t_summary_totals": "Работы, КПД и энергия за цикл",
        "f_motion": "Движение машины за цикл",
        "f_reactions": "Реакции в шарнирах",
        "f_hodograph": "Годограф реакции в шарнире {name}",
        "f_centres": "Траектории центров масс",
        "t_appendix": "Значения во всех положениях (часть {part} из {parts})",
        "h_quantity": "величина", "h_value": "значение",
        "h_number": "№", "h_name": "название", "h_role": "роль", "h_kind": "вид",
        "h_law": "закон или диапазон", "h_unit": "единица", "h_vectors": "векторы",
        "h_module": "модуль", "h_variant": "вариант", "h_functions": "функции",
        "h_mass": "m", "h_inertia": "J", "h_centre": "центр масс",
        "h_bodies": "звенья", "h_point": "точка", "h_along": "вдоль вектора",
        "h_friction": "f", "h_body": "звено", "h_magnitude": "величина",
        "h_direction": "направление", "h_position": "положение",
        "g_name": "модель", "g_description": "описание",
        "g_positions": "расчётные положения",
        "g_positions_v": "0…{n} (всего {count})",
        "g_units": "единицы результатов",
        "g_time": "время модели",
        "g_time_rpm": "частота вращения входного звена {speed}, оборотов за положения: "
                      "{turns}",
        "g_time_table": "таблица времени по положениям, {start} … {stop}",
        "g_time_none": "нет: производные — аналоги по аргументу 1",
        "g_size": "контуров, векторов",
        "constant": "константа", "function": "функция", "argument": "аргумент {k}",
        "link": "связь", "angle": "угол", "length": "длина",
        "a_table": "таблица из {count} значений: {span}",
        "a_law": "закон {law} от положения {a} до {b}: {span}",
        "a_csv": "таблица из файла {file}: {span}",
        "a_intermediate": "промежуточный: {count} значений {span} в каждом положении",
        "a_values": "{span}",
        "revolute": "вращательная", "prismatic": "поступательная",
        "spherical": "сферическая (шаровой шарнир)", "cylindrical": "цилиндрическая",
        "inferred": " (по контурам)",
        "p_tail": "начало вектора {v}", "p_head": "конец вектора {v}",
        "p_share": "на векторе {v}, {share} его длины от начала",
        "p_along": "на векторе {v}, {along} от начала",
        "p_across": ", {across} влево",
        "d_absolute": "{angle} от оси X",
        "d_along": "вектор {v}, повёрнутый на {angle}",
        "v_constant": "{value}",
        "v_table": "таблица по положениям: {span}",
        "v_parameter": "таблица по {name}: {span}",
        "v_expression": "выражение {text}: {span}",
        "v_indicator": "сила давления газов по индикаторной диаграмме (поршень "
                       "{piston}): {span}",
        "v_when": "; действует, пока {name} {sign}",
        "grows": "растёт", "falls": "убывает",
        "o_gravity": "сила тяжести",
        "o_gravity_v": "g = {g}, направление {angle} от оси X",
        "o_spring": "пружина {name}", "o_damper": "демпфер {name}",
        "o_spring_v": "звенья {a}–{b}, жёсткость {k}, свободная длина {l0}, "
                      "предварительное натяжение {p}",
        "o_spring_table": "звенья {a}–{b}, сила по таблице из {count} точек",
        "o_damper_v": "звенья {a}–{b}, коэффициент {c}",
        "o_damper_table": "звенья {a}–{b}, сила по таблице из {count} точек",
        "o_friction": "трение в шарнирах",
        "o_friction_v": "коэффициент {f}",
        "none": "—",
        "no_angles": "Разность углов соседних векторов не меняется.",
        "no_breaks": "Проверка кинематической цепи на разрыв: разрывов нет.",
        "breaks_intro": "Кинематическая цепь разрывается; на графиках в этих местах "
                        "разрывы, значения этих положений не приводятся:",
        "break_contour": "контур {n} ({module})",
        "break_block": "связанный блок контуров {list}",
        "break_at": "{where} разрывается в положениях {positions}: {reason}.",
        "break_between": "контур {n} ({module}) не собирается между положениями {a} и "
                         "{b} (аргумент 1 равен {x} и {y}): решения нет при {at}.",
        "break_at_value": "аргументе 1, равном {x}",
        "break_range": "аргументе 1 от {x} до {y}",
        "position_broken": "в положении {position} цепь разрывается",
        "stroke": "Диапазон параметра выходного звена {name}: {value} ({low} … {high}).",
        "extreme_rate": "Экстремумы 1-й производной {name}: {low} … {high}.",
        "extreme_accel": "Экстремумы 2-й производной {name}: {low} … {high}.",
        "peak_bal": "Наибольшая уравновешивающая нагрузка {name}: {value} (в положении "
                    "{position}).",
        "peak_reaction": "Наибольшая реакция: шарнир {name}, {value} (в положении "
                         "{position}).",
        "reduced_range": "Приведённый момент инерции {name}: {low} … {high}; его "
                         "производная {dname}: {dlow} … {dhigh}.",
        "efficiency": "Механический КПД за цикл: η = {value}.",
        "no_efficiency": "Нагрузки в сумме не совершают положительной работы за цикл: "
                         "КПД не определён.",
        "flywheel": "Маховик для коэффициента неравномерности хода δ = {delta}: момент "
                    "инерции {value}.",
        "cycle_breaks": "ВНИМАНИЕ: кинематическая цепь разрывается в цикле ({where}). "
                        "Цикловые характеристики — работа за цикл, коэффициент потерь ψ, "
                        "КПД η, маховик и δ — недостоверны и не приводятся; на графике "
                        "сводных характеристик пропущены шаги рядом с разрывами. Сначала "
                        "устраните разрыв.",
        "chain_break": "разрыв",
        "e_position_range": "--position {position}: такого расчётного положения нет (0 … "
                            "{last})",
        "e_position_broken": "--position {position}: в этом положении цепь разрывается",
        "e_position_hint": "укажите положение, в котором цепь собирается: {good}",
        "e_all_broken": "цепь разрывается во всех положениях: сначала исправьте модель",
        "progress": "рисунки",
        "wrote": "записан {path}",
        "warning": "предупреждение",
    },
}

#: The reasons of a chain break (:mod:`mechloop.solve.kinematics`,
#: :mod:`mechloop.modules.coupled`) in Russian.
RUSSIAN_REASONS: dict[str, str] = {
    "the closing vector has zero length, its direction is undefined":
        "замыкающий вектор имеет нулевую длину, его направление не определено",
    "the two vectors of unknown length are parallel":
        "два вектора неизвестной длины параллельны",
    "the vector of known length cannot reach the line of the other vector":
        "вектор известной длины не достаёт до линии другого вектора",
    "the two vectors cannot close the loop (triangle inequality fails)":
        "два вектора не замыкают контур (не выполняется неравенство треугольника)",
    "dead point: the loop's Jacobian is singular, velocities are unbounded":
        "мёртвая точка: якобиан контура вырожден, скорости неограничены",
    "the values overflow floating point (a dimension, an input or a speed is too large)":
        "значения выходят за пределы чисел с плавающей точкой (слишком велик размер, "
        "вход или скорость)",
    "Newton's method finds no assembly of the coupled block near the previous one (past "
    "a limit position, or the block cannot close)":
        "метод Ньютона не находит сборки связанного блока вблизи предыдущей (за крайним "
        "положением, или блок не замыкается)",
    "dead point: the coupled block's Jacobian is singular, velocities are unbounded":
        "мёртвая точка: якобиан связанного блока вырожден, скорости неограничены",
    "the coupled block jumped to another assembly branch (its Jacobian determinant "
    "changed sign or the solution moved too far in one step): positions are too coarse "
    "here, or the motion passes a singular position":
        "связанный блок перешёл на другую ветвь сборки (определитель якобиана сменил знак "
        "или решение сместилось слишком далеко за шаг): положения здесь слишком редки, "
        "или движение проходит особое положение",
}

#: The laws of motion of an argument (:mod:`mechloop.model.laws`) in Russian.
RUSSIAN_LAWS: dict[str, str] = {
    "constant_speed": "равномерный", "harmonic": "гармонический",
    "cycloidal": "циклоидальный", "poly345": "полиномиальный 3-4-5",
}


def words(lang: str) -> dict[str, str]:
    """The words of ``lang``; a :class:`~mechloop.views.figure.ViewError` for another
    language."""
    if lang not in TEXT:
        raise ViewError(f"no report language {lang!r}", "use 'en' or 'ru'")
    return TEXT[lang]


#: A spatial module's break (:func:`mechloop.spatial.solve._break_reason`, issue 17).
_SPATIAL_REASON = re.compile(r"module Pr(\d+) has no real solution on the chosen variant "
                             r"\(the vectors cannot close the loop in space\)")


def reason(text: str, lang: str) -> str:
    """A chain break's reason in ``lang``."""
    if lang != "ru":
        return text
    spatial = _SPATIAL_REASON.fullmatch(text)
    if spatial:
        return (f"у модуля Пр{spatial.group(1)} нет вещественного решения для выбранного "
                "варианта (векторы не замыкают контур в пространстве)")
    return RUSSIAN_REASONS.get(text, "контур не собирается")


def law(name: str, lang: str) -> str:
    """A law of motion's name in ``lang``."""
    return RUSSIAN_LAWS.get(name, name) if lang == "ru" else name.replace("_", " ")
