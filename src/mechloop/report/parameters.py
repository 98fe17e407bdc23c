"""Section 1 of the report, the model's parameters: general data, the vectors with the
role and value of r and α, the arguments, the contours (as tables in the display units)
and the vector scheme in the intermediate position."""

from __future__ import annotations

import numpy as np

from mechloop.model.schema import (
    ArgumentRole,
    IntermediateArgument,
    LawArgument,
    LinkRole,
    Model,
    RpmTime,
    TableArgument,
)
from mechloop.model.structure import is_function, param_role
from mechloop.model.units import to_si
from mechloop.report.document import FigureItem, Section, Table
from mechloop.report.numbers import Shown
from mechloop.report.values import module_text, span_text, symbol
from mechloop.report.words import law
from mechloop.solve.results import Results
from mechloop.views.russian import translate


def _unit(name: str) -> str:
    """The table unit of a parameter's values as :meth:`Shown.text` takes them."""
    return "m" if name[0] == "r" else "deg"


def _values(results: Results, name: str) -> np.ndarray:
    values = np.asarray(results.value(name), dtype=float)
    return np.degrees(values) if name[0] == "a" else values


def _offset(value, name: str, model: Model, shown: Shown) -> str:
    """' + 10°' / ' − 10°' / '' of a constant added to a parameter."""
    kind = "length" if name[0] == "r" else "angle"
    si = to_si(value, kind, model.units.length if kind == "length" else model.units.angle)
    if si == 0:
        return ""
    shown_value = si if kind == "length" else np.degrees(si)
    text = shown.text(abs(shown_value), _unit(name))
    return f" − {text}" if si < 0 else f" + {text}"


def role_text(model: Model, name: str, shown: Shown, w: dict[str, str]) -> str:
    """How parameter ``name`` is given, in words: 'constant', 'function',
    'argument 1 + 10°', 'linked: −0.4·α2 + 5°'."""
    role = param_role(model, name)
    if is_function(role):
        return w["function"]
    if isinstance(role, ArgumentRole):
        return w["argument"].format(k=role.argument) + _offset(role.offset, name, model,
                                                                shown)
    if isinstance(role, LinkRole):
        factor = "" if role.ratio == 1 else f"{shown.number(float(role.ratio))}·"
        return (f"{w['link']}: {factor}{symbol(role.link)}"
                + _offset(role.delta, name, model, shown))
    return w["constant"]


def general_table(model: Model, results: Results, shown: Shown, w: dict[str, str]
                  ) -> Table:
    """The model's name, positions, units of the results and time."""
    rows = [(w["g_name"], model.name or "—")]
    if model.description:
        rows.append((w["g_description"], model.description))
    rows.append((w["g_positions"], w["g_positions_v"].format(n=model.positions,
                                                             count=model.positions + 1)))
    units = [shown.unit_text(u) for u in ("m", "deg", "s", "rad/s")]
    rows.append((w["g_units"], ", ".join(dict.fromkeys(units))))
    if model.time is None:
        rows.append((w["g_time"], w["g_time_none"]))
    elif isinstance(model.time, RpmTime):
        speed = shown.text(float(model.time.rpm) * np.pi / 30, "rad/s") \
            if shown.unit("rad/s") != "rad/s" else f"{shown.number(float(model.time.rpm))} " \
            + ("об/мин" if shown.lang == "ru" else "rpm")
        rows.append((w["g_time"], w["g_time_rpm"].format(
            speed=speed, turns=shown.number(float(model.time.turns)))))
    else:
        time = results.time
        rows.append((w["g_time"], w["g_time_table"].format(
            start=shown.text(float(time[0]), "s"), stop=shown.text(float(time[-1]), "s"))))
    rows.append((w["g_size"], f"{len(model.contours)}, {len(model.vectors)}"))
    return Table(w["t_general"], (w["h_quantity"], w["h_value"]), rows)


def vector_table(model: Model, results: Results, shown: Shown, w: dict[str, str]
                 ) -> Table:
    """Each vector: number, name, the role and value of r, the role and value of α
    (a varying one as its range over the positions)."""
    rows = []
    for number, vector in sorted(model.vectors.items()):
        cells = [str(number), vector.name or ""]
        for letter in "ra":
            name = f"{letter}{number}"
            cells += [role_text(model, name, shown, w),
                      span_text(shown, _values(results, name), _unit(name), bare=True)]
        rows.append(tuple(cells))
    header = (w["h_number"], w["h_name"], f"r: {w['h_role']}",
              f"r, {shown.unit_text('m')}", f"α: {w['h_role']}",
              f"α, {shown.unit_text('deg')}")
    return Table(w["t_vectors"], header, rows)


def argument_table(model: Model, results: Results, shown: Shown, w: dict[str, str]
                   ) -> Table:
    """Each argument: number, kind (angle or length), its law or table and its range,
    and its unit."""
    rows = []
    for number, arg in sorted(model.arguments.items()):
        kind = results.argument_kinds[number]
        values = results.arguments[number]
        unit = "deg" if kind == "angle" else "m"
        values = np.degrees(values) if kind == "angle" else np.asarray(values)
        span = span_text(shown, values, unit)
        if isinstance(arg, LawArgument):
            form = w["a_law"].format(law=law(arg.law, shown.lang), a=arg.start[0],
                                     b=arg.end[0], span=span)
        elif isinstance(arg, IntermediateArgument):
            form = w["a_intermediate"].format(count=arg.intermediate.count, span=span)
        elif isinstance(arg, TableArgument):
            form = w["a_table"].format(count=len(arg.table), span=span)
        elif hasattr(arg, "csv"):
            form = w["a_csv"].format(file=arg.csv, span=span)
        else:
            form = w["a_values"].format(span=span)
        rows.append((str(number), w[kind], form, shown.unit_text(unit)))
    return Table(w["t_arguments"], (w["h_number"], w["h_kind"], w["h_law"], w["h_unit"]),
                 rows)


def contour_table(model: Model, results: Results, w: dict[str, str]) -> Table:
    """Each contour in its solving order: number, name, vectors, module, variant and
    the functions it solves."""
    rows = []
    for info in results.structure.ordered():
        contour = model.contours[info.number - 1]
        rows.append((str(info.number), contour.name or "",
                     ", ".join(map(str, info.vectors)), module_text(info.module, w["lang"]),
                     str(contour.variant if contour.variant != "auto" else "1/2"),
                     ", ".join(symbol(f) for f in info.functions)))
    return Table(w["t_contours"], (w["h_number"], w["h_name"], w["h_vectors"],
                                   w["h_module"], w["h_variant"], w["h_functions"]), rows)


def parameters_section(model: Model, results: Results, source, position: int,
                       shown: Shown, w: dict[str, str], length_unit: str | None
                       ) -> Section:
    """Section 1: the tables of the model's data and the vector scheme at
    ``position``."""
    from mechloop.views import plan

    lang = shown.lang
    blocks = [general_table(model, results, shown, w),
              vector_table(model, results, shown, w)]
    if model.arguments:
        blocks.append(argument_table(model, results, shown, w))
    blocks.append(contour_table(model, results, w))
    blocks.append(FigureItem(w["f_plan"].format(position=position), lambda: translate(
        plan.plot_plan(source, position, length_unit=length_unit), lang)))
    return Section(w["s_parameters"], blocks)
