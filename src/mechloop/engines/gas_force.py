"""The gas force on a piston over the positions of a mechanism, from the piston's solved
position (so that an offset cylinder, or each cylinder of a V engine, gets its own dead
centres and stroke).

Inputs are the crank's angle ``φ`` (rad), the parameter ``x`` that places the piston (m:
e.g. the length of the cylinder's vector) and its analog ``dx/dφ`` (m/rad), each shape
``(..., P)``: positions last, designs (or cylinders) leading.  ``head`` says which way the
cylinder head lies: +1 when ``x`` is largest at top dead centre, −1 when smallest.

* **Dead centres and stroke.** The extremes of ``x`` over the positions, read between them
  from the cubic Hermite interpolant of ``x`` and ``dx/dφ`` (exact for a cubic, error
  O(h⁴) otherwise), give top and bottom dead centre; the stroke ``S`` is their distance
  and the swept volume ``V_h = A·S`` (``A = π·D²/4``).  The cylinder volume is
  ``V = V_c + A·|x_TDC − x|``.
* **Which stroke.**  The piston moves away from the head where ``head·dx/dφ < 0``, towards
  it where ``> 0``; at a dead centre itself (``dx/dφ`` zero to 1e-9 of its largest
  value) the stroke that starts there counts.  A four-stroke cycle (two turns) tells its
  expansion from its intake, and its exhaust from its compression, by the crank's angle
  after the firing dead centre ``ψ = φ − firing`` (mod 4π): expansion and exhaust in
  the first turn, intake and compression in the second — each stroke is taken as the one
  whose nominal half-turn (expansion ψ in [0, π), exhaust [π, 2π), ...) is nearest, so
  ``firing`` and the true dead centres may differ by up to a quarter turn.
* **Force.** ``F = (p − p₀)·A``, ``p₀`` the pressure under the piston (crankcase); positive
  ``F`` pushes the piston away from the head.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

from mechloop.engines.cycle import CompressorCycle, EngineCycle
from mechloop.engines.diagram import clearance_volume, pressure
from mechloop.errors import HintedError

Array = NDArray[np.float64]
TWO_PI = 2.0 * np.pi


def _hermite_extremes(phi: Array, x: Array, dx: Array) -> tuple[Array, Array]:
    """Largest and smallest value, shape (...,), of the piecewise cubic Hermite
    interpolant through ``(phi, x, dx)`` (positions last), NaN rows left out."""
    h = np.diff(phi, axis=-1)
    p0, p1 = x[..., :-1], x[..., 1:]
    m0, m1 = dx[..., :-1] * h, dx[..., 1:] * h
    # H'(t) = a t² + b t + c on t in [0, 1]
    a = 6 * p0 + 3 * m0 - 6 * p1 + 3 * m1
    b = -6 * p0 - 4 * m0 + 6 * p1 - 2 * m1
    c = m0
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        disc = np.sqrt(np.maximum(b * b - 4 * a * c, 0.0))
        q = -0.5 * (b + np.where(b >= 0, disc, -disc))
        roots = [q / a, c / q]
    candidates = [x]
    for t in roots:
        t = np.clip(np.nan_to_num(t, nan=0.0, posinf=0.0, neginf=0.0), 0.0, 1.0)
        value = ((2 * t**3 - 3 * t**2 + 1) * p0 + (t**3 - 2 * t**2 + t) * m0
                 + (-2 * t**3 + 3 * t**2) * p1 + (t**3 - t**2) * m1)
        candidates.append(value)
    # fmax/fmin leave NaN (positions where the chain breaks) out without a warning; a
    # row of NaN only gives NaN
    top = np.fmax.reduce([np.fmax.reduce(v, axis=-1) for v in candidates], axis=0)
    bottom = np.fmin.reduce([np.fmin.reduce(v, axis=-1) for v in candidates], axis=0)
    return top, bottom


def _hermite_pieces(phi: Array, x: Array, dx: Array):
    """``(h, p0, p1, m0, m1)`` of the cubic Hermite pieces between the positions."""
    h = np.diff(phi, axis=-1)
    return h, x[..., :-1], x[..., 1:], dx[..., :-1] * h, dx[..., 1:] * h


def _hermite_at(t: Array, p0, p1, m0, m1) -> Array:
    return ((2 * t**3 - 3 * t**2 + 1) * p0 + (t**3 - 2 * t**2 + t) * m0
            + (-2 * t**3 + 3 * t**2) * p1 + (t**3 - t**2) * m1)


def port_share(phi: ArrayLike, x: ArrayLike, dx: ArrayLike, opens: float, *,
               head: int = 1) -> Array:
    """The share of the stroke above bottom dead centre that a two-stroke's exhaust port
    takes, shape (...,), when it opens ``opens`` (rad, 0 < opens < π) after top dead
    centre: the piston's position there, read from the cubic Hermite interpolant of
    ``x`` and ``dx/dφ`` (top dead centre located on it, the angle taken a turn back when
    it falls beyond the last position)."""
    if not 0 < opens < np.pi:
        raise HintedError(f"the exhaust port opens {np.degrees(opens):.6g} deg after top "
                          "dead centre", "give an angle between 0 and 180 deg (typical: "
                          "100 to 120)")
    phi, x, dx = (np.asarray(v, dtype=float) for v in (phi, x, dx))
    top, bottom = piston_extremes(phi, x, dx)
    h, p0, p1, m0, m1 = _hermite_pieces(phi, x, dx)
    # the head's extreme: the best of the pieces' ends and inner stationary points
    a = 6 * p0 + 3 * m0 - 6 * p1 + 3 * m1
    b = -6 * p0 - 4 * m0 + 6 * p1 - 2 * m1
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        disc = np.sqrt(np.maximum(b * b - 4 * a * m0, 0.0))
        q = -0.5 * (b + np.where(b >= 0, disc, -disc))
        ts = [np.zeros_like(h), np.ones_like(h), q / a, m0 / q]
    ts = [np.clip(np.nan_to_num(t, nan=0.0, posinf=0.0, neginf=0.0), 0.0, 1.0) for t in ts]
    lead = h.shape[:-1]
    values = np.stack([head * _hermite_at(t, p0, p1, m0, m1) for t in ts], axis=-1)
    values = np.nan_to_num(values, nan=-np.inf).reshape(*lead, -1)  # (..., (P-1)·4)
    best = np.argmax(values, axis=-1)[..., None]
    t_top = np.take_along_axis(np.stack(ts, axis=-1).reshape(*lead, -1), best, axis=-1)
    piece = best // len(ts)
    phi_top = (np.take_along_axis(phi[..., :-1], piece, axis=-1)
               + t_top * np.take_along_axis(h, piece, axis=-1))[..., 0]
    target = phi_top + opens
    end = phi[..., -1]
    target = np.where(target > end, target - TWO_PI, target)
    k = np.clip(np.sum(phi <= target[..., None], axis=-1) - 1, 0, h.shape[-1] - 1)[..., None]
    hk = np.take_along_axis(h, k, axis=-1)[..., 0]
    t = (target - np.take_along_axis(phi, k, axis=-1)[..., 0]) / hk
    x_port = _hermite_at(t, *(np.take_along_axis(v, k, axis=-1)[..., 0]
                              for v in (p0, p1, m0, m1)))
    return (x_port - bottom) / (top - bottom) if head > 0 else (top - x_port) / (top - bottom)


def piston_extremes(phi: ArrayLike, x: ArrayLike, dx: ArrayLike) -> tuple[Array, Array]:
    """The largest and the smallest value of the piston's parameter over the positions
    (m), shape (...,): at the samples or between them (cubic Hermite interpolant of ``x``
    and ``dx/dφ`` over ``φ``).  Raises :class:`~mechloop.errors.HintedError` when ``φ``
    does not cover a whole turn (the piston may not reach both dead centres)."""
    phi, x, dx = (np.asarray(v, dtype=float) for v in (phi, x, dx))
    span = np.nanmax(phi, axis=-1) - np.nanmin(phi, axis=-1)
    if not np.all(span >= TWO_PI * (1 - 1e-9)):
        raise HintedError("the gas force needs the piston's whole stroke, but the crank "
                          f"turns by {np.degrees(np.min(span)):.6g} deg over the positions",
                          "let the crank's argument cover at least a whole turn")
    if not np.all(np.diff(phi, axis=-1) > 0):
        raise HintedError("the gas force needs the crank's angle to grow from position to "
                          "position", "give the crank's argument increasing values")
    return _hermite_extremes(phi, x, dx)


def stroke_of(cycle: EngineCycle | CompressorCycle, phi: ArrayLike, x: ArrayLike,
              dx: ArrayLike, top: ArrayLike, bottom: ArrayLike, *, head: int = 1,
              firing: float = 0.0) -> NDArray[np.int64]:
    """The stroke (an index into :func:`~mechloop.engines.diagram.stroke_names`) at each
    position, shape (..., P); ``top``/``bottom`` the largest and smallest ``x`` (...,),
    ``firing`` the crank's angle at the firing dead centre of a four-stroke (rad)."""
    phi, x, dx = (np.asarray(v, dtype=float) for v in (phi, x, dx))
    top, bottom = np.asarray(top, dtype=float)[..., None], np.asarray(bottom, dtype=float)[
        ..., None]
    head_x = top if head > 0 else bottom
    tol = 1e-9 * np.fmax.reduce(np.abs(dx), axis=-1, keepdims=True)
    moving = head * dx
    at_head = np.abs(x - head_x) < 0.5 * (top - bottom)
    # away from the head (True) or towards it; at a dead centre: the stroke that starts
    with np.errstate(invalid="ignore"):  # NaN where the chain breaks: any stroke
        away = np.where(np.abs(dx) <= tol, at_head, moving < 0)
    if isinstance(cycle, CompressorCycle) or cycle.strokes == 2:
        return np.where(away, 0, 1).astype(np.int64)
    psi = np.mod(phi - firing, 2 * TWO_PI)
    first_half = np.where(away, np.mod(psi + np.pi / 2, 2 * TWO_PI) < TWO_PI,
                          np.mod(psi - np.pi / 2, 2 * TWO_PI) < TWO_PI)
    return np.select([away & first_half, ~away & first_half, away], [0, 1, 2], 3).astype(
        np.int64)


@dataclass(frozen=True)
class GasForce:
    """The gas force over positions.

    Attributes
    ----------
    volume : array (..., P), m³ — the cylinder volume ``V_c + A·|x_TDC − x|``.
    pressure : array (..., P), Pa — the gas pressure from the diagram.
    force : array (..., P), N — ``(p − p₀)·A``, positive away from the head.
    stroke : int array (..., P) — the stroke at each position.
    swept : array (...,), m³ — ``V_h = A·S``; ``clearance``: ``V_c`` (m³);
    top, bottom : array (...,), m — ``x`` at top and bottom dead centre.
    area : float, m² — the piston's area.
    """

    volume: Array
    pressure: Array
    force: Array
    stroke: NDArray[np.int64]
    swept: Array
    clearance: Array
    top: Array
    bottom: Array
    area: float


def gas_force(cycle: EngineCycle | CompressorCycle, phi: ArrayLike, x: ArrayLike,
              dx: ArrayLike, *, bore: float, crankcase: float, head: int = 1,
              firing: float = 0.0) -> GasForce:
    """The gas force on the piston at every position (see the module's text).

    Parameters
    ----------
    cycle : the engine's or compressor's cycle.
    phi : array (..., P), rad — the crank's angle, increasing over at least a turn.
    x, dx : arrays (..., P) — the piston's parameter (m) and ``dx/dφ`` (m/rad).
    bore : float, m; crankcase : float, Pa — the pressure under the piston.
    head : +1 (``x`` largest at top dead centre) or −1; firing : float, rad — the crank's
        angle at the firing dead centre (four-stroke).
    """
    if head not in (1, -1):
        raise HintedError(f"head is +1 or -1, got {head!r}", "+1: x is largest at top "
                          "dead centre")
    if not bore > 0:
        raise HintedError(f"the bore must be positive, got {bore!r}", "give the cylinder's "
                          "diameter")
    phi, x, dx = (np.asarray(v, dtype=float) for v in (phi, x, dx))
    if isinstance(cycle, EngineCycle) and cycle.strokes == 4:
        span = np.max(phi, axis=-1) - np.min(phi, axis=-1)
        if np.any(span < 2 * TWO_PI * (1 - 1e-9)):
            raise HintedError("a four-stroke cycle takes two turns of the crank, but its "
                              f"angle spans {np.degrees(np.min(span)):.6g} deg over the "
                              "positions", "let the crank's argument cover 720 deg (and "
                              "time: {rpm: ..., turns: 2})")
    top, bottom = piston_extremes(phi, x, dx)
    area = np.pi * bore * bore / 4.0
    swept = area * (top - bottom)
    if np.any(swept <= 0):  # NaN: a design whose chain breaks everywhere
        raise HintedError("the piston does not move: its stroke is zero",
                          "name the parameter that places the piston (piston: rK)")
    head_x = top if head > 0 else bottom
    vc = clearance_volume(cycle, 1.0) * swept
    volume = vc[..., None] + area * np.abs(head_x[..., None] - x)
    stroke = stroke_of(cycle, phi, x, dx, top, bottom, head=head, firing=firing)
    p = pressure(cycle, volume / swept[..., None], stroke, 1.0)
    return GasForce(volume, p, (p - crankcase) * area, stroke, swept, vc, top, bottom, area)
