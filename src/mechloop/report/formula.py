"""Section 2 of the report, the calculation formula: the structure of the vector model
drawn (:func:`mechloop.views.formula.plot_structure`) and its structure and parametric
formulas contour by contour, in the report's language (KDAM's "structure of the vector
model" panel)."""

from __future__ import annotations

from mechloop.model.formula import spatial_branches
from mechloop.model.schema import Model
from mechloop.model.structure import MODULE_SOLUTIONS
from mechloop.report.document import FigureItem, Paragraph, Section
from mechloop.report.numbers import Shown
from mechloop.report.parameters import role_text
from mechloop.report.values import module_text, symbol
from mechloop.solve.results import Results

#: Constants on one line of the formula (the lines are kept as they are).
CONSTANTS_PER_LINE = 3

WORDS = {
    "en": {"head": "planar model: {contours} contour(s), {vectors} vectors, positions "
                   "0…{n}",
           "order": "solving order: {order}", "contour": "contour {n}",
           "vectors": "vectors {list}", "structure": "structure formula: {text}",
           "links": "links: {list}", "parametric": "parametric formula: {text}",
           "constants_only": "constants only",
           "solutions": "({count} solution(s))",
           "block": "(coupled block {n}: contours {list} solved together for {unknowns} "
                    "by Newton's method)",
           "constants": "constants: {list}", "needs": "needs contours: {list}",
           "spatial_head": "spatial model: {contours} contour(s), {vectors} vectors, "
                           "positions 0…{n}"},
    "ru": {"head": "плоская модель: контуров {contours}, векторов {vectors}, положения "
                   "0…{n}",
           "order": "порядок решения: {order}", "contour": "контур {n}",
           "vectors": "векторы {list}", "structure": "структурная формула: {text}",
           "links": "связи: {list}", "parametric": "параметрическая формула: {text}",
           "constants_only": "только константы",
           "solutions": "(решений: {count})",
           "block": "(связанный блок {n}: контуры {list} решаются совместно "
                    "относительно {unknowns} методом Ньютона)",
           "constants": "константы: {list}",
           "needs": "нужны контуры: {list}",
           "spatial_head": "пространственная модель: контуров {contours}, векторов "
                           "{vectors}, положения 0…{n}"},
}


def formula_text(model: Model, results: Results, shown: Shown, w: dict[str, str]) -> str:
    """The structure and parametric formulas of every contour in solving order, one
    line each (the lines of a 'formula' paragraph)."""
    f = WORDS[shown.lang]
    structure = results.structure
    spatial = set(getattr(results, "spatial_vectors", ()))  # issue 17: β of these
    head = "spatial_head" if any(c.spatial for c in model.contours) else "head"
    lines = [f[head].format(contours=len(model.contours), vectors=len(model.vectors),
                              n=model.positions),
             f["order"].format(order=" → ".join(f["contour"].format(n=n)
                                                for n in structure.order))]
    for info in structure.ordered():
        name = model.contours[info.number - 1].name
        lines.append("")
        lines.append(f["contour"].format(n=info.number) + (f" — {name}" if name else "")
                     + ": " + f["vectors"].format(list=", ".join(map(str, info.vectors))))
        links = [f"{symbol(p)} = {role_text(model, p, shown, w).split(': ', 1)[-1]}"
                 for p in info.links]
        dimension = 3 if model.contours[info.number - 1].spatial else 2
        text = f"n={dimension}, m={len(info.vectors)}"
        if links:
            text += "; " + f["links"].format(list=", ".join(links))
        lines.append("  " + f["structure"].format(text=text))
        inputs = [f"{symbol(p)} ({role_text(model, p, shown, w)})" for p in info.arguments]
        inputs += [symbol(p) for p in info.links]
        spatial_module = model.contours[info.number - 1].spatial and info.module != "coupled"
        count = (spatial_branches(info.module) if spatial_module
                 else MODULE_SOLUTIONS.get(info.module, 2))
        variant = info.variant if count > 1 else 1
        lhs = ", ".join(inputs) if inputs else f["constants_only"]
        formula = (f"{lhs} → {', '.join(symbol(p) for p in info.functions)} · "
                   f"{module_text(info.module, shown.lang)}, V={variant}")
        block = next((b for b in structure.blocks if info.number in b.contours), None)
        if spatial_module:
            tail = f["solutions"].format(count=count)
        elif info.module in MODULE_SOLUTIONS or block is None:
            tail = f["solutions"].format(count=MODULE_SOLUTIONS.get(info.module, 1))
        else:
            tail = f["block"].format(n=block.number,
                                     list=", ".join(map(str, block.contours)),
                                     unknowns=", ".join(map(symbol, block.unknowns)))
        lines.append("  " + f["parametric"].format(text=formula))
        lines.append("    " + tail)
        known = [f"{symbol(p)} = {_constant(results, p, shown)}"
                 for n in info.vectors
                 for p in (f"r{n}", f"a{n}", *((f"b{n}",) if n in spatial else ()))
                 if p not in info.functions and p not in info.arguments
                 and p not in info.links]
        for k in range(0, len(known), CONSTANTS_PER_LINE):
            chunk = ", ".join(known[k:k + CONSTANTS_PER_LINE])
            lines.append("  " + (f["constants"].format(list=chunk) if k == 0
                                 else " " * (len(f["constants"]) - 6) + chunk))
        if info.needs:
            lines.append("  " + f["needs"].format(list=", ".join(map(str, info.needs))))
    return "\n".join(lines)


def _constant(results: Results, name: str, shown: Shown) -> str:
    import numpy as np

    from mechloop.report.values import span_text

    values = np.asarray(results.value(name), dtype=float)
    angle = name[0] in "ab"
    return span_text(shown, np.degrees(values) if angle else values,
                     "deg" if angle else "m")


def formula_section(model: Model, results: Results, shown: Shown, w: dict[str, str]
                    ) -> Section:
    """Section 2: the structure figure and the formulas."""
    from mechloop.report.structure_figure import structure_figure

    lang = shown.lang
    return Section(w["s_formula"], [
        FigureItem(w["f_structure"], lambda: structure_figure(model, lang)),
        Paragraph(formula_text(model, results, shown, w), "formula")])
