"""The kinematic parts of the report of a model with spatial contours (issue 17): the
vectors' table with β, the coordinates of the vector ends at the intermediate position,
the 3-D vector scheme with its projections, the angles between adjacent vectors in
space, and the trajectories of the moving vector ends.

Lengths are in the display's length unit, angles in its angle unit (the units and
precision of :class:`~mechloop.report.numbers.Shown`); the figures are those of
:mod:`mechloop.views.spatial_plan` put in the report's language."""

from __future__ import annotations

import itertools

import numpy as np
from numpy.typing import NDArray

from mechloop.model.schema import Model
from mechloop.report.document import FigureItem, Paragraph, Section, Table
from mechloop.report.numbers import Shown
from mechloop.report.parameters import role_text
from mechloop.report.values import span_text
from mechloop.solve.results import Results
from mechloop.views.display import Display
from mechloop.views.russian import translate

Array = NDArray[np.float64]

#: Angle figures at most (as the planar report's section 4).
MAX_ANGLE_FIGURES = 6
#: An angle that varies less than this over the positions (rad) is constant.
ANGLE_TOL = 1e-9


def _values(results: Results, name: str) -> Array:
    values = np.asarray(results.value(name), dtype=float)
    return np.degrees(values) if name[0] in "ab" else values


def vector_table3(model: Model, results: Results, shown: Shown, w: dict[str, str]
                  ) -> Table:
    """Each vector: number, name, the role and value of r, α and β (a varying one as
    its range over the positions); a vector of a planar contour has no β ('—')."""
    spatial = set(getattr(results, "spatial_vectors", ()))
    rows = []
    for number, vector in sorted(model.vectors.items()):
        cells = [str(number), vector.name or ""]
        for letter in "rab":
            name = f"{letter}{number}"
            if letter == "b" and number not in spatial:
                cells += [w["none"], w["none"]]
                continue
            cells += [role_text(model, name, shown, w),
                      span_text(shown, _values(results, name),
                                "m" if letter == "r" else "deg", bare=True)]
        rows.append(tuple(cells))
    degrees = shown.unit_text("deg")
    header = (w["h_number"], w["h_name"], f"r: {w['h_role']}", f"r, {shown.unit_text('m')}",
              f"α: {w['h_role']}", f"α, {degrees}", f"β: {w['h_role']}", f"β, {degrees}")
    return Table(w["t_vectors3"], header, rows)


def vector_ends(results: Results) -> tuple[dict[int, Array], dict[int, Array]]:
    """Tails and heads (m, ``(3, P)``) of every vector, as the 3-D scheme places them."""
    from mechloop.views.spatial_plan import spatial_scene

    scene = spatial_scene(results, length_unit="m")
    return scene.tails, scene.heads


def joints_table(results: Results, position: int, shown: Shown, w: dict[str, str]
                 ) -> Table:
    """x, y, z of the tail and the head of every vector at ``position``, in the display
    length unit (every column to the precision of the largest coordinate)."""
    tails, heads = vector_ends(results)
    numbers = sorted(tails)
    table = np.array([[*tails[n][:, position], *heads[n][:, position]] for n in numbers])
    cells = shown.column(shown.value(table.ravel(), "m"))
    width = table.shape[1]
    rows = [(str(n), *cells[k * width:(k + 1) * width]) for k, n in enumerate(numbers)]
    unit = shown.unit_text("m")
    header = (w["h_number"], *(f"{w[end]} {axis}, {unit}" for end in ("h_tail", "h_head")
                               for axis in "xyz"))
    return Table(w["t_joints"].format(position=position), header, rows)


def scheme_figure(results: Results, position: int, length_unit: str | None, lang: str,
                  w: dict[str, str]) -> FigureItem:
    """The 3-D vector scheme at ``position`` with the projections on the three planes."""
    from mechloop.views.spatial_plan import plot_spatial_plan

    return FigureItem(w["f_plan3"].format(position=position), lambda: translate(
        plot_spatial_plan(results, position, length_unit=length_unit), lang))


def _directions(results: Results, number: int, tails: dict[int, Array],
                heads: dict[int, Array]) -> Array:
    """The unit direction ``(3, P)`` of vector ``number`` (NaN where the chain breaks or
    the vector has zero length)."""
    d = heads[number] - tails[number]
    with np.errstate(invalid="ignore", divide="ignore"):
        return d / np.linalg.norm(d, axis=0)


def space_angle(results: Results, a: int, b: int) -> Array:
    """The angle (rad, 0…π) between vectors ``a`` and ``b`` in space over the
    positions: ``atan2(|u_a × u_b|, u_a · u_b)``."""
    tails, heads = vector_ends(results)
    ua, ub = (_directions(results, n, tails, heads) for n in (a, b))
    # atan2 of the sine and the cosine: accurate near 0 and π, where arccos is not
    sine = np.linalg.norm(np.cross(ua, ub, axis=0), axis=0)
    return np.arctan2(sine, np.einsum("ip,ip->p", ua, ub))


def angle_pairs3(results: Results) -> list[tuple[int, int]]:
    """Adjacent vectors in each contour whose angle in space varies (the transmission
    angle of an RSSR among them)."""
    pairs = []
    for contour in results.model.contours:
        for a, b in itertools.pairwise(abs(v) for v in contour.vectors):
            angle = space_angle(results, a, b)
            finite = angle[np.isfinite(angle)]
            if finite.size and np.ptp(finite) > ANGLE_TOL:
                pairs.append((a, b))
    return pairs


def plot_space_angle(results: Results, a: int, b: int, display: Display):
    """The angle between vectors ``a`` and ``b`` in space against the position."""
    from mechloop.views.curves import Series, draw_curves
    from mechloop.views.figure import new_figure
    from mechloop.views.russian import keep_names, model_names

    figure = keep_names(new_figure(8.0, 4.5), model_names(results.model))
    ax = figure.add_subplot()
    x = Series("position", results.positions.astype(float), None)
    draw_curves(ax, x, [Series(f"∠({a}, {b})", space_angle(results, a, b), "angle")],
                display)
    return figure


def angles_section(results: Results, display: Display, lang: str, w: dict[str, str]
                   ) -> Section:
    """The angles between adjacent vectors in space (the planar report's section 4)."""
    blocks: list = [FigureItem(w["f_angle3"].format(a=a, b=b),
                               lambda a=a, b=b: translate(
                                   plot_space_angle(results, a, b, display), lang))
                    for a, b in angle_pairs3(results)[:MAX_ANGLE_FIGURES]]
    return Section(w["s_angles3"], blocks or [Paragraph(w["no_angles3"])])


def trajectories_section(results: Results, position: int, length_unit: str | None,
                         lang: str, w: dict[str, str]) -> Section:
    """The paths of every moving vector end over the cycle in 3-D and the projections,
    over the scheme at ``position``."""
    from mechloop.views.spatial_plan import plot_spatial_trajectories

    return Section(w["s_trajectories"], [FigureItem(w["f_trajectories"], lambda: translate(
        plot_spatial_trajectories(results, position=position, length_unit=length_unit),
        lang))])
