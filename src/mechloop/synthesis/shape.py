"""Shape-only path synthesis: the targets' position, orientation and size are free.

With ``path.frame`` (``{translate, rotate, scale}``, or ``free`` for all three) a target
point set is compared with the *shape* of the traced curve: each design's curve ``z``
(the tracing point at the positions, complex ``(D, P)``) is placed on the targets by the
similarity ``w = a·z + b`` (``a`` complex: rotation ``arg a`` and scale ``|a|``; ``b``
the translation) that brings it nearest them, and the deviations are the distances from
the targets to the placed curve, in the user's frame and units.  ``a`` is kept to
``|a| = 1`` without ``scale``, to a positive real without ``rotate``, to 1 without
either, and ``b`` to 0 without ``translate``.

The placement is found in closed form, iterated as ICP (iterative closest points):
each target's nearest point on the placed polyline gives the correspondences, and the
best ``(a, b)`` for them is a weighted linear least-squares problem in the four real
numbers of ``a`` and ``b`` (in complex numbers Umeyama's closed form of the Procrustes
problem is exactly this regression).  The first iterations measure the full distance
to the matched point (point-to-point, robust from far); the last measure mostly the
distance along the curve's normal there (point-to-line, which converges fast — the
targets may slide along the curve).  Starts are equivariant with the targets:
centroids matched, sizes matched by their RMS radii, and ``ROTATIONS`` turns around the
difference of the principal axes, so a translated, rotated or scaled target set gets the
same placement, transformed: Q is invariant to translating and rotating the targets
and scales with them.  All designs, starts and targets are one array operation per
iteration.

The search works on the shape (the mechanism's own frame and size are free
directions); the written model is the mechanism placed on the targets
(:func:`place_model`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from mechloop.errors import ModelError, Problem
from mechloop.model.schema import ArgumentRole, LinkRole, Model
from mechloop.model.synthesis import Frame
from mechloop.model.units import to_si, unit_factor
from mechloop.synthesis import deviations as dv

Array = NDArray[np.float64]
Complex = NDArray[np.complex128]

#: Starting rotations of the ICP (equally spaced around the principal-axis guess).
ROTATIONS = 8
#: Point-to-point iterations from every start, then point-to-line ones from the best
#: (at most: they stop when the placement settles; quadratic near a good fit), in the
#: search and for a precise result.
COARSE = 6
FINE = 8
PRECISE = 40
#: Positions of the curve in the point-to-point iterations (every few positions).
_COARSE_POINTS = 48
#: Weight of the tangential error in the point-to-line iterations.
_TANGENT = 1e-3


@dataclass(frozen=True)
class Freedom:
    """Which parts of the placement are free."""

    translate: bool = True
    rotate: bool = True
    scale: bool = True

    @classmethod
    def of(cls, frame: Frame | str) -> Freedom:
        if frame == "free":
            return cls()
        return cls(frame.translate, frame.rotate, frame.scale)


def fit_placement(z: Complex, targets: Complex, freedom: Freedom,
                  weights: Array | None = None, *, fine: int = FINE
                  ) -> tuple[Complex, Complex, Array]:
    """The best placement ``w = a·z + b`` of each traced curve on the targets.

    ``z`` : complex ``(D, P)``, the curve in the mechanism's frame (m); ``targets`` :
    complex ``(K,)`` (m); ``weights`` ``(K,)`` (the targets' E_k; least squares of the
    weighted distances); ``fine`` point-to-line iterations at most.  Returns ``a``,
    ``b`` (complex ``(D,)``) and the distances from the targets to the placed polyline,
    ``(D, K)`` (m; NaN for a curve with NaN)."""
    n_designs = z.shape[0]
    w2 = np.ones(targets.size) if weights is None else np.asarray(weights, float) ** 2
    good = np.isfinite(z).all(axis=-1)
    zz = np.where(good[:, None], z, 0.0)
    a0, b0 = _starts(zz, targets, freedom)                       # (D, S)
    starts = a0.shape[1]
    coarse = zz[:, ::max(1, zz.shape[1] // _COARSE_POINTS)]     # every few positions
    many = np.repeat(coarse, starts, axis=0)                      # (D·S, P')
    a, b = a0.reshape(-1), b0.reshape(-1)
    for _ in range(COARSE):
        a, b = _step(many, targets, a, b, freedom, w2, tangent=1.0)
    dist = dv.nearest_on_curve(a[:, None] * many + b[:, None], targets)[0]
    score = (dist * dist * w2).sum(axis=-1).reshape(n_designs, starts)
    best = np.nan_to_num(score, nan=np.inf).argmin(axis=-1)
    pick = np.arange(n_designs) * starts + best
    a, b = a[pick], b[pick]
    size = np.sqrt(np.mean(np.abs(targets - targets.mean()) ** 2)) or 1.0
    for _ in range(fine):
        new_a, new_b = _step(zz, targets, a, b, freedom, w2, tangent=_TANGENT)
        moved = np.abs(new_a - a) + np.abs(new_b - b) / np.maximum(size, 1e-300)
        a, b = new_a, new_b
        if not np.any(moved > 1e-12 * np.abs(a)):
            break
    dist = dv.nearest_on_curve(a[:, None] * zz + b[:, None], targets)[0]
    dist = np.where(good[:, None], dist, np.nan)
    return a, b, dist


def _starts(z: Complex, targets: Complex, freedom: Freedom) -> tuple[Complex, Complex]:
    """Starting placements ``(D, S)``: centroids matched, RMS radii matched, rotations
    around the difference of the principal axes (all equivariant with the targets)."""
    zc = z.mean(axis=-1) if freedom.translate else np.zeros(z.shape[0], complex)
    tc = targets.mean() if freedom.translate else 0j
    dz = z - zc[:, None]
    dt = targets - tc
    rz = np.sqrt(np.mean(np.abs(dz) ** 2, axis=-1))
    rt = float(np.sqrt(np.mean(np.abs(dt) ** 2)))
    size = np.where(rz > 0, rt / np.where(rz > 0, rz, 1.0), 1.0) if freedom.scale else \
        np.ones(z.shape[0])
    if freedom.rotate:
        axis = 0.5 * (np.angle(np.sum(dt * dt)) - np.angle(np.sum(dz * dz, axis=-1)))
        turns = axis[:, None] + 2 * np.pi * np.arange(ROTATIONS)[None, :] / ROTATIONS
        a = size[:, None] * np.exp(1j * turns)
    else:
        a = size[:, None].astype(complex)
    b = tc - a * zc[:, None] if freedom.translate else np.zeros_like(a)
    return a, b


def _step(z: Complex, targets: Complex, a: Complex, b: Complex, freedom: Freedom,
          w2: Array, *, tangent: float) -> tuple[Complex, Complex]:
    """One ICP iteration: the nearest points of the placed curves, then the best
    placement for them (weighted linear least squares; ``tangent`` weighs the error
    along the curve against the error across it)."""
    placed = a[:, None] * z + b[:, None]
    _, s, point = dv.nearest_on_curve(placed, targets)           # (D, K)
    ok = np.isfinite(point)
    safe_a = np.where(np.abs(a) > 0, a, 1.0)
    c = np.where(ok, (point - b[:, None]) / safe_a[:, None], 0.0)  # matched, own frame
    i = np.clip(np.floor(s).astype(np.int64), 0, z.shape[1] - 2)
    i = np.where(ok, i, 0)
    seg = np.take_along_axis(placed, i + 1, axis=-1) - np.take_along_axis(placed, i, axis=-1)
    length = np.abs(seg)
    normal = np.where(length > 0, 1j * seg / np.where(length > 0, length, 1.0), 1.0)
    # unknowns u = (Re a, Im a, Re b, Im b) where free; residual e = a c + b - t
    cols = []
    if freedom.scale:
        cols.append(c)
        if freedom.rotate:
            cols.append(1j * c)
        fixed = np.zeros_like(c)
    elif freedom.rotate:  # |a| = 1: a turn δ from a, linearized (Gauss-Newton)
        cols.append(1j * a[:, None] * c)
        fixed = a[:, None] * c
    else:
        fixed = c  # a = 1
    if freedom.translate:
        cols += [np.ones_like(c), 1j * np.ones_like(c)]
    if not cols:
        return a, b
    basis = np.stack(cols, axis=-1)                                # (D, K, U)
    rhs = targets[None, :] - fixed
    weight = np.where(ok, w2[None, :], 0.0)
    rows, values = [], []
    for direction, share in ((normal, 1.0), (1j * normal, tangent)):
        scale = np.sqrt(weight * share)
        rows.append(np.real(np.conj(direction)[..., None] * basis) * scale[..., None])
        values.append(np.real(np.conj(direction) * rhs) * scale)
    m = np.concatenate(rows, axis=1)                               # (D, 2K, U)
    v = np.concatenate(values, axis=1)
    normal_eq = np.einsum("dku,dkv->duv", m, m)
    rhs_eq = np.einsum("dku,dk->du", m, v)
    # a singular system (all targets matched to one point) keeps the placement
    diag = np.einsum("duu->du", normal_eq)
    solvable = diag.min(axis=-1) > 1e-12 * diag.max(axis=-1)
    ridge = np.eye(normal_eq.shape[-1]) * 1e-14 * diag.max(axis=-1)[:, None, None]
    safe = np.where(solvable[:, None, None], normal_eq + ridge, np.eye(normal_eq.shape[-1]))
    solved = np.linalg.solve(safe, rhs_eq[..., None])[..., 0]
    if freedom.scale and freedom.rotate:
        new_a, k = solved[:, 0] + 1j * solved[:, 1], 2
    elif freedom.scale:  # a positive real
        new_a, k = np.maximum(solved[:, 0], 0.0) + 0j, 1
    elif freedom.rotate:
        new_a, k = a * np.exp(1j * solved[:, 0]), 1
    else:
        new_a, k = np.ones_like(a), 0
    new_b = solved[:, k] + 1j * solved[:, k + 1] if freedom.translate else np.zeros_like(b)
    keep = solvable & np.isfinite(new_a) & np.isfinite(new_b) & (np.abs(new_a) > 0)
    return np.where(keep, new_a, a), np.where(keep, new_b, b)


def check_frame(model: Model) -> None:
    """A shape task that scales needs every length of the model to scale with it: a
    length driven by an argument (a slider's input) cannot; a located error."""
    task = model.synthesis
    frame = Freedom.of(task.path.frame)
    if not frame.scale:
        return
    problems = [Problem(("vectors", number, "r"), f"r{number} is driven by argument "
                        f"{vector.r.argument}, which a scaled placement cannot scale",
                        "set frame: {scale: false}")
                for number, vector in model.vectors.items()
                if isinstance(vector.r, ArgumentRole)]
    if problems:
        raise ModelError(problems)


def place_model(model: Model, a: complex, b: complex) -> Model:
    """``model`` moved by the similarity ``w = a·z + b`` (SI): every length times
    ``|a|`` (constants and the deltas of links), every absolute angle plus ``arg a``
    (constant angles and the offsets of driven angles; a link's delta is relative and
    stays, unless the link has a ratio k ≠ 1: its delta gains (1 − k)·arg a), the fixed
    starts of contours mapped, a start at the origin moved to ``b``.
    The synthesis task is kept as written; loads and dynamic data are not moved."""
    scale, turn = abs(a), float(np.angle(a))
    length = unit_factor(model.units.length, "length")
    angle = unit_factor(model.units.angle, "angle")
    data = model.model_dump(mode="json", exclude_defaults=True)

    def number(value, kind: str) -> float:
        unit = model.units.length if kind == "length" else model.units.angle
        return to_si(value, kind, unit) / (length if kind == "length" else angle)

    for key, vector in model.vectors.items():
        out = data["vectors"][str(key)]
        r, al = vector.r, vector.a
        if isinstance(r, LinkRole):
            out["r"]["delta"] = number(r.delta, "length") * scale
        elif isinstance(r, int | float) or (isinstance(r, str) and r.strip() != "function"):
            out["r"] = number(r, "length") * scale
        if isinstance(al, ArgumentRole):
            out["a"]["offset"] = number(al.offset, "angle") + turn / angle
        elif isinstance(al, LinkRole) and al.ratio != 1:  # k(a + t) + d' = (k a + d) + t
            out["a"]["delta"] = number(al.delta, "angle") + (1 - al.ratio) * turn / angle
        elif isinstance(al, int | float) or (isinstance(al, str)
                                             and al.strip() != "function"):
            out["a"] = number(al, "angle") + turn / angle
    for i, contour in enumerate(model.contours):
        start = contour.start
        if isinstance(start, tuple | list):
            xy = complex(number(start[0], "length"), number(start[1], "length")) * length
            moved = (a * xy + b) / length
            data["contours"][i]["start"] = [moved.real, moved.imag]
        elif start == "origin" and b != 0:
            data["contours"][i]["start"] = [b.real / length, b.imag / length]
    return Model.model_validate(data)
