"""Structure and parametric formulas of a vector model, as text (KDAM's "structure of the
vector model" panel).

Structure formula of a contour: ``n=2, m=4`` (planar, four vectors) plus the links that tie
its vectors to other parameters.  Parametric formula: ``arguments → functions`` with the
module type and the solution variant, e.g. ``α1 (arg 1) → α2, r3 · Pl3, V=1``.
"""

from __future__ import annotations

from mechloop.model.check import argument_kind, require_valid
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


def _fmt(value, unit: str) -> str:
    if isinstance(value, str):
        return value.strip()
    return f"{value:g} {unit}"


def _plus(value, unit: str) -> str:
    """' + 10 deg', ' − 10 deg', or '' for zero."""
    if value in (0, 0.0):
        return ""
    text = _fmt(value, unit)
    if text.startswith("-"):
        return f" − {text[1:].lstrip()}"
    return f" + {text}"


def role_text(model: Model, name: str) -> str:
    """How parameter ``name`` is given: '0.05 m', 'function', 'arg 1 + 10 deg', ..."""
    role = param_role(model, name)
    unit = _unit(model, name)
    if is_function(role):
        return "function"
    if isinstance(role, ArgumentRole):
        return f"arg {role.argument}{_plus(role.offset, unit)}"
    if isinstance(role, LinkRole):
        factor = "" if role.ratio == 1 else f"{role.ratio:g}·"
        return f"{factor}{symbol(role.link)}{_plus(role.delta, unit)}"
    return _fmt(role, unit)


def parametric_formula(model: Model, info: ContourInfo) -> str:
    """``'α1 (arg 1) → r3, α2 · Pl3, V=1'`` — the parametric formula of one contour."""
    inputs = [f"{symbol(p)} ({role_text(model, p)})" for p in info.arguments]
    inputs += [symbol(p) for p in info.links]
    lhs = ", ".join(inputs) if inputs else "constants only"
    count = MODULE_SOLUTIONS.get(info.module, spatial_branches(info.module))
    variant = info.variant if count > 1 else 1
    return f"{lhs} → {', '.join(symbol(f) for f in info.functions)} · {info.module}, V={variant}"


def describe_structure(model: Model) -> str:
    """Multi-line description of the model's structure, contour by contour."""
    structure = require_valid(model)
    lines = []
    title = model.name or "vector model"
    kind = "spatial" if any(c.spatial for c in model.contours) else "planar"
    lines.append(f"{title}: {kind}, {len(model.contours)} contour(s), {len(model.vectors)} "
                 f"vectors, positions 0..{model.positions}")
    if model.time is None:
        lines.append("time: none — derivatives are analogs with respect to argument 1")
    elif hasattr(model.time, "rpm"):
        turns = "" if model.time.turns == 1 else f", {model.time.turns:g} turns"
        lines.append(f"time: {model.time.rpm:g} rpm{turns} over positions 0..{model.positions}")
    else:
        lines.append(f"time: table over positions 0..{model.positions}")
    for number, arg in sorted(model.arguments.items()):
        kind = argument_kind(model, number)
        driven = [symbol(f"{letter}{n}") for n, v in sorted(model.vectors.items())
                  for letter in "rab"
                  if isinstance(getattr(v, letter), ArgumentRole)
                  and getattr(v, letter).argument == number]
        form = (f"law {arg.law} from position {arg.start[0]} to {arg.end[0]}"
                if isinstance(arg, LawArgument) else
                f"intermediate, {arg.intermediate.count} values from "
                f"{arg.intermediate.start} to {arg.intermediate.to} in every position"
                if isinstance(arg, IntermediateArgument)
                else f"table of {len(arg.table)} value(s)")
        lines.append(f"argument {number} ({kind}): {form}; drives {', '.join(driven)}")
    lines.append("solving order: " + " → ".join(f"contour {n}" for n in structure.order))
    for info in structure.ordered():
        lines.append("")
        name = model.contours[info.number - 1].name
        spatial = model.contours[info.number - 1].spatial
        lines.append(f"contour {info.number}" + (f" — {name}" if name else "")
                     + f": vectors {', '.join(map(str, model.contours[info.number - 1].vectors))}")
        link_terms = [f"{symbol(p)} = {role_text(model, p)}" for p in info.links]
        structure_formula = f"n={3 if spatial else 2}, m={len(info.vectors)}"
        if link_terms:
            structure_formula += "; links: " + ", ".join(link_terms)
        lines.append(f"  structure formula:  {structure_formula}")
        block = next((b for b in structure.blocks if info.number in b.contours), None)
        solutions = (f"{MODULE_SOLUTIONS[info.module]} solution(s)"
                     if info.module in MODULE_SOLUTIONS else
                     f"{spatial_branches(info.module)} solution(s)"
                     if spatial and info.module != "coupled" else
                     f"coupled block {block.number}: contours "
                     f"{', '.join(map(str, block.contours))} solved together for "
                     f"{', '.join(map(symbol, block.unknowns))} by Newton's method")
        lines.append(f"  parametric formula: {parametric_formula(model, info)} "
                     f"({solutions})")
        known = [f"{symbol(f'{letter}{n}')}={role_text(model, f'{letter}{n}')}"
                 for n in info.vectors for letter in ("rab" if spatial else "ra")
                 if f"{letter}{n}" not in info.functions
                 and f"{letter}{n}" not in info.arguments and f"{letter}{n}" not in info.links]
        if known:
            lines.append(f"  constants:          {', '.join(known)}")
        if info.needs:
            lines.append("  needs contours:     " + ", ".join(map(str, info.needs)))
    return "\n".join(lines)
