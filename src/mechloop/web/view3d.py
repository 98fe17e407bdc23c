"""A solved model with spatial contours as the page draws it (issue 17): the diagram is
the 3-D view's data (:func:`mechloop.views.spatial_html.view_data`: every vector's tail
and head ``{x, y, z}`` over the positions, the ground, the viewing angles of the static
3-D plan), marked ``spatial: true`` so the page draws it with ``static/view3d.js``; the
rest (breaks, the results table, its precision) as for a planar model
(:func:`mechloop.web.payload.solution`).  A model with bodies gets its dynamics by
virtual power (:func:`mechloop.spatial.dynamics.solve_spatial_dynamics`), the table its
columns.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from mechloop.model.schema import ArgumentRole, Model
from mechloop.views.spatial_html import view_data
from mechloop.views.spatial_plan import spatial_scene


def parameter_marks(model: Model, number: int) -> dict[str, str]:
    """``{'a': 'function', 'b': 'argument'}``: the parameters of vector ``number`` that
    are unknowns of the loops or arguments (the page picks its first plotted column
    among the functions)."""
    vector = model.vectors[number]
    marks = {}
    for letter in "rab":
        value = getattr(vector, letter, None)
        if isinstance(value, ArgumentRole):
            marks[letter] = "argument"
        elif isinstance(value, str) and value.strip() == "function":
            marks[letter] = "function"
    return marks


def spatial_solution(model: Model) -> dict[str, Any]:
    """Everything the page shows of a solved spatial model (see the module docstring)."""
    from mechloop.solve.kinematics import solve
    from mechloop.web.payload import precision, table

    kin = solve(model)
    if model.bodies:
        from mechloop.spatial.dynamics import solve_spatial_dynamics

        solved: Any = solve_spatial_dynamics(model)
    else:
        solved = kin
    scene = spatial_scene(kin)
    diagram = view_data(scene)
    for vector in diagram["vectors"]:
        vector["marks"] = parameter_marks(model, vector["number"])
    box = [[float(v) for v in pair] for pair in _box(scene)]
    diagram.update({"spatial": True, "limits": [*box[0], *box[1]], "centers": [],
                    "joints": []})
    breaks = [{"contour": b.contour, "module": b.module, "reason": b.reason,
               "positions": np.asarray(b.positions, dtype=np.int64)} for b in kin.breaks]
    return {"name": model.name or "", "count": scene.count, "dynamics": bool(model.bodies),
            "time": kin.time, "broken": np.asarray(kin.broken, dtype=bool),
            "breaks": breaks, "diagram": diagram, "columns": table(solved, model),
            "precision": precision(model)}


def _box(scene: Any) -> Any:
    from mechloop.views.spatial_plan import _all_points, scene_box

    return scene_box(_all_points(scene))
