"""Structure and parametric formulas of a vector model, as text (KDAM's "structure of the
vector model" panel).

Structure formula of a contour: ``n=2, m=4`` (planar, four vectors) plus the links that tie
its vectors to other parameters.  Parametric formula: ``arguments → functions`` with the
module type and the solution variant, e.g. ``α1 (arg 1) → α2, r3 · Pl3, V=1``.
"""

from __future__ import annotations

from mechloop.model.check import argument_kind, require_valid
from mechloop.model.formula_words import WORDS, law_name
from mechloop.model.schema import (
    ArgumentRole,
    IntermediateArgument,
    LawArgument,
    LinkRole,
    Model,
)
from mechloop.model.structure import MODULE_SOLUTIONS, ContourInfo, is_function, param_role
from mechloop.spatial.contour import MODULES as SPATIAL_MODULES


def spatial_branches(module: str) -> int:
    """Solutions of spatial module ``module`` (2 for a name that is not one: a coupled
    block, as the planar default)."""
    return SPATIAL_MODULES[module][3] if module in SPATIAL_MODULES else 2


def symbol(name: str) -> str:
    """'a2' -> 'α2', 'r3' -> 'r3', 'b2' -> 'β2' (spatial)."""
    return {"a": "α", "b": "β"}.get(name[0], "r") + name[1:]


def _unit(model: Model, name: str) -> str:
    return model.units.angle if name[0] in "ab" else model.units.length


def _fmt(value, unit: str, lang: str = "en") -> str:
    if isinstance(value, str):
        return value.strip()
    if lang != "en":  # Russian: the unit's Russian designation, 10°
        from mechloop.report.numbers import unit_text

        shown = unit_text(unit, lang)
        return f"{value:g}{'' if shown == '°' else ' '}{shown}"
    return f"{value:g} {unit}"


def _plus(value, unit: str, lang: str = "en") -> str:
    """' + 10 deg', ' − 10 deg', or '' for zero."""
    if value in (0, 0.0):
        return ""
    text = _fmt(value, unit, lang)
    if text.startswith("-"):
        return f" − {text[1:].lstrip()}"
    return f" + {text}"


def role_text(model: Model, name: str, lang: str = "en") -> str:
    """How parameter ``name`` is given: '0.05 m', 'function', 'arg 1 + 10 deg', ...
    (``lang`` 'ru': '0.05 м', 'искомый', 'арг. 1 + 10°'; numbers still with the point)."""
    role = param_role(model, name)
    unit = _unit(model, name)
    words = WORDS[lang]
    if is_function(role):
        return words["function"]
    if isinstance(role, ArgumentRole):
        return words["arg"].format(number=role.argument,
                                   offset=_plus(role.offset, unit, lang))
    if isinstance(role, LinkRole):
        factor = "" if role.ratio == 1 else f"{role.ratio:g}·"
        return f"{factor}{symbol(role.link)}{_plus(role.delta, unit, lang)}"
    return _fmt(role, unit, lang)


def parametric_formula(model: Model, info: ContourInfo, lang: str = "en") -> str:
    """``'α1 (arg 1) → r3, α2 · Pl3, V=1'`` — the parametric formula of one contour."""
    inputs = [f"{symbol(p)} ({role_text(model, p, lang)})" for p in info.arguments]
    inputs += [symbol(p) for p in info.links]
    lhs = ", ".join(inputs) if inputs else WORDS[lang]["constants only"]
    count = MODULE_SOLUTIONS.get(info.module, spatial_branches(info.module))
    variant = info.variant if count > 1 else 1
    module = WORDS[lang].get(f"module {info.module}", info.module)  # coupled: Russian
    return f"{lhs} → {', '.join(symbol(f) for f in info.functions)} · {module}, V={variant}"


def describe_structure(model: Model, lang: str = "en") -> str:
    """Multi-line description of the model's structure, contour by contour, in ``lang``
    ('en', or 'ru': the course's Russian terms, units and the decimal comma; the words are
    in :mod:`mechloop.model.formula_words`)."""
    structure = require_valid(model)
    words = WORDS[lang]
    lines = []
    title = model.name or words["model"]
    kind = words["spatial" if any(c.spatial for c in model.contours) else "planar"]
    lines.append(words["head"].format(title=title, kind=kind, contours=len(model.contours),
                                      vectors=len(model.vectors), positions=model.positions))
    if model.time is None:
        lines.append(words["no time"])
    elif hasattr(model.time, "rpm"):
        turns = ("" if model.time.turns == 1
                 else words["turns"].format(turns=f"{model.time.turns:g}"))
        lines.append(words["rpm"].format(rpm=f"{model.time.rpm:g}", turns=turns,
                                         positions=model.positions))
    else:
        lines.append(words["time table"].format(positions=model.positions))
    for number, arg in sorted(model.arguments.items()):
        kind = words[argument_kind(model, number)]
        driven = [symbol(f"{letter}{n}") for n, v in sorted(model.vectors.items())
                  for letter in "rab"
                  if isinstance(getattr(v, letter), ArgumentRole)
                  and getattr(v, letter).argument == number]
        form = (words["law"].format(law=law_name(arg.law, lang), start=arg.start[0],
                                    end=arg.end[0])
                if isinstance(arg, LawArgument) else
                words["intermediate"].format(count=arg.intermediate.count,
                                             start=arg.intermediate.start,
                                             to=arg.intermediate.to)
                if isinstance(arg, IntermediateArgument)
                else words["table"].format(count=len(arg.table)))
        lines.append(words["argument"].format(number=number, kind=kind, form=form,
                                              driven=", ".join(driven)))
    lines.append(words["order"] + " → ".join(words["contour"].format(number=n)
                                             for n in structure.order))
    for info in structure.ordered():
        lines.append("")
        name = model.contours[info.number - 1].name
        spatial = model.contours[info.number - 1].spatial
        lines.append(words["contour vectors"].format(
            contour=words["contour"].format(number=info.number),
            name=f" — {name}" if name else "",
            vectors=", ".join(map(str, model.contours[info.number - 1].vectors))))
        link_terms = [f"{symbol(p)} = {role_text(model, p, lang)}" for p in info.links]
        structure_formula = f"n={3 if spatial else 2}, m={len(info.vectors)}"
        if link_terms:
            structure_formula += words["links"] + ", ".join(link_terms)
        lines.append(words["structure formula"].format(formula=structure_formula))
        block = next((b for b in structure.blocks if info.number in b.contours), None)
        solutions = (words["solutions"].format(count=MODULE_SOLUTIONS[info.module])
                     if info.module in MODULE_SOLUTIONS else
                     words["solutions"].format(count=spatial_branches(info.module))
                     if spatial and info.module != "coupled" else
                     words["block"].format(number=block.number,
                                           contours=", ".join(map(str, block.contours)),
                                           unknowns=", ".join(map(symbol, block.unknowns))))
        lines.append(words["parametric formula"].format(
            formula=parametric_formula(model, info, lang), solutions=solutions))
        known = [f"{symbol(f'{letter}{n}')}={role_text(model, f'{letter}{n}', lang)}"
                 for n in info.vectors for letter in ("rab" if spatial else "ra")
                 if f"{letter}{n}" not in info.functions
                 and f"{letter}{n}" not in info.arguments and f"{letter}{n}" not in info.links]
        if known:
            lines.append(words["constants"].format(known=", ".join(known)))
        if info.needs:
            lines.append(words["needs"].format(needs=", ".join(map(str, info.needs))))
    text = "\n".join(lines)
    if lang == "en":
        return text
    from mechloop.views.decimal_mark import localized  # the decimal comma

    return localized(text, lang)
