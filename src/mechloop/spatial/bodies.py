"""Bodies of a model with spatial contours: their frames, angular motion and masses.

A body (``bodies:``, as in a planar model) is a set of vectors fixed in it.  Its **frame**
is built from the unit directions ``u(α, β)`` of its vectors
(:func:`~mechloop.spatial.points.unit_direction`):

* ``e1 = u₁``, the direction of the body's first listed vector;
* ``e3 = (u₁ × w) / |u₁ × w|`` with ``w`` the direction of the first later vector not
  parallel to ``u₁`` (the normal of the plane of the two), and ``e2 = e3 × e1``.

The frame turns with the body, so its angular velocity and acceleration are exactly
``ω = ½ Σᵢ eᵢ × ėᵢ`` and ``ε = ½ Σᵢ eᵢ × ëᵢ`` (from ``ėᵢ = ω × eᵢ``:
``Σ eᵢ × (ω × eᵢ) = 3ω − ω``), with ``ė3 = (u̇₁ × w + u₁ × ẇ)/s`` and ``ë3 = (ü₁ × w +
2 u̇₁ × ẇ + u₁ × ẅ)/s`` (``s = |u₁ × w|`` is constant in a rigid body: checked), and
``ė2``, ``ë2`` by the product rule.  A body whose vectors are all parallel (a rod between
two ball joints) has no spin about its axis that the kinematics decide: it is taken as
zero, ``ω = u₁ × u̇₁`` and ``ε = u₁ × ü₁``, and its inertia tensor must then be symmetric
about the rod, ``[J_axis, J, J]`` (so the kinetic energy does not depend on the spin
left out).  For a planar body in the XY plane, ``ω = (0, 0, α̇)``.

The **inertia tensor** of a mass (kg·m², about its centre of mass, in the body frame
``(e1, e2, e3)``) is ``inertia: [Jx, Jy, Jz]`` (principal axes along the frame), the full
symmetric 3×3 tensor, ``rod`` (``m·l²/12`` across the vector that carries the centre,
which must be the body's first vector: ``[0, J, J]``), or 0.  In space it is
``J_w = R J Rᵀ`` with ``R = [e1 e2 e3]``.  The planar moment of inertia of a body in the
XY plane is its ``Jz``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from mechloop.errors import Problem
from mechloop.model.dynamic import HeadPoint, TailPoint, VectorPoint
from mechloop.model.units import UnitProblem, to_si
from mechloop.spatial.points import Motion3, unit_direction

Array = NDArray[np.float64]

#: Directions closer to parallel than this sine make a one-axis body.
PARALLEL_SIN = 1e-6
#: The angle between two vectors of one body may change by this much (cosine) at most.
RIGID_TOL = 1e-9



def vectors_defined(model, number: int, body, problems: list[Problem]) -> bool:
    """Whether every vector body ``number`` lists is a vector of ``model``; else a
    problem at ``("bodies", number, "vectors")`` naming the first that is not."""
    missing = [v for v in body.vectors if v not in model.vectors]
    if missing:
        problems.append(Problem(("bodies", number, "vectors"), f"body {number} lists "
                                f"vector {missing[0]}, which is not defined",
                                f"use vectors of {sorted(model.vectors)}"))
    return not missing

@dataclass(frozen=True)
class Frame:
    """A moving body's frame over positions: ``axes`` ``(3, 3, P)`` (columns e1, e2, e3),
    ``omega`` and ``epsilon`` ``(3, P)`` (rad/s, rad/s², or analogs), and whether it is a
    one-axis body (``rod``: no spin about e1)."""

    axes: Array
    omega: Array
    epsilon: Array
    rod: bool


@dataclass(frozen=True)
class SpatialMass:
    """A lumped mass of a body: ``mass`` (kg), ``tensor`` (kg·m², 3×3, body frame, about
    the centre of mass) and its ``center``."""

    body: int
    mass: float
    tensor: Array
    center: TailPoint | HeadPoint | VectorPoint

    def world(self, frame: Frame) -> Array:
        """The tensor in the model's axes, ``(3, 3, P)``."""
        if frame.rod:  # symmetric about e1: J·I + (J_axis − J)·e1 e1ᵀ
            e1 = frame.axes[:, 0]
            j_axis, j = self.tensor[0, 0], self.tensor[1, 1]
            return j * np.eye(3)[:, :, None] + (j_axis - j) * e1[:, None] * e1[None]
        return np.einsum("iap,ab,jbp->ijp", frame.axes, self.tensor, frame.axes)


def _cross(a: Array, b: Array) -> Array:
    return np.cross(a, b, axis=0)


@np.errstate(invalid="ignore", divide="ignore")  # broken rows: NaN, marked broken
def body_frame(results, vectors: list[int], *, second: int | None = None) -> Frame:
    """The frame of a body made of ``vectors`` (see the module), from ``results`` (time
    derivatives or analogs); ``second`` is the vector whose direction sets e3 (None: a
    one-axis body)."""
    u = unit_direction(results, vectors[0])
    if second is None:
        n = u.p.shape[1]
        e2 = _cross(np.array([[0.0], [0.0], [1.0]]) + np.zeros((3, n)), u.p)
        return Frame(np.stack([u.p, e2, _cross(u.p, e2)], axis=1), _cross(u.p, u.v),
                     _cross(u.p, u.a), rod=True)
    w = unit_direction(results, second)
    normal = _cross(u.p, w.p)
    s = np.linalg.norm(normal, axis=0)
    e3 = Motion3(normal / s, (_cross(u.v, w.p) + _cross(u.p, w.v)) / s,
                 (_cross(u.a, w.p) + 2.0 * _cross(u.v, w.v) + _cross(u.p, w.a)) / s)
    e2 = Motion3(_cross(e3.p, u.p), _cross(e3.v, u.p) + _cross(e3.p, u.v),
                 _cross(e3.a, u.p) + 2.0 * _cross(e3.v, u.v) + _cross(e3.p, u.a))
    axes = (u, e2, e3)
    omega = 0.5 * sum(_cross(e.p, e.v) for e in axes)
    epsilon = 0.5 * sum(_cross(e.p, e.a) for e in axes)
    return Frame(np.stack([e.p for e in axes], axis=1), omega, epsilon, rod=False)


def frame_vector(results, number: int, vectors: list[int], problems: list[Problem]
                 ) -> int | None:
    """The vector that sets e3 of body ``number`` (None: all its vectors are parallel);
    a problem when two of its vectors turn relative to each other."""
    path = ("bodies", number, "vectors")
    first = unit_direction(results, vectors[0]).p
    good = np.isfinite(first).all(axis=0)
    second = None
    for v in vectors[1:]:
        other = unit_direction(results, v).p
        ok = good & np.isfinite(other).all(axis=0)
        if not ok.any():
            continue
        cos = np.einsum("ip,ip->p", first[:, ok], other[:, ok])
        if np.ptp(cos) > RIGID_TOL:
            problems.append(Problem(path, f"vectors {vectors[0]} and {v} of body {number} "
                                    "turn relative to each other, so they are not fixed "
                                    "in one body", "list in a body only vectors that move "
                                    "together (split it into bodies)"))
            return None
        sine = np.linalg.norm(_cross(first[:, ok], other[:, ok]), axis=0)
        if second is None and sine.min() > PARALLEL_SIN:
            second = v
    return second


def inertia_tensor(value, mass: float, units, length: Array | None, first: bool,
                   path: tuple, problems: list[Problem]) -> Array | None:
    """The 3×3 tensor (kg·m², body frame) of an ``inertia:`` entry (see the module);
    ``length`` is the length of the centre's vector for ``rod`` and ``first`` whether that
    vector is the body's first."""
    if value == "rod":
        if length is None or not first:
            problems.append(Problem(path, "'rod' needs the centre on the body's first "
                                    "vector (the rod's axis, e1), of constant length",
                                    "give the tensor: inertia: [Jx, Jy, Jz]"))
            return None
        j = mass * float(length) ** 2 / 12.0
        return np.diag([0.0, j, j])
    try:
        if not isinstance(value, list):
            j = to_si(value, "inertia", units.inertia)
            if j != 0:
                problems.append(Problem(path, "a body of a model with spatial contours "
                                        "needs its inertia tensor, not one moment of inertia",
                                        "give inertia: [Jx, Jy, Jz] (principal, in the body "
                                        "frame) or the 3×3 tensor [[Jxx, Jxy, Jxz], [Jxy, "
                                        "Jyy, Jyz], [Jxz, Jyz, Jzz]]"))
                return None
            return np.zeros((3, 3))
        if len(value) == 3 and not any(isinstance(x, list) for x in value):
            tensor = np.diag([to_si(x, "inertia", units.inertia) for x in value])
        elif len(value) == 3 and all(isinstance(r, list) and len(r) == 3 for r in value):
            tensor = np.array([[to_si(x, "inertia", units.inertia) for x in r]
                               for r in value])
        else:
            problems.append(Problem(path, "an inertia tensor is [Jx, Jy, Jz] or 3 rows of 3",
                                    "give inertia: [Jx, Jy, Jz] or [[Jxx, Jxy, Jxz], [Jxy, "
                                    "Jyy, Jyz], [Jxz, Jyz, Jzz]]"))
            return None
    except UnitProblem as exc:
        problems.append(Problem(path, exc.message, exc.hint))
        return None
    scale = max(float(np.abs(tensor).max()), 1e-300)
    if np.abs(tensor - tensor.T).max() > 1e-12 * scale:
        problems.append(Problem(path, "an inertia tensor is symmetric (Jxy = Jyx, ...)",
                                "make the rows and columns equal"))
        return None
    principal = np.linalg.eigvalsh(tensor)
    lo, mid, hi = principal
    if lo < -1e-12 * scale or hi > lo + mid + 1e-12 * scale:
        problems.append(Problem(path, "these moments of inertia belong to no body (each "
                                "principal moment is ≥ 0 and at most the sum of the other "
                                "two)", "check the values and their signs"))
        return None
    return tensor


def rod_symmetric(tensor: Array) -> bool:
    """Whether ``tensor`` is ``[J_axis, J, J]`` about e1 (no products of inertia)."""
    scale = max(float(np.abs(tensor).max()), 1e-300)
    off = tensor - np.diag(np.diag(tensor))
    return bool(np.abs(off).max() <= 1e-12 * scale
                and abs(tensor[1, 1] - tensor[2, 2]) <= 1e-12 * scale)
