"""A solved model as the page draws it: the vector diagram of every position (the same
geometry as :mod:`mechloop.views.plan`: :func:`~mechloop.views.plan.plan_scene`, its ground
points, parameter marks and limits), the chain breaks, and the results table in the model's
display units (:mod:`mechloop.output.display`), with its numbers rounded to the model's
precision, which ``precision`` names (``{"digits": 3}``, ``{"decimals": 2}`` or ``{}``)
for the page to print them with.

Arrays are NumPy, of shape ``(P,)`` over the positions ``0..N``; an unknown value (a chain
break) is NaN here and ``null`` in the JSON (orjson), with ``broken`` saying why.
"""

from __future__ import annotations

import re
from typing import Any

import numpy as np

from mechloop.dynamics.analysis import DynamicResults, solve_dynamics
from mechloop.model.schema import Model
from mechloop.output.display import apply_display, resolve, round_frame
from mechloop.report.words import reason
from mechloop.solve.kinematics import solve
from mechloop.solve.results import Results
from mechloop.views.plan import PlanScene, parameter_roles, plan_scene, scene_limits

_HEADER = re.compile(r"^(.*) \[([^\[\]]+)\]$")
#: Columns of the table that are not results (the position number, the break flag).
_NOT_RESULTS = {"position", "chain_break"}


def solve_model(model: Model) -> Results | DynamicResults:
    """The kinematics, or with bodies the dynamics, of ``model``."""
    return solve_dynamics(model) if model.bodies else solve(model)


def _hex(color: tuple[float, float, float, float]) -> str:
    return "#" + "".join(f"{round(255 * c):02x}" for c in color[:3])


def _xy(z: np.ndarray) -> dict[str, np.ndarray]:
    return {"x": np.ascontiguousarray(z.real), "y": np.ascontiguousarray(z.imag)}


def diagram(scene: PlanScene) -> dict[str, Any]:
    """The vector diagram of every position: each vector's tail and head, its colour and
    parameter marks (``{'a': 'argument', 'r': 'function'}``), the ground points, and for
    dynamic results the centres of mass and the joints; the limits cover every position
    (the diagram keeps one scale while it moves)."""
    roles = parameter_roles(scene)
    vectors = [{"number": n, "color": _hex(scene.color(n)),
                "marks": {letter: roles[f"{letter}{n}"] for letter in "ar"
                          if f"{letter}{n}" in roles},
                "tail": _xy(scene.tails[n]), "head": _xy(scene.heads[n])}
               for n in scene.vectors()]
    points = [*scene.tails.values(), *scene.heads.values(), scene.ground]
    centers, joints = [], []
    if scene.dynamic is not None:
        for body, motion in sorted(scene.dynamic.centers.items()):
            z = scene.to_display(motion.z)
            centers.append({"name": f"S{body}", **_xy(z)})
            points.append(z)
        for pair in scene.dynamic.mechanism.pairs:
            if pair.kind == "prismatic" and pair.along is not None:
                z = (scene.tails[pair.along] + scene.heads[pair.along]) / 2
            else:
                z = scene.to_display(scene.placement.point(pair.at).z)
            joints.append({"name": pair.name, "kind": pair.kind, **_xy(z)})
    return {"unit": scene.unit, "limits": list(scene_limits(points)), "vectors": vectors,
            "ground": _xy(scene.ground), "centers": centers, "joints": joints}


def table(results: Results | DynamicResults, model: Model) -> list[dict[str, Any]]:
    """The results table in the display units of ``model`` (its ``display:`` section):
    one item per column, ``name``, ``unit`` and ``values`` (shape (P,), every digit: the
    plots' curves), and with a precision in the section ``shown``, the values rounded to
    it as the table files write them (:func:`~mechloop.output.display.round_frame`)."""
    shown = resolve(model.display)
    frame = apply_display(results.to_frame(), shown, ".parquet")  # converted, not rounded
    rounded = round_frame(frame, shown) if shown is not None and shown.rounds(".csv") \
        else None
    columns = []
    for header in frame.columns:
        match = _HEADER.match(str(header))
        name, unit = (match.group(1), match.group(2)) if match else (str(header), "")
        if name in _NOT_RESULTS:
            continue
        column = {"name": name, "unit": unit, "values": frame[header].to_numpy(dtype=float)}
        if rounded is not None:
            column["shown"] = rounded[header].to_numpy(dtype=float)
        columns.append(column)
    return columns


def precision(model: Model) -> dict[str, int]:
    """The precision the numbers of ``model``'s table are rounded to and printed with:
    ``{"digits": n}``, ``{"decimals": n}`` or ``{}`` (every digit)."""
    shown = resolve(model.display)
    if shown is not None and shown.digits is not None:
        return {"digits": shown.digits}
    if shown is not None and shown.decimals is not None:
        return {"decimals": shown.decimals}
    return {}


def solution(model: Model, solved: Results | DynamicResults | None = None) -> dict[str, Any]:
    """Everything the page shows of a solved model (see the module docstring)."""
    if any(c.spatial for c in model.contours):  # issue 17: the 3-D view's data
        from mechloop.web.view3d import spatial_solution

        return spatial_solution(model)
    solved = solve_model(model) if solved is None else solved
    kin = solved.kinematics if isinstance(solved, DynamicResults) else solved
    scene = plan_scene(solved)
    breaks = [{"contour": b.contour, "module": b.module, "reason": b.reason,
               "reason_ru": reason(b.reason, "ru"),  # the page's words in Russian
               "positions": np.asarray(b.positions, dtype=np.int64)} for b in kin.breaks]
    return {"name": model.name or "", "count": scene.count, "dynamics": bool(model.bodies),
            "time": kin.time, "broken": np.asarray(kin.broken, dtype=bool),
            "breaks": breaks, "diagram": diagram(scene), "columns": table(solved, model),
            "precision": precision(model)}
