"""Gear meshes in the force analysis: one unknown per mesh, the tangential force.

A mesh (``gears:`` in the model, :class:`~mechloop.model.gearing.GearMesh`) between bodies
``i`` and ``j`` with the pitch point ``P`` and the pressure angle ``α``: the force of
``i`` on ``j`` at ``P`` is ``F_t·t + |F_t|·tan α·u``, with ``u`` the unit vector from
``P`` to the centre of gear ``j`` (its revolute pair; from the centre outward for a ring
gear) and ``t = i·u`` (the common tangent, counter-clockwise of ``u``).  The radial part
always pushes the gears apart, so the line of action (``t ± tan α·u``) depends on the sign
of ``F_t``: the force system is solved with ``+`` and re-solved with ``−`` at the
positions where ``F_t`` came out negative (:func:`choose_sides`).  Ideal teeth: no
friction, so the mesh does no work (its two contact points move alike along the normal).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from mechloop.errors import Problem
from mechloop.model.dynamic import PointOn
from mechloop.model.schema import Model
from mechloop.model.units import UnitProblem, to_si

Array = NDArray[np.float64]
Complex = NDArray[np.complex128]


@dataclass(frozen=True)
class MeshPair:
    """A gear mesh of the mechanism (SI): ``bodies`` (the force is of the first on the
    second), the pitch point ``at``, ``pressure`` (rad), the centre of the second gear
    ``center`` (the point of its revolute pair) and whether it has internal teeth."""

    name: str
    bodies: tuple[int, int]
    at: PointOn
    pressure: float
    center: PointOn
    ring: bool


@dataclass(frozen=True)
class MeshForce:
    """A mesh's force over positions: ``force`` (N, complex) of the first body on the
    second at ``point`` (m, complex), ``tangential`` ``F_t`` (N, signed along ``t``),
    ``radial`` (N, ≥ 0, separating) and ``normal`` ``|F_t|/cos α`` (N)."""

    mesh: MeshPair
    point: Complex
    force: Complex
    tangential: Array
    radial: Array
    normal: Array


def mesh_pairs(model: Model, pairs, problems: list[Problem]) -> tuple[MeshPair, ...]:
    """The model's ``gears:`` compiled against its lower ``pairs`` (the second gear's
    centre is its revolute pair); every problem located under ``gears``."""
    out = []
    for name, gear in (getattr(model, "gears", None) or {}).items():
        path = ("gears", name)
        first, second = gear.bodies
        bad = [b for b in gear.bodies if b != 0 and b not in model.bodies]
        if bad or first == second:
            problems.append(Problem((*path, "bodies"), f"gear mesh {name!r} needs two "
                                    "different bodies of the model"
                                    + (f"; {bad[0]} is not one" if bad else ""),
                                    f"use two of {sorted(model.bodies)}"))
            continue
        if gear.ring is not None and gear.ring not in gear.bodies:
            problems.append(Problem((*path, "ring"), f"ring {gear.ring} is not one of the "
                                    f"mesh's bodies {list(gear.bodies)}",
                                    "name the body with internal teeth, or leave ring out"))
            continue
        try:
            alpha = to_si(gear.pressure_angle, "angle", model.units.angle)
        except UnitProblem as exc:
            problems.append(Problem((*path, "pressure_angle"), exc.message, exc.hint))
            continue
        if not 0 <= alpha < np.pi / 2:
            problems.append(Problem((*path, "pressure_angle"), "the pressure angle must lie "
                                    "in [0°, 90°)", "use the standard 20°"))
            continue
        axles = [p for p in pairs if p.kind == "revolute" and second in p.bodies]
        if len(axles) != 1:
            problems.append(Problem((*path, "bodies"), f"the gear of body {second} needs "
                                    "exactly one revolute pair, its axle, to tell the "
                                    f"radial direction (it has {len(axles)})",
                                    "put the mesh's second gear on one pin (list the gear "
                                    "on a body of its own)"))
            continue
        out.append(MeshPair(name, (first, second), gear.at, float(alpha), axles[0].at,
                            gear.ring == second))
    return tuple(out)


def directions(mesh: MeshPair, placement) -> tuple[Complex, Complex, Complex]:
    """The pitch point ``P``, the unit ``u`` (radial, separating on the second gear) and
    the tangent ``t = i·u``, each ``(P,)`` complex."""
    p = placement.point(mesh.at).z
    centre = placement.point(mesh.center).z
    with np.errstate(invalid="ignore", divide="ignore"):
        u = (centre - p) / np.abs(centre - p)
    if mesh.ring:
        u = -u
    return p, u, 1j * u


def choose_sides(tangential: Array) -> NDArray[np.bool_]:
    """The positions where the line of action is the ``−`` one (``F_t < 0``)."""
    with np.errstate(invalid="ignore"):
        return tangential < 0
