"""The planetary train's part of the gear sheet (sheet 3): its members with their numbers
of teeth and roles, the ratio as the course writes it for the member held, the conditions,
the speeds of every member and the velocity plan — for a James (2K-H) train of any scheme
with any member held and any input, and for the Wolfrom train; in English or Russian.

The formula of the ratio, by Willis' formula read for the member held (Kudryavtsev's
notation, ``i_xy^h = (ω_x − ω_h)/(ω_y − ω_h)``):

* ``b`` fixed: ``i_ah = 1 − i_ab^h``, ``i_ha = 1/(1 − i_ab^h)``;
* ``a`` fixed: ``i_bh = 1 − i_ba^h``, ``i_hb = 1/(1 − i_ba^h)``, with ``i_ba^h = 1/i_ab^h``;
* the carrier ``h`` fixed (a train with fixed axes): ``i_ab = i_ab^h``, ``i_ba = i_ba^h``;
* Wolfrom, ``b`` fixed: ``i_ae = i_ah/(1 − i_eb^h)`` with ``i_ah = 1 + z_b/z_a`` and
  ``i_eb^h = z_b z_f/(z_g z_e)``.

Every number comes from :mod:`mechloop.gears` (:class:`~mechloop.gears.PlanetaryTrain`,
:class:`~mechloop.gears.wolfrom.WolfromTrain`); lengths in mm, speeds in rpm.
"""

from __future__ import annotations

import math

from matplotlib.figure import Figure

from mechloop.gears.planetary import PlanetaryTrain
from mechloop.gears.velocity_plan import plot_velocity_plan, plot_wolfrom_plan
from mechloop.gears.wolfrom import WolfromTrain
from mechloop.views.sheet import Table, number_text

Train = PlanetaryTrain | WolfromTrain

#: The ratio ω_driver/ω_output of a 2K-H train as the course writes it, by (fixed, input).
FORMULAS: dict[tuple[str, str], str] = {
    ("b", "a"): "i_ah = 1 − i_ab^h",
    ("b", "h"): "i_ha = 1/(1 − i_ab^h)",
    ("a", "b"): "i_bh = 1 − i_ba^h",
    ("a", "h"): "i_hb = 1/(1 − i_ba^h)",
    ("h", "a"): "i_ab = i_ab^h",
    ("h", "b"): "i_ba = i_ba^h",
}
WOLFROM_FORMULA = "i_ae = i_ah/(1 − i_eb^h)"

TRAIN_TEXT: dict[str, dict[str, str]] = {
    "en": {
        "members": "Members of the planetary train: numbers of teeth and roles",
        "member": "member", "z": "z", "role": "role",
        "a": "central gear a", "g": "planet g", "f": "planet's second row f",
        "b": "central gear b", "e": "central gear e", "h": "carrier h",
        "input": "input", "output": "output", "fixed": "fixed", "planet": "—",
        "free": "free (holds the planets)",
        "train_table": "Planetary train: ratio by Willis' formula and the conditions",
        "scheme": "scheme", "planets": "number of planets", "module": "module",
        "willis": "ratio of the train seen from the carrier (Willis' formula)",
        "willis_inverse": "the same, b to a: i_ba^h = 1/i_ab^h",
        "ratio": "ratio, {held} fixed: {formula}",
        "first_stage": "first stage a–g–b with b fixed, to the carrier: "
                       "i_ah = 1 − i_ab^h = 1 + z_b/z_a",
        "second_stage": "second stage seen from the carrier (Willis' formula): "
                        "i_eb^h = z_b z_f/(z_g z_e)",
        "target": "target ratio", "error": "error against the target",
        "a_w": "centre distance of the planets", "coaxial": "coaxiality (both rows at a_w)",
        "coaxial_3": "coaxiality (all three meshes at a_w)",
        "assembly": "assembly number (whole: the planets can be fitted evenly)",
        "assembly_1": "assembly number of the sun, (z_a + z_b)/k (whole: fits)",
        "assembly_2": "assembly number of the second ring, (z_e z_g − z_b z_f)/"
                      "(k·gcd(z_g, z_f)) (whole: fits)",
        "margin": "clearance between neighbouring planets' tip circles",
        "speed": "speed of {member}", "rpm": "rpm", "yes": "yes", "no": "no",
        "cond_ok": "met", "cond_fails": "NOT MET",
        "cond_coaxial": "Coaxiality: {verdict}.", "cond_assembly": "Assembly: {verdict}.",
        "cond_neighbours": "Neighbourhood (the planets clear each other): {verdict}.",
        "direction": "The output {output} turns against the input {input} (the ratio is "
                     "negative).",
        "fig_plan": "Velocity plan (Kutzbach) of the planetary train",
        "simple": "simple (a–g–b)", "double_planet": "two-row (a–g, f–b)",
        "two_rings": "two rings (a–g, f–b)", "two_suns": "two suns (a–g, f–b)",
        "wolfrom": "Wolfrom, 3K (a–g–b, f–e)",
    },
    "ru": {
        "members": "Звенья планетарного механизма: числа зубьев и назначение",
        "member": "звено", "z": "z", "role": "назначение",
        "a": "центральное колесо a", "g": "сателлит g", "f": "второй венец сателлита f",
        "b": "центральное колесо b", "e": "центральное колесо e", "h": "водило h",
        "input": "входное (ведущее)", "output": "выходное (ведомое)",
        "fixed": "неподвижное звено", "planet": "—",
        "free": "свободное (несёт сателлиты)",
        "train_table": "Планетарный механизм: передаточное отношение по формуле Виллиса "
                       "и условия",
        "scheme": "схема", "planets": "число сателлитов", "module": "модуль",
        "willis": "передаточное отношение обращённого механизма (формула Виллиса)",
        "willis_inverse": "то же от b к a: i_ba^h = 1/i_ab^h",
        "ratio": "передаточное отношение, {held} неподвижно: {formula}",
        "first_stage": "первая ступень a–g–b до водила, b неподвижно: "
                       "i_ah = 1 − i_ab^h = 1 + z_b/z_a",
        "second_stage": "вторая ступень в обращённом движении (формула Виллиса): "
                        "i_eb^h = z_b z_f/(z_g z_e)",
        "target": "заданное передаточное отношение", "error": "отклонение от заданного",
        "a_w": "межосевое расстояние сателлитов", "coaxial": "соосность (оба ряда на a_w)",
        "coaxial_3": "соосность (все три зацепления на a_w)",
        "assembly": "число сборки (целое: сборка возможна)",
        "assembly_1": "число сборки по солнечному колесу, (z_a + z_b)/k (целое: сборка "
                      "возможна)",
        "assembly_2": "число сборки по второму эпициклу, (z_e z_g − z_b z_f)/"
                      "(k·НОД(z_g, z_f)) (целое: сборка возможна)",
        "margin": "зазор между вершинами соседних сателлитов",
        "speed": "частота вращения {member}", "rpm": "об/мин", "yes": "да", "no": "нет",
        "cond_ok": "выполнено", "cond_fails": "НЕ ВЫПОЛНЕНО",
        "cond_coaxial": "Условие соосности: {verdict}.",
        "cond_assembly": "Условие сборки: {verdict}.",
        "cond_neighbours": "Условие соседства (сателлиты не задевают друг друга): "
                           "{verdict}.",
        "direction": "Выходное звено {output} вращается в сторону, противоположную "
                     "входному звену {input} (передаточное отношение отрицательно).",
        "fig_plan": "План линейных скоростей планетарного механизма",
        "simple": "однорядная (a–g–b)", "double_planet": "двухрядная (a–g, f–b)",
        "two_rings": "с двумя эпициклами (a–g, f–b)",
        "two_suns": "с двумя солнечными колёсами (a–g, f–b)",
        "wolfrom": "Вольфрома, 3K (a–g–b, f–e)",
    },
}

#: The words of the velocity plans (mechloop.gears.velocity_plan) in Russian.
PLAN_WORDS_RU: dict[str, str] = {
    "carrier h": "водило h",
    "(fixed)": "(неподвижное)",
    "(input)": "(входное)",
    "(output)": "(выходное)",
    "sun a": "центральное колесо a",
    "ring b": "центральное колесо b",
    "ring e": "центральное колесо e",
    "stepped planet g/f": "ступенчатый сателлит g/f",
    "planet g": "сателлит g",
    "linear speed": "линейная скорость",
    "distance from the central axis": "расстояние от центральной оси",
}


def is_wolfrom(train: Train) -> bool:
    return isinstance(train, WolfromTrain)


def roles(train: Train) -> dict[str, str]:
    """The role of each member, ``input``, ``output``, ``fixed``, ``planet`` or ``free``
    (the Wolfrom train's idle carrier), in the order of the sheet's table."""
    if is_wolfrom(train):
        return {"a": "input", "g": "planet", "f": "planet", "b": "fixed", "e": "output",
                "h": "free"}
    found = {key: "planet" for key in train.teeth}
    found |= {train.driver: "input", train.output: "output", train.fixed: "fixed"}
    return {key: found[key] for key in (*train.teeth, "h")}


def driver_output(train: Train) -> tuple[str, str]:
    """The input and the output member of ``train``."""
    return ("a", "e") if is_wolfrom(train) else (train.driver, train.output)


def ratio_formula(train: Train) -> str:
    """The ratio's formula as the course writes it for the member held."""
    return WOLFROM_FORMULA if is_wolfrom(train) else FORMULAS[train.fixed, train.driver]


def members_table(train: Train, text: dict[str, str]) -> Table:
    """Each member: its name, its letter, its number of teeth ('—' for the carrier) and
    its role."""
    teeth = train.teeth
    rows = [(text[key], key, str(teeth[key]) if key in teeth else "—", text[role])
            for key, role in roles(train).items()]
    return Table(text["members"], (text["member"], text["symbol"], text["z"], text["role"]),
                 rows)


def ratio_rows(train: Train, target: float | None, text: dict[str, str]
               ) -> list[tuple[str, str, str, str]]:
    """The scheme, planets, module and the ratio's rows (with the target's when given)."""
    driver, output = driver_output(train)
    name = "wolfrom" if is_wolfrom(train) else train.scheme.name
    rows = [(text["scheme"], "", text[name], ""),
            (text["planets"], "k", str(train.k), ""),
            (text["module"], "m", number_text(train.m_n), "mm")]
    if is_wolfrom(train):
        rows += [(text["first_stage"], "i_ah", number_text(train.carrier_ratio), ""),
                 (text["second_stage"], "i_eb^h", number_text(train.willis_be), "")]
    else:
        rows.append((text["willis"], "i_ab^h", number_text(train.willis), ""))
        if "i_ba^h" in ratio_formula(train):
            rows.append((text["willis_inverse"], "i_ba^h", number_text(1.0 / train.willis),
                         ""))
    held = "b" if is_wolfrom(train) else train.fixed
    symbol = f"i_{driver}{output}"
    rows.append((text["ratio"].format(held=text[held], formula=ratio_formula(train)),
                 symbol, number_text(train.ratio), ""))
    if target is not None:
        rows += [(text["target"], symbol + "*", number_text(target), ""),
                 (text["error"], "Δi", number_text(100 * abs(train.ratio - target)
                                                   / abs(target)), "%")]
    return rows


def condition_rows(train: Train, text: dict[str, str]) -> list[tuple[str, str, str, str]]:
    """Centre distance, coaxiality, assembly and the neighbours' clearance."""
    rows = [(text["a_w"], "a_w", number_text(train.a_w), "mm"),
            (text["coaxial_3" if is_wolfrom(train) else "coaxial"], "",
             text["yes" if train.coaxial else "no"], "")]
    if is_wolfrom(train):
        first, second = train.assembly
        rows += [(text["assembly_1"], "", number_text(first), ""),
                 (text["assembly_2"], "", number_text(second), "")]
    else:
        rows.append((text["assembly"], "", number_text(train.assembly), ""))
    rows.append((text["margin"], "", number_text(train.neighbour_margin), "mm"))
    return rows


def speed_rows(train: Train, speed_rpm: float, text: dict[str, str]
               ) -> list[tuple[str, str, str, str]]:
    """The speed (rpm) of every member, the held one 0, with the input at ``speed_rpm``."""
    speeds = train.speeds(speed_rpm * math.pi / 30)
    return [(text["speed"].format(member=key), f"n_{key}",
             number_text(value * 30 / math.pi), text["rpm"])
            for key, value in speeds.items()]


def train_tables(train: Train, speed_rpm: float, target: float | None,
                 text: dict[str, str]) -> list[Table]:
    """The members' table and the table of the ratio, the conditions and the speeds."""
    rows = [*ratio_rows(train, target, text), *condition_rows(train, text),
            *speed_rows(train, speed_rpm, text)]
    return [members_table(train, text),
            Table(text["train_table"], (text["quantity"], text["symbol"], text["value"],
                                        text["unit"]), rows)]


def train_paragraphs(train: Train, text: dict[str, str]) -> list[str]:
    """The conditions in words, and the output's sense of turning when it is reversed."""
    words = [text[key].format(verdict=text["cond_ok" if ok else "cond_fails"])
             for key, ok in (("cond_coaxial", train.coaxial),
                             ("cond_assembly", train.assembles),
                             ("cond_neighbours", train.neighbour_margin > 0))]
    if train.ratio < 0:
        driver, output = driver_output(train)
        words.append(text["direction"].format(input=driver, output=output))
    return words


def train_plan(train: Train, speed_rpm: float, text: dict[str, str]) -> Figure:
    """The velocity plan of the train (the one ``mechloop gear planetary --plot`` draws),
    titled with the teeth, the ratio and the input speed."""
    driver, output = driver_output(train)
    draw = plot_wolfrom_plan if is_wolfrom(train) else plot_velocity_plan
    figure = draw(train, speed_rpm)
    figure.axes[0].set_title("z = " + "/".join(f"{k}{v}" for k, v in train.teeth.items())
                             + f", i_{driver}{output} = {train.ratio:.6g}, "
                             f"n_{driver} = {speed_rpm:g} {text['rpm']}", fontsize=9)
    return figure
