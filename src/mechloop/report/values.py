"""Small helpers of the report's content: the range of values over the positions where
the chain assembles, symbols, and points and directions of the model in words."""

from __future__ import annotations

import math

import numpy as np
from numpy.typing import NDArray

from mechloop.model.dynamic import HeadPoint, TailPoint, VectorPoint
from mechloop.model.units import to_si
from mechloop.report.numbers import Shown, joined


def finite_span(values: NDArray[np.float64]) -> tuple[float, float] | None:
    """(smallest, largest) of the finite values; None when there is none."""
    array = np.asarray(values, dtype=float)
    finite = array[np.isfinite(array)]
    if not finite.size:
        return None
    return float(finite.min()), float(finite.max())


def peak(values: NDArray[np.float64]) -> tuple[int, float] | None:
    """(position, value) of the largest magnitude among the finite values."""
    array = np.abs(np.asarray(values, dtype=float))
    if not np.isfinite(array).any():
        return None
    index = int(np.nanargmax(np.where(np.isfinite(array), array, -1.0)))
    return index, float(np.asarray(values, dtype=float)[index])


def symbol(name: str) -> str:
    """'a2' -> 'α2', 'r3' -> 'r3', 'da2' -> 'dα2', 'b3' -> 'β3' (a spatial vector's
    rotation about Y)."""
    head = name.rstrip("0123456789")
    if head in ("a", "da", "dda", "b", "db", "ddb"):
        return head[:-1] + ("α" if head[-1] == "a" else "β") + name[len(head):]
    return name


def span_text(shown: Shown, values: NDArray[np.float64], unit: str, *,
              bare: bool = False) -> str:
    """'low … high unit' of ``values`` (in ``unit``) over the positions where they are
    finite; a single value when they do not vary; '—' when there is none.  ``bare``:
    without the unit (a table whose header names it)."""
    found = finite_span(values)
    if found is None:
        return "—"
    low, high = found
    f = shown.factor(unit)
    if math.isclose(low, high, rel_tol=1e-12, abs_tol=1e-15):
        text = shown.number(low * f)
    else:
        scale = max(abs(low * f), abs(high * f))
        text = f"{shown.number(low * f, scale)} … {shown.number(high * f, scale)}"
    return text if bare else joined(text, shown.unit_text(unit))


def module_text(module: str, lang: str) -> str:
    """A module's name: 'Pl3' ('Пл3' in Russian), 'Pr10' ('Пр10'), 'coupled'
    ('связанный')."""
    if lang != "ru":
        return module
    if module == "coupled":
        return "связанный"
    return module.replace("Pl", "Пл").replace("Pr", "Пр")


def point_text(point: TailPoint | HeadPoint | VectorPoint, model, shown: Shown,
               w: dict[str, str]) -> str:
    """A point of the model in words: 'head of vector 3', 'on vector 2, 0.3 of its
    length from the tail', with distances in the display's length unit."""
    if isinstance(point, TailPoint):
        return w["p_tail"].format(v=point.tail)
    if isinstance(point, HeadPoint):
        return w["p_head"].format(v=point.head)
    length = model.units.length
    if point.share is not None:
        text = w["p_share"].format(v=point.vector, share=shown.number(float(point.share)))
    else:
        text = w["p_along"].format(v=point.vector, along=shown.text(
            to_si(point.along, "length", length), "m"))
    across = to_si(point.across, "length", length)
    if across:
        text += w["p_across"].format(across=shown.text(across, "m"))
    return text


def angle_text(value, model, shown: Shown) -> str:
    """An angle of the model file (number in the model's angle unit or a quantity) in the
    display's angle unit."""
    return shown.angle(to_si(value, "angle", model.units.angle))
