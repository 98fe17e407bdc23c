"""Starting designs from an atlas of normalized four-bar coupler curves.

The atlas holds ``ATLAS_SIZE`` crank-rockers (crank 1 and shortest, Grashof with a
margin, so the crank turns fully), frame pivot O at the origin and C at ``(g, 0)``,
coupler ``c``, rocker ``k`` and a coupler point ``c (px + i py)`` in the coupler's own
frame, assembly variant 1 of mechloop's four-bar contour (crank, coupler, rocker, frame
C→O).  Each curve, traced by a turn of the crank at ``SAMPLES`` angles, is described by
Fourier descriptors invariant to position, orientation, scale and starting point
(:func:`descriptors`: the curve resampled by arc length, its complex Fourier
coefficients ``Z_k`` divided by ``Z_1``, the start turned so that ``Z_{-1}/Z_1`` is real
and positive).  It is built once in a few seconds, vectorized, and cached on disk
(``platformdirs.user_cache_dir('mechloop')``, or the directory ``MECHLOOP_CACHE_DIR``
names; about 20 MB).

A query (:func:`atlas_starts`) describes the targets the same way (a point set as the
closed polygon through the points in order), takes the nearest curves in descriptor
space (:class:`scipy.spatial.cKDTree`, both starting-point normalizations), maps each
onto the targets by the similarity ``z ↦ a z + b`` (complex ``a``, ``b``) found in
closed form — first from the two curves' coefficients, then refined by a few rounds of
closest points and a closed-form least-squares similarity — and writes each mapped
mechanism as a design of the problem (lengths ×|a|, frame and coupler angles +arg a,
pivot O at b, with free timing each target's input the crank angle of its closest
curve point).  The designs are scored by the problem itself (one vectorized call) and
the best are the search's starting designs.

Where it applies: a path task whose targets are reached without prescribed timing
(free timing, or the distance to the traced curve), on a model whose tracing point is a
point of the coupler of a four-bar contour driven by argument 1 at its crank, with the
four-bar's dimensions, frame angle, pivot O and coupler point all design variables
(:func:`recognize`).  Elsewhere it is skipped with the reason.
"""

from __future__ import annotations

import math
import os
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from mechloop.model.dynamic import HeadPoint
from mechloop.model.schema import ArgumentRole, LinkRole, Model
from mechloop.model.structure import is_function
from mechloop.modules.planar import pl4_unit

Array = NDArray[np.float64]
Complex = NDArray[np.complex128]

#: Mechanisms in the atlas, crank angles per curve, harmonics of the descriptors.
ATLAS_SIZE = 100_000
SAMPLES = 64
HARMONICS = 6
#: Crank angles per turn when a matched curve is mapped onto the targets.
DENSE = 720
#: Version of the atlas's recipe (part of the cache file's name).
VERSION = 2


@dataclass(frozen=True)
class Atlas:
    """``params`` ``(M, 5)``: g, c, k, px, py of each normalized mechanism; ``features``
    ``(M, F)`` the descriptors of its coupler curve (the curves themselves are computed
    again when needed, :meth:`curves`, so the cache holds only these two arrays)."""

    params: Array
    features: Array

    @property
    def angles(self) -> Array:
        return np.linspace(0.0, 2 * np.pi, SAMPLES, endpoint=False)

    def curves(self, rows: NDArray[np.int64] | slice = slice(None)) -> Complex:
        """The coupler curves of mechanisms ``rows`` at the ``SAMPLES`` crank angles,
        ``(len(rows), SAMPLES)`` (x + iy)."""
        return coupler_curves(self.params[rows], self.angles)[0]


def coupler_curves(params: Array, angles: Array) -> tuple[Complex, NDArray[np.bool_]]:
    """Coupler curves of normalized four-bars ``params`` ``(M, 5)`` (g, c, k, px, py) at
    crank ``angles`` ``(S,)``: ``(M, S)`` points and whether each assembles.  Closed
    form: mechloop's Pl4 module (variant 1) on the loop crank + coupler + rocker +
    frame = 0."""
    g, c, k, px, py = (params[:, i : i + 1] for i in range(5))
    crank = np.exp(1j * angles)[None, :]
    known = crank - g  # crank + frame (C→O is -g)
    cos2, sin2, _, _, ok = pl4_unit(known.real, known.imag, c, k, variant=1)
    point = crank + c * (px + 1j * py) * (cos2 + 1j * sin2)
    return point, ok


def _sample(count: int, rng: np.random.Generator) -> Array:
    """Normalized crank-rockers: crank 1 shortest, longest + 1 <= the other two - 0.05."""
    out = np.empty((0, 5))
    while out.shape[0] < count:
        n = 2 * count
        g, c, k = (rng.uniform(1.2, 6.0, n) for _ in range(3))
        lengths = np.stack([g, c, k])
        ok = 1.0 + lengths.max(axis=0) <= lengths.sum(axis=0) - lengths.max(axis=0) - 0.05
        px = rng.uniform(-1.0, 2.0, n)
        py = rng.uniform(-1.5, 1.5, n)
        out = np.vstack([out, np.stack([g, c, k, px, py], axis=1)[ok]])
    return out[:count]


def resample(curves: Complex, count: int = SAMPLES) -> Complex:
    """Closed curves ``(M, S)`` resampled at ``count`` points equally spaced by arc length
    (vectorized: one interpolation over all rows)."""
    closed = np.concatenate([curves, curves[:, :1]], axis=1)
    seg = np.abs(np.diff(closed, axis=1))
    length = np.concatenate([np.zeros((curves.shape[0], 1)), np.cumsum(seg, axis=1)], axis=1)
    total = length[:, -1:]
    total = np.where(total > 0, total, 1.0)
    rel = length / total
    want = np.linspace(0.0, 1.0, count, endpoint=False)[None, :]
    rows = np.arange(curves.shape[0])[:, None]
    # per row, the segment of each wanted point: one searchsorted over rows offset by 2
    offset = 2.0 * rows
    idx = np.searchsorted((rel + offset).ravel(), (want + offset).ravel(), side="right")
    idx = idx.reshape(curves.shape[0], count) - 1 - rows * closed.shape[1]
    idx = np.clip(idx, 0, closed.shape[1] - 2)
    lo = np.take_along_axis(rel, idx, axis=1)
    hi = np.take_along_axis(rel, idx + 1, axis=1)
    frac = np.where(hi > lo, (want - lo) / np.where(hi > lo, hi - lo, 1.0), 0.0)
    z0 = np.take_along_axis(closed, idx, axis=1)
    z1 = np.take_along_axis(closed, idx + 1, axis=1)
    return z0 + frac * (z1 - z0)


def coefficients(curves: Complex) -> Complex:
    """Fourier coefficients ``(M, count)`` of closed curves resampled by arc length."""
    points = resample(curves)
    return np.fft.fft(points, axis=1) / points.shape[1]


def _normalized(coef: Complex, flip: bool = False) -> tuple[Complex, Array]:
    """Coefficients divided by Z_1 and turned to the start where Z_{-1}/Z_1 is real and
    positive (``flip``: the other such start, half a turn later); and the start shift
    ``t`` (a start moved by ``t`` multiplies Z_k by e^{ikt})."""
    n = coef.shape[1]
    ratio = coef[:, -1] / np.where(coef[:, 1] != 0, coef[:, 1], 1.0)
    shift = np.angle(ratio) / 2 + (np.pi if flip else 0.0)  # Z_k -> Z_k e^{ik t}
    ks = np.fft.fftfreq(n, 1.0 / n)
    turned = coef * np.exp(1j * ks[None, :] * shift[:, None])
    return turned / np.where(turned[:, 1:2] != 0, turned[:, 1:2], 1.0), shift


def descriptors(coef: Complex, flip: bool = False) -> Array:
    """Invariant descriptors ``(M, 4·HARMONICS - 2)``: real and imaginary parts of the
    normalized Z_k, k = -HARMONICS..HARMONICS except 0 and 1."""
    norm, _ = _normalized(coef, flip)
    keep = [k for k in range(-HARMONICS, HARMONICS + 1) if k not in (0, 1)]
    picked = norm[:, keep]
    return np.concatenate([picked.real, picked.imag], axis=1)


def build_atlas(count: int = ATLAS_SIZE, seed: int = 0) -> Atlas:
    """The atlas of ``count`` mechanisms (a few seconds, vectorized)."""
    rng = np.random.default_rng(seed)
    params = _sample(count, rng)
    angles = np.linspace(0.0, 2 * np.pi, SAMPLES, endpoint=False)
    curves, ok = coupler_curves(params, angles)
    good = ok.all(axis=1)
    params, curves = params[good], curves[good]
    return Atlas(params, descriptors(coefficients(curves)))


def cache_path() -> Path:
    import platformdirs

    root = Path(os.environ.get("MECHLOOP_CACHE_DIR") or platformdirs.user_cache_dir(
        "mechloop"))
    return root / f"fourbar_atlas_v{VERSION}_{ATLAS_SIZE}.npz"


_LOADED: dict[Path, Atlas] = {}


def load_atlas() -> Atlas:
    """The atlas: from memory, from the disk cache, or built and cached (an unwritable
    cache directory only means it is built again next time)."""
    path = cache_path()
    if path in _LOADED:
        return _LOADED[path]
    atlas = None
    if path.exists():
        try:
            with np.load(path) as data:
                atlas = Atlas(data["params"], data["features"])
        except (OSError, ValueError, KeyError):
            atlas = None
    if atlas is None:
        atlas = build_atlas()
        try:
            path.parent.mkdir(parents=True, exist_ok=True)
            tmp = path.with_suffix(f".{os.getpid()}.tmp.npz")
            np.savez(tmp, params=atlas.params, features=atlas.features)
            os.replace(tmp, path)
        except OSError:
            pass
    _LOADED[path] = atlas
    return atlas


# ---- recognizing a four-bar path problem -----------------------------------------------
@dataclass(frozen=True)
class FourBarMap:
    """Where the parts of a four-bar sit in a model: the vector numbers of the crank,
    coupler, rocker and frame, the four-bar contour's number, and the coupler point as
    ``(vector, delta kind)`` pairs: each vector's angle is the coupler angle plus its own
    delta."""

    contour: int
    crank: int
    coupler: int
    rocker: int
    frame: int
    point: tuple[int, ...]


def recognize(model: Model, problem) -> tuple[FourBarMap | None, str]:
    """The four-bar structure of a path problem, or None and why the atlas does not
    apply."""
    task = model.synthesis
    if problem.target_kind != "path":
        return None, "the atlas is for path targets"
    if problem.target_positions is not None and not problem.free_timing:
        return None, ("the timing is prescribed; the atlas matches the shape of the "
                      "targets, not their timing")
    found = fourbar_contour(model)
    if found is None:
        return None, ("no four-bar contour (crank driven by argument 1, coupler and rocker "
                      "angles unknown, a fixed frame, a fixed start, variant 1)")
    number, crank, coupler, rocker, frame = found
    return _recognize_point(model, problem, task, number, crank, coupler, rocker, frame)


def fourbar_contour(model: Model) -> tuple[int, int, int, int, int] | None:
    """The first four-bar contour of ``model``: ``(contour number, crank, coupler,
    rocker, frame)`` vector numbers — a contour of four vectors starting at a fixed
    point, the crank's angle driven by argument 1, the coupler's and rocker's angles its
    unknowns, a constant frame, assembly variant 1 — or None."""
    for index, contour in enumerate(model.contours):
        vs = list(contour.vectors)
        if len(vs) != 4 or not isinstance(contour.start, list | tuple):
            continue
        crank, coupler, rocker, frame = (model.vectors[v] for v in vs)
        if (isinstance(crank.a, ArgumentRole) and crank.a.argument == 1
                and not is_function(crank.r) and not isinstance(crank.r, LinkRole)
                and is_function(coupler.a) and is_function(rocker.a)
                and not is_function(coupler.r) and not is_function(rocker.r)
                and not isinstance(frame.a, ArgumentRole | LinkRole)
                and not is_function(frame.a) and not is_function(frame.r)
                and contour.variant == 1):
            return (index + 1, *vs)
    return None


def _recognize_point(model: Model, problem, task, number: int, crank: int, coupler: int,
                     rocker: int, frame: int) -> tuple[FourBarMap | None, str]:
    point = problem.point
    if not isinstance(point, HeadPoint):
        return None, "the tracing point is not the head of a coupler-point vector"
    # the coupler point: a contour starting at the crank's tail whose first vector copies
    # the crank and whose next vectors turn with the coupler, up to the tracing point
    path: list[int] = []
    for contour in model.contours:
        vs = list(contour.vectors)
        if point.head not in vs or len(vs) < 3:
            continue
        first = model.vectors[vs[0]]
        start = contour.start
        starts_at_crank = getattr(start, "tail", None) == crank
        copies = (isinstance(first.r, LinkRole) and first.r.link == f"r{crank}"
                  and isinstance(first.a, LinkRole) and first.a.link == f"a{crank}"
                  and first.r.ratio == 1 and first.a.ratio == 1)
        rest = vs[1: vs.index(point.head) + 1]
        turns = all(isinstance(model.vectors[v].a, LinkRole)
                    and model.vectors[v].a.link == f"a{coupler}"
                    and model.vectors[v].a.ratio == 1
                    and not is_function(model.vectors[v].r)
                    and not isinstance(model.vectors[v].r, LinkRole | ArgumentRole)
                    for v in rest)
        if starts_at_crank and copies and rest and turns and len(rest) <= 2:
            path = rest
            break
    if not path:
        return None, ("the tracing point is not a point of the coupler (a contour from the "
                      "crank's tail copying the crank, then one or two vectors turning "
                      "with the coupler)")
    need = {f"r{crank}", f"r{coupler}", f"r{rocker}", f"r{frame}", f"a{frame}",
            f"start{number}.x", f"start{number}.y"}
    if len(path) == 1:
        need |= {f"r{path[0]}", f"a{path[0]}"}
    else:
        need |= {f"r{path[0]}", f"r{path[1]}"}
    names = set(problem.variables.names)
    missing = sorted(need - names)
    if missing or task.dimensions:
        what = ", ".join(missing) if missing else "they are set through dimensions"
        return None, ("the four-bar's dimensions, frame angle, pivot and coupler point are "
                      f"not all plain design variables ({what})")
    if len(path) == 2:  # two vectors: along and normal to the coupler (deltas 0 and 90°)
        deltas = [model.vectors[v].a.delta for v in path]
        if any(isinstance(d, str) for d in deltas) or not (
                math.isclose(float(deltas[0]), 0.0, abs_tol=1e-12)
                and math.isclose(float(deltas[1]) * _angle_factor(model), math.pi / 2,
                                 rel_tol=1e-12)):
            return None, "the coupler point's two vectors are not along and normal to it"
    return FourBarMap(number, crank, coupler, rocker, frame, tuple(path)), ""


def _angle_factor(model: Model) -> float:
    from mechloop.model.units import unit_factor

    return unit_factor(model.units.angle, "angle")


# ---- matching and mapping ---------------------------------------------------------------
def _similarity(src: Complex, dst: Complex) -> tuple[Complex, Complex]:
    """Closed-form least-squares similarity ``dst ≈ a src + b`` per row ``(M, K)``."""
    ms, md = src.mean(axis=1, keepdims=True), dst.mean(axis=1, keepdims=True)
    s, d = src - ms, dst - md
    den = np.sum(np.abs(s) ** 2, axis=1, keepdims=True)
    a = np.sum(np.conj(s) * d, axis=1, keepdims=True) / np.where(den > 0, den, 1.0)
    return a, md - a * ms


def match(atlas: Atlas, targets: Complex, count: int = 200, rounds: int = 6
          ) -> tuple[NDArray[np.int64], Complex, Complex, NDArray[np.int64]]:
    """The ``count`` atlas curves nearest to the targets (a point set, as the closed
    polygon through them) with their similarities onto the targets: ``(rows, a, b,
    nearest)``, ``a``, ``b`` ``(count,)``, ``nearest`` ``(count, K)`` the crank angle
    (rad, of ``DENSE`` per turn) of the curve point closest to each target after the
    mapping."""
    from scipy.spatial import cKDTree

    coef = coefficients(targets[None, :])
    tree = cKDTree(atlas.features)
    rows_list, ab = [], []
    for flip in (False, True):
        _, rows = tree.query(descriptors(coef, flip)[0], k=count // 2)
        rows_list.append(np.atleast_1d(rows))
        # a from the first harmonics: Z1_target (turned) = a Z1_atlas (both turned)
        _, shift_t = _normalized(coef, flip)
        ab.append(shift_t[0])
    rows = np.concatenate(rows_list)
    curves = atlas.curves(rows)
    # initial similarity: the coefficients (start normalized) of both curves
    ccoef = coefficients(curves)
    a0, b0 = [], []
    for half in range(2):
        part = slice(half * (count // 2), (half + 1) * (count // 2))
        n = ccoef.shape[1]
        ks = np.fft.fftfreq(n, 1.0 / n)
        _, shift_c = _normalized(ccoef[part])
        ct = ccoef[part] * np.exp(1j * ks[None, :] * shift_c[:, None])
        tt = coef[0] * np.exp(1j * ks * ab[half])
        a0.append(tt[1] / ct[:, 1])
        b0.append(tt[0] - (tt[1] / ct[:, 1]) * ct[:, 0])
    a = np.concatenate(a0)[:, None]
    b = np.concatenate(b0)[:, None]
    dense_angles = np.linspace(0.0, 2 * np.pi, DENSE, endpoint=False)
    dense, _ = coupler_curves(atlas.params[rows], dense_angles)
    nearest = np.zeros((rows.size, targets.size), dtype=np.int64)
    for _ in range(rounds):  # closest points, then the closed-form similarity
        mapped = a * dense + b
        dist = np.abs(mapped[:, None, :] - targets[None, :, None])
        nearest = np.argmin(dist, axis=2)
        src = np.take_along_axis(dense, nearest, axis=1)
        a, b = _similarity(src, np.broadcast_to(targets, src.shape))
    return rows, a[:, 0], b[:, 0], dense_angles[nearest]


def atlas_starts(problem, count: int = 20) -> tuple[Array | None, str]:
    """Starting designs ``(S, V)`` (SI, within the bounds) from the atlas for a four-bar
    path problem, best first by the problem's own total; or None and why not."""
    fourbar, reason = recognize(problem.model, problem)
    if fourbar is None:
        return None, reason
    atlas = load_atlas()
    targets = problem.targets
    rows, a, b, nearest = match(atlas, targets)
    params = atlas.params[rows]
    g, c, k, px, py = params.T
    scale, turn = np.abs(a), np.angle(a)
    v = problem.variables
    model = problem.model
    names = list(v.names)
    designs = np.tile(0.5 * (v.low + v.high), (rows.size, 1))

    def put(name: str, value: Array) -> None:
        designs[:, names.index(name)] = value

    put(f"r{fourbar.crank}", scale)
    put(f"r{fourbar.coupler}", scale * c)
    put(f"r{fourbar.rocker}", scale * k)
    put(f"r{fourbar.frame}", scale * g)
    put(f"a{fourbar.frame}", np.pi + turn)
    put(f"start{fourbar.contour}.x", b.real)
    put(f"start{fourbar.contour}.y", b.imag)
    if len(fourbar.point) == 1:
        p = fourbar.point[0]
        put(f"r{p}", scale * c * np.hypot(px, py))
        put(f"a{p}", np.arctan2(py, px))
    else:
        put(f"r{fourbar.point[0]}", scale * c * px)
        put(f"r{fourbar.point[1]}", scale * c * py)
    crank_offset = model.vectors[fourbar.crank].a.offset
    from mechloop.model.units import to_si

    offset = to_si(crank_offset, "angle", model.units.angle)
    if problem.free_timing:
        theta = nearest + turn[:, None] - offset
        designs[:, v.input_columns] = theta
    # angles into their bounds modulo the turn, then everything clipped to the box
    for i in range(len(v)):
        if v.kind(i) == "angle":
            designs[:, i] = v.low[i] + np.mod(designs[:, i] - v.low[i], 2 * np.pi)
    inside = np.all((designs >= v.low) & (designs <= v.high), axis=1)
    designs = np.clip(designs, v.low, v.high)
    total = problem.evaluate(designs).total
    total = np.where(inside, total, total + 1e6)  # a clipped mapping is a worse start
    order = np.argsort(total)[:count]
    return designs[order], ""


__all__ = ["ATLAS_SIZE", "Atlas", "atlas_starts", "build_atlas", "descriptors",
           "load_atlas", "match", "recognize"]
