"""Classical closed-form synthesis of four-bars and slider-cranks — starting points.

Textbook constructions, each a pure function over NumPy arrays returning a small frozen
dataclass, meant as starting designs for optimization synthesis:

* **function generation** with Freudenstein's equation, exact at three precision points
  (:func:`freudenstein_three_point`) or in the least-squares sense at more
  (:func:`freudenstein_least_squares`); precision points by Chebyshev spacing
  (:func:`chebyshev_points`) and the linear maps ``x → φ``, ``y → ψ``
  (:func:`function_generator_points`);
* **three-position rigid-body guidance**: the fixed pivots from chosen moving pivots
  (:func:`three_position_fixed_pivots`) or, by inversion, the moving pivots from chosen
  fixed pivots (:func:`three_position_moving_pivots`);
* an **offset slider-crank** with a given stroke and time ratio
  (:func:`slider_crank_from_stroke`);
* a **crank-rocker** with a given rocker swing and time ratio
  (:func:`crank_rocker_from_swing`).

Conventions
-----------
Lengths are in any one consistent unit (SI metres at the edges of mechloop), angles in
radians, counter-clockwise positive.  A four-bar has the crank pivot ``O2`` at the origin
and the rocker pivot ``O4`` at ``(d, 0)``: ``a`` crank ``O2A``, ``b`` coupler ``AB``, ``c``
rocker ``O4B``, ``d`` frame.  The crank angle φ (of ``O2→A``) and the rocker angle ψ (of
``O4→B``) are measured from the frame line ``O2→O4``.  The time ratio (coefficient of the
change of average velocity) is ``K = (π + θ)/(π − θ)``, i.e. ``θ = π (K − 1)/(K + 1)``:
the crank turns ``π + θ`` during the slow stroke and ``π − θ`` during the fast one.  The
*excess angle* θ is the angle under which the crank pivot sees the two extreme positions
of the output point (the crank is in line with the rod or coupler at both).

Shapes: the arguments broadcast over leading design axes ``(...)``; trailing axes hold the
precision points or poses (``N``, ``3``) and coordinates (``2``).  Every field of a result
carries the broadcast design shape ``(...)`` first.

Failures
--------
Data with no real mechanism raise :class:`~mechloop.errors.SolveError` saying why and what
to change (``errors="raise"``, the default).  With ``errors="mask"`` nothing is raised:
the failing designs are NaN in every float field, ``ok`` is false there and ``reason``
(an object array of ``str``) says why — for sweeps over a free parameter.  Malformed
arguments (wrong shapes, unknown options, a missing free parameter) raise ``ValueError``.

References
----------
* F. Freudenstein, "Approximate synthesis of four-bar linkages", Trans. ASME 77 (1955)
  853–861 — the displacement equation used for function generation.
* R. L. Norton, *Design of Machinery*: ch. 3, graphical linkage synthesis (three
  positions with specified moving or fixed pivots; quick-return mechanisms); ch. 4, the
  four-bar position equation with ``K1, K2, K3``; ch. 5, analytical synthesis (precision
  points, Chebyshev spacing).
* A. G. Erdman, G. N. Sandor, *Mechanism Design* (vol. 1) and *Advanced Mechanism Design*
  (vol. 2) — three-position guidance and inversion; function generation, least squares.
* R. S. Hartenberg, J. Denavit, *Kinematic Synthesis of Linkages* (1964) — precision-point
  spacing.
* I. I. Artobolevsky, *Theory of Mechanisms and Machines* — synthesis of the crank-rocker
  and slider-crank from the extreme positions and the time ratio.
* J. J. Uicker, G. R. Pennock, J. E. Shigley, *Theory of Machines and Mechanisms*, ch.
  "Synthesis of linkages" (Freudenstein's equation, Chebyshev spacing, quick-return).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Literal

import numpy as np
from numpy.typing import ArrayLike, NDArray

from mechloop.errors import SolveError

Array = NDArray[np.float64]
Errors = Literal["raise", "mask"]

#: Relative sine of the triangle angle below which three points count as collinear.
COLLINEAR_SINE = 1e-10
#: Relative distance below which two points count as one.
COINCIDENT_RTOL = 1e-12
#: 2-norm condition number above which Freudenstein's linear system counts as singular.
SINGULAR_CONDITION = 1e12
#: Relative slack on the closed ranges of the free parameters (round-off at the ends).
RANGE_RTOL = 1e-12


# --------------------------------------------------------------------------------------
# failures: raise or mask, with one reason per design
# --------------------------------------------------------------------------------------


Hint = str | Callable[[tuple[int, ...]], str]


class _Failures:
    """Per-design failure record: the first reason found for a design wins."""

    def __init__(self, shape: tuple[int, ...]):
        self.shape = shape
        self.ok = np.ones(shape, dtype=bool)
        self.reason = np.full(shape, "", dtype=object)
        self._hints: dict[str, Hint] = {}

    def add(self, bad: ArrayLike, message: str, hint: Hint = "") -> None:
        bad = np.broadcast_to(np.asarray(bad, dtype=bool), self.shape) & self.ok
        if not bad.any():
            return
        self.reason[bad] = message
        self.ok = self.ok & ~bad
        self._hints.setdefault(message, hint)

    def settle(self, errors: Errors) -> None:
        if errors == "mask" or self.ok.all():
            return
        index = tuple(int(i) for i in np.argwhere(~self.ok)[0])
        message = str(self.reason[index])
        hint = self._hints[message]
        hint_text = hint(index) if callable(hint) else hint
        if self.shape:
            n_bad, n = int((~self.ok).sum()), self.ok.size
            message = f"design {index} ({n_bad} of {n} fail): {message}"
        raise SolveError(message, hint_text)


def _check_errors(errors: str) -> None:
    if errors not in ("raise", "mask"):
        raise ValueError(f"errors must be 'raise' or 'mask', got {errors!r}")


def _masked(ok: NDArray[np.bool_], a: ArrayLike) -> Array:
    """``a`` (shape ``ok.shape + trailing``) with NaN where ``ok`` is false."""
    a = np.asarray(a, dtype=float)
    if ok.all():
        return a
    ok = ok.reshape(ok.shape + (1,) * (a.ndim - ok.ndim))
    return np.where(ok, a, np.nan)


def _cross(u: Array, v: Array) -> Array:
    return u[..., 0] * v[..., 1] - u[..., 1] * v[..., 0]


def _angle_in(u: Array, v: Array) -> Array:
    """Angle of vector ``v`` in the frame whose x axis is the unit vector ``u``."""
    return np.arctan2(_cross(u, v), np.sum(u * v, axis=-1))


def _sign(x: Array) -> NDArray[np.int8]:
    return np.sign(np.nan_to_num(x)).astype(np.int8)


def excess_angle(time_ratio: ArrayLike) -> Array:
    """Excess angle θ of a time ratio: ``θ = π (K − 1)/(K + 1)``.

    Parameters
    ----------
    time_ratio : array, shape (...) — ``K ≥ 1``, dimensionless.

    Returns
    -------
    theta : array, shape (...), rad — the crank turns ``π + θ`` during the slow stroke and
    ``π − θ`` during the fast one, so that ``K = (π + θ)/(π − θ)``.

    >>> round(float(np.degrees(excess_angle(1.4))), 6)
    30.0
    """
    k = np.asarray(time_ratio, dtype=float)
    return np.pi * (k - 1.0) / (k + 1.0)


# --------------------------------------------------------------------------------------
# function generation: Freudenstein's equation
# --------------------------------------------------------------------------------------


@dataclass(frozen=True, eq=False)
class FunctionGenerator:
    """A four-bar function generator from Freudenstein's equation.

    Attributes
    ----------
    a, b, c, d : array, shape (...), length — crank, coupler, rocker, frame (all ≥ 0).
    k : array, shape (..., 3) — ``K1 = d/a, K2 = d/c, K3 = (a² − b² + c² + d²)/(2ac)``
        with the *signed* lengths of the solution.
    crank_phase, rocker_phase : array, shape (...), rad — 0 or π.  A negative signed
        length is reported as its absolute value with the link turned by π: the physical
        crank angle is ``phi + crank_phase`` and the physical rocker angle
        ``psi + rocker_phase``.
    phi, psi : array, shape (..., N), rad — the precision points used.
    residual : array, shape (..., N) — ``K1 cos ψ − K2 cos φ + K3 − cos(φ − ψ)`` at the
        precision points (zero to round-off for three points).
    branch : int8 array, shape (..., N) — assembly branch at each precision point: the
        sign of ``(O4 − A) × (B − A)`` (+1: ``B`` left of the line ``A→O4``; 0: toggle).
    ok : bool array, shape (...) — false where no real four-bar exists (``errors="mask"``).
    reason : object array of str, shape (...) — why, where ``ok`` is false.
    """

    a: Array
    b: Array
    c: Array
    d: Array
    k: Array
    crank_phase: Array
    rocker_phase: Array
    phi: Array
    psi: Array
    residual: Array
    branch: NDArray[np.int8]
    ok: NDArray[np.bool_]
    reason: NDArray[np.object_]

    @property
    def branch_defect(self) -> NDArray[np.bool_]:
        """True where the precision points lie on different assembly branches.

        The linkage then cannot move through all of them without being taken apart.  Equal
        branches are necessary, not sufficient: a non-Grashof linkage may still meet a
        toggle between two precision points.
        """
        return np.any(self.branch != self.branch[..., :1], axis=-1)


def chebyshev_points(x0: ArrayLike, x1: ArrayLike, n: int) -> Array:
    """Chebyshev spacing of ``n`` precision points on ``[x0, x1]``.

    ``x_j = (x0 + x1)/2 − (x1 − x0)/2 · cos((2j − 1) π / (2n))``, ``j = 1 … n`` — the
    roots of the Chebyshev polynomial ``T_n`` mapped onto the interval, which roughly
    equalizes the structural error between and beyond the precision points (Norton,
    *Design of Machinery*, ch. 5; Hartenberg & Denavit, *Kinematic Synthesis of
    Linkages*, 1964).

    Parameters
    ----------
    x0, x1 : array, shape (...) — ends of the range of the independent variable.
    n : int ≥ 1 — number of precision points.

    Returns
    -------
    x : array, shape (..., n) — ascending when ``x1 > x0``.

    >>> np.round(chebyshev_points(1.0, 10.0, 3), 6)
    array([1.602886, 5.5     , 9.397114])
    """
    if int(n) != n or n < 1:
        raise ValueError(f"n must be a positive integer, got {n!r}")
    x0 = np.asarray(x0, dtype=float)[..., None]
    x1 = np.asarray(x1, dtype=float)[..., None]
    j = np.arange(1, int(n) + 1)
    return 0.5 * (x0 + x1) - 0.5 * (x1 - x0) * np.cos((2 * j - 1) * np.pi / (2 * int(n)))


def function_generator_points(
    f: Callable[[Array], ArrayLike],
    x0: ArrayLike,
    x1: ArrayLike,
    phi0: ArrayLike,
    dphi: ArrayLike,
    psi0: ArrayLike,
    dpsi: ArrayLike,
    *,
    n: int = 3,
    spacing: Literal["chebyshev", "uniform"] = "chebyshev",
) -> tuple[Array, Array]:
    """Precision points ``(φ_i, ψ_i)`` of a four-bar generating ``y = f(x)`` on ``[x0, x1]``.

    The input crank angle and the output rocker angle are linear in ``x`` and ``y``::

        φ = φ0 + Δφ (x − x0)/(x1 − x0),      ψ = ψ0 + Δψ (y − y0)/(y1 − y0),

    with ``y0 = f(x0)``, ``y1 = f(x1)`` (Norton, *Design of Machinery*, ch. 5; Uicker,
    Pennock & Shigley, *Theory of Machines and Mechanisms*, "function generation").

    Parameters
    ----------
    f : callable — vectorized ``y = f(x)`` (any units; only ratios enter).
    x0, x1 : array, shape (...) — range of ``x``, ``x1 ≠ x0``.
    phi0, dphi : array, shape (...), rad — crank angle at ``x0`` and crank range.
    psi0, dpsi : array, shape (...), rad — rocker angle at ``x0`` and rocker range; a
        negative ``dpsi`` turns the rocker clockwise as ``y`` grows.
    n : int, keyword, default 3 — number of precision points.
    spacing : {"chebyshev", "uniform"}, keyword, default "chebyshev" — Chebyshev spacing
        (:func:`chebyshev_points`) or ``n`` evenly spaced points including both ends.

    Returns
    -------
    phi, psi : array, shape (..., n), rad.

    Raises
    ------
    SolveError
        If ``x1 = x0`` or ``f(x1) = f(x0)`` (the map to the angles is undefined).

    >>> phi, psi = function_generator_points(np.log10, 1.0, 10.0, np.radians(30.0),
    ...                                      np.radians(60.0), np.radians(-60.0),
    ...                                      np.radians(-90.0))
    >>> np.round(np.degrees(phi), 4)
    array([34.0192, 60.    , 85.9808])
    >>> np.round(np.degrees(psi), 4)
    array([ -78.4412, -126.6326, -147.5695])
    """
    if spacing == "chebyshev":
        x = chebyshev_points(x0, x1, n)
    elif spacing == "uniform":
        if int(n) != n or n < 1:
            raise ValueError(f"n must be a positive integer, got {n!r}")
        t = np.linspace(0.0, 1.0, int(n))
        x = np.asarray(x0, float)[..., None] + np.subtract(x1, x0, dtype=float)[..., None] * t
    else:
        raise ValueError(f"spacing must be 'chebyshev' or 'uniform', got {spacing!r}")
    x0 = np.asarray(x0, dtype=float)[..., None]
    x1 = np.asarray(x1, dtype=float)[..., None]
    y = np.asarray(f(x), dtype=float)
    y0 = np.asarray(f(x0), dtype=float)
    y1 = np.asarray(f(x1), dtype=float)
    if np.any(x1 == x0):
        raise SolveError("x1 = x0: the input range is empty", "give x0 ≠ x1")
    if np.any(y1 == y0):
        raise SolveError(
            "f(x1) = f(x0): the output range is empty, so ψ cannot be mapped from y",
            "choose a range [x0, x1] over which f changes",
        )
    phi = np.asarray(phi0, float)[..., None] + np.asarray(dphi, float)[..., None] * (
        (x - x0) / (x1 - x0)
    )
    psi = np.asarray(psi0, float)[..., None] + np.asarray(dpsi, float)[..., None] * (
        (y - y0) / (y1 - y0)
    )
    return phi, psi


def _freudenstein(
    phi: ArrayLike, psi: ArrayLike, frame: ArrayLike, errors: Errors, *, exact: bool
) -> FunctionGenerator:
    _check_errors(errors)
    phi, psi = np.broadcast_arrays(np.asarray(phi, dtype=float), np.asarray(psi, dtype=float))
    if phi.ndim == 0:
        raise ValueError("phi and psi need a last axis of precision points")
    n = phi.shape[-1]
    if exact and n != 3:
        raise ValueError(f"three-point synthesis needs exactly 3 precision points, got {n}")
    if not exact and n < 3:
        raise ValueError(f"least-squares synthesis needs at least 3 precision points, got {n}")
    d = np.asarray(frame, dtype=float)
    shape = np.broadcast_shapes(phi.shape[:-1], d.shape)
    phi = np.broadcast_to(phi, (*shape, n))
    psi = np.broadcast_to(psi, (*shape, n))
    d = np.broadcast_to(d, shape)

    fail = _Failures(shape)
    finite = np.all(np.isfinite(phi) & np.isfinite(psi), axis=-1) & np.isfinite(d)
    fail.add(~finite, "the precision points or the frame length are not finite numbers")
    fail.add(~(d > 0), "the frame length must be positive", "pass frame > 0")

    # K1 cos ψ − K2 cos φ + K3 = cos(φ − ψ): one row per precision point
    m = np.stack([np.cos(psi), -np.cos(phi), np.ones_like(phi)], axis=-1)  # (..., N, 3)
    rhs = np.cos(phi - psi)  # (..., N)
    safe = fail.ok[..., None, None]
    with np.errstate(invalid="ignore"):
        cond = np.linalg.cond(np.where(safe, m, np.eye(n, 3)))
    fail.add(
        ~(cond < SINGULAR_CONDITION),
        "the precision points give a singular system for K1, K2, K3",
        "use distinct precision points whose (cos φ, cos ψ) are not collinear, e.g. not "
        "repeated and not mirror images (φ, ψ) → (−φ, −ψ)",
    )
    m_safe = np.where(fail.ok[..., None, None], m, np.eye(n, 3))
    rhs_safe = np.where(fail.ok[..., None], rhs, 0.0)
    if exact:
        k = np.linalg.solve(m_safe, rhs_safe[..., None])[..., 0]
    else:
        k = (np.linalg.pinv(m_safe) @ rhs_safe[..., None])[..., 0]
    k1, k2, k3 = k[..., 0], k[..., 1], k[..., 2]
    degenerate = "give other ranges or start angles φ0, ψ0, Δφ, Δψ"
    fail.add(
        np.abs(k1) < 1e-12,
        "K1 = d/a = 0: the crank would be infinitely long",
        degenerate,
    )
    fail.add(np.abs(k2) < 1e-12, "K2 = d/c = 0: the rocker would be infinitely long", degenerate)
    with np.errstate(divide="ignore", invalid="ignore"):
        a_s = np.where(fail.ok, d / k1, np.nan)
        c_s = np.where(fail.ok, d / k2, np.nan)
        b2 = a_s**2 + c_s**2 + d**2 - 2.0 * a_s * c_s * k3
    fail.add(
        ~(b2 > 1e-12 * (a_s**2 + c_s**2 + d**2)),
        "no real coupler: b² = a² + c² + d² − 2ac·K3 ≤ 0, the chosen ranges give no real four-bar",
        lambda i: (
            f"b² = {b2[i]:.6g} with a = {a_s[i]:.6g}, c = {c_s[i]:.6g}, d = {d[i]:.6g}"
            "; " + degenerate
        ),
    )
    fail.settle(errors)

    ok = fail.ok
    residual = np.sum(m * k[..., None, :], axis=-1) - rhs
    # assembly branch: side of B with respect to the line A → O4
    ax, ay = a_s[..., None] * np.cos(phi), a_s[..., None] * np.sin(phi)
    bx = d[..., None] + c_s[..., None] * np.cos(psi)
    by = c_s[..., None] * np.sin(psi)
    side = (d[..., None] - ax) * (by - ay) + ay * (bx - ax)
    with np.errstate(invalid="ignore"):
        b = np.sqrt(b2)
    return FunctionGenerator(
        a=_masked(ok, np.abs(a_s)),
        b=_masked(ok, b),
        c=_masked(ok, np.abs(c_s)),
        d=_masked(ok, d),
        k=_masked(ok, k),
        crank_phase=_masked(ok, np.where(a_s < 0, np.pi, 0.0)),
        rocker_phase=_masked(ok, np.where(c_s < 0, np.pi, 0.0)),
        phi=np.array(phi),
        psi=np.array(psi),
        residual=_masked(ok, residual),
        branch=np.where(ok[..., None], _sign(side), 0).astype(np.int8),
        ok=ok,
        reason=fail.reason,
    )


def freudenstein_three_point(
    phi: ArrayLike, psi: ArrayLike, *, frame: ArrayLike = 1.0, errors: Errors = "raise"
) -> FunctionGenerator:
    """Four-bar function generator exact at three precision points (Freudenstein).

    With the signed link lengths of the convention above, loop closure
    ``|B − A|² = b²`` reads (Freudenstein 1955; Norton, *Design of Machinery*, ch. 4 and 5)::

        K1 cos ψ − K2 cos φ + K3 = cos(φ − ψ),
        K1 = d/a,   K2 = d/c,   K3 = (a² − b² + c² + d²)/(2ac),

    linear in ``K1, K2, K3``: three precision points give a 3×3 system, then
    ``a = d/K1``, ``c = d/K2``, ``b² = a² + c² + d² − 2ac·K3``.  The solution is unique up
    to the scale set by ``frame``.  A negative ``a`` (or ``c``) is a link pointing the other
    way: it is returned as ``|a|`` with ``crank_phase = π`` (``rocker_phase`` for ``c``).

    Parameters
    ----------
    phi, psi : array, shape (..., 3), rad — crank and rocker angles at the precision
        points, from the frame line.
    frame : array, shape (...), length, keyword, default 1.0 — frame length ``d``.
    errors : {"raise", "mask"}, keyword, default "raise" — see the module docstring.

    Returns
    -------
    FunctionGenerator — lengths shape (...), per-point fields shape (..., 3).

    Raises
    ------
    SolveError
        If the system is singular (repeated or mirror-image precision points: the ranges
        define no four-bar), ``K1`` or ``K2`` vanishes (an infinitely long crank or
        rocker), or ``b = 0``.  With exactly three points ``b² = |B_i − A_i|² ≥ 0`` always
        holds; ``b² < 0`` can only come out of :func:`freudenstein_least_squares`.  A
        valid result may still have a branch defect (``branch_defect``) or meet a toggle
        between the precision points.

    ``y = log10 x`` on [1, 10], φ from 30° over 60°, ψ from −60° over −90°, three
    Chebyshev points (structural error below 0.007 of the output range, see the tests):

    >>> phi, psi = function_generator_points(np.log10, 1.0, 10.0, np.radians(30.0),
    ...                                      np.radians(60.0), np.radians(-60.0),
    ...                                      np.radians(-90.0))
    >>> fg = freudenstein_three_point(phi, psi)
    >>> [round(float(v), 4) for v in (fg.a, fg.b, fg.c, fg.d)]
    [0.6631, 1.075, 0.5567, 1.0]
    >>> fg.branch, bool(fg.branch_defect)
    (array([-1, -1, -1], dtype=int8), False)
    """
    return _freudenstein(phi, psi, frame, errors, exact=True)


def freudenstein_least_squares(
    phi: ArrayLike, psi: ArrayLike, *, frame: ArrayLike = 1.0, errors: Errors = "raise"
) -> FunctionGenerator:
    """Four-bar function generator fitted to ``N ≥ 3`` points by linear least squares.

    Minimizes the *equation* error ``Σ_i (K1 cos ψ_i − K2 cos φ_i + K3 − cos(φ_i − ψ_i))²``
    over ``K1, K2, K3`` (Freudenstein's equation, see :func:`freudenstein_three_point`;
    Erdman & Sandor, *Advanced Mechanism Design*, vol. 2, least-squares function
    generation).  This is not the structural (angle) error, but a good, cheap starting
    point for minimizing it.  With ``N = 3`` it equals the three-point solution.

    Parameters
    ----------
    phi, psi : array, shape (..., N), rad — ``N ≥ 3``.
    frame : array, shape (...), length, keyword, default 1.0 — frame length ``d``.
    errors : {"raise", "mask"}, keyword, default "raise".

    Returns
    -------
    FunctionGenerator — ``residual`` holds the equation error at each point.
    """
    return _freudenstein(phi, psi, frame, errors, exact=False)


# --------------------------------------------------------------------------------------
# three-position rigid-body guidance
# --------------------------------------------------------------------------------------


@dataclass(frozen=True, eq=False)
class GuidanceFourBar:
    """A four-bar whose coupler passes three given poses.

    Attributes
    ----------
    ground_a, ground_b : array, shape (..., 2), length — fixed pivots ``A0`` (crank) and
        ``B0`` (rocker), world frame.
    moving_a, moving_b : array, shape (..., 3, 2), length — moving pivots ``A_i, B_i`` in
        the world frame at the three poses (``[..., 0, :]`` is the first pose).
    coupler_a, coupler_b : array, shape (..., 2), length — the moving pivots in the coupler
        frame (origin at the pose point, x axis at the pose angle).
    a, b, c, d : array, shape (...), length — ``|A0A|``, ``|AB|``, ``|B0B|``, ``|A0B0|``.
    crank_angle, rocker_angle : array, shape (..., 3), rad — directions of ``A0→A_i`` and
        ``B0→B_i`` from the world x axis.
    branch : int8 array, shape (..., 3) — sign of ``(B0 − A_i) × (B_i − A_i)`` at each pose
        (the assembly branch; 0 at a toggle).
    ok : bool array, shape (...); reason : object array of str, shape (...).
    """

    ground_a: Array
    ground_b: Array
    moving_a: Array
    moving_b: Array
    coupler_a: Array
    coupler_b: Array
    a: Array
    b: Array
    c: Array
    d: Array
    crank_angle: Array
    rocker_angle: Array
    branch: NDArray[np.int8]
    ok: NDArray[np.bool_]
    reason: NDArray[np.object_]

    @property
    def branch_defect(self) -> NDArray[np.bool_]:
        """True where the poses lie on different assembly branches (not reachable in one
        motion without taking the linkage apart)."""
        return np.any(self.branch != self.branch[..., :1], axis=-1)


def _rotate(theta: Array, p: Array) -> Array:
    """Rotate vectors ``p`` (..., 2) by ``theta`` (...)."""
    c, s = np.cos(theta), np.sin(theta)
    return np.stack([c * p[..., 0] - s * p[..., 1], s * p[..., 0] + c * p[..., 1]], axis=-1)


def _circumcentre(p: Array, fail: _Failures, what: str, hint: str) -> Array:
    """Centre of the circle through ``p[..., 0:3, :]``; records coincident/collinear."""
    u = p[..., 1, :] - p[..., 0, :]
    v = p[..., 2, :] - p[..., 0, :]
    w = p[..., 2, :] - p[..., 1, :]
    lu, lv, lw = (np.hypot(q[..., 0], q[..., 1]) for q in (u, v, w))
    scale = np.maximum(np.maximum(lu, lv), lw)
    cross = _cross(u, v)
    fail.add(
        ~(np.minimum(np.minimum(lu, lv), lw) > COINCIDENT_RTOL * scale),
        f"two of the three positions of {what} coincide, so no unique circle passes through them",
        hint,
    )
    fail.add(
        ~(np.abs(cross) > COLLINEAR_SINE * lu * lv),
        f"the three positions of {what} are collinear: the circle through them has an "
        "infinite radius (the pivot would have to be a slider)",
        hint,
    )
    den = np.where(fail.ok, 2.0 * cross, 1.0)
    uu, vv = lu**2, lv**2
    cx = (v[..., 1] * uu - u[..., 1] * vv) / den
    cy = (u[..., 0] * vv - v[..., 0] * uu) / den
    return p[..., 0, :] + np.stack([cx, cy], axis=-1)


def _guidance(
    xy: Array,
    theta: Array,
    ground_a: Array,
    ground_b: Array,
    coupler_a: Array,
    coupler_b: Array,
    fail: _Failures,
    errors: Errors,
) -> GuidanceFourBar:
    """Assemble the result from fixed pivots and coupler-frame moving pivots."""
    moving_a = xy + _rotate(theta, coupler_a[..., None, :])
    moving_b = xy + _rotate(theta, coupler_b[..., None, :])
    scale = np.max(np.hypot(xy[..., 0], xy[..., 1]), axis=-1) + np.hypot(
        *np.moveaxis(coupler_a - coupler_b, -1, 0)
    )
    d_vec = ground_b - ground_a
    d = np.hypot(d_vec[..., 0], d_vec[..., 1])
    fail.add(
        ~(d > COINCIDENT_RTOL * scale),
        "the two fixed pivots coincide (zero frame length)",
        "choose other pivots",
    )
    fail.settle(errors)
    ok = fail.ok
    ra = moving_a - ground_a[..., None, :]
    rb = moving_b - ground_b[..., None, :]
    side = _cross(ground_b[..., None, :] - moving_a, moving_b - moving_a)
    return GuidanceFourBar(
        ground_a=_masked(ok, ground_a),
        ground_b=_masked(ok, ground_b),
        moving_a=_masked(ok, moving_a),
        moving_b=_masked(ok, moving_b),
        coupler_a=_masked(ok, coupler_a),
        coupler_b=_masked(ok, coupler_b),
        a=_masked(ok, np.hypot(ra[..., 0, 0], ra[..., 0, 1])),
        b=_masked(ok, np.hypot(*np.moveaxis(coupler_b - coupler_a, -1, 0))),
        c=_masked(ok, np.hypot(rb[..., 0, 0], rb[..., 0, 1])),
        d=_masked(ok, d),
        crank_angle=_masked(ok, np.arctan2(ra[..., 1], ra[..., 0])),
        rocker_angle=_masked(ok, np.arctan2(rb[..., 1], rb[..., 0])),
        branch=np.where(ok[..., None], _sign(side), 0).astype(np.int8),
        ok=ok,
        reason=fail.reason,
    )


def _poses(xy: ArrayLike, theta: ArrayLike, *pivots: ArrayLike) -> tuple[Array, ...]:
    xy = np.asarray(xy, dtype=float)
    theta = np.asarray(theta, dtype=float)
    if xy.shape[-2:] != (3, 2) or theta.shape[-1:] != (3,):
        raise ValueError(
            f"three poses need xy of shape (..., 3, 2) and theta of shape (..., 3), got "
            f"{xy.shape} and {theta.shape}"
        )
    arrays = [np.asarray(p, dtype=float) for p in pivots]
    for p in arrays:
        if p.shape[-1:] != (2,):
            raise ValueError(f"a pivot needs shape (..., 2), got {p.shape}")
    shape = np.broadcast_shapes(xy.shape[:-2], theta.shape[:-1], *(p.shape[:-1] for p in arrays))
    return (
        np.broadcast_to(xy, (*shape, 3, 2)),
        np.broadcast_to(theta, (*shape, 3)),
        *(np.broadcast_to(p, (*shape, 2)) for p in arrays),
    )


def _finite_poses(fail: _Failures, *arrays: Array) -> None:
    finite = np.ones(fail.shape, dtype=bool)
    for arr, trailing in arrays:
        finite &= np.all(np.isfinite(arr), axis=tuple(range(-trailing, 0)))
    fail.add(~finite, "the poses or pivots are not finite numbers")


def three_position_fixed_pivots(
    xy: ArrayLike,
    theta: ArrayLike,
    *,
    moving_a: ArrayLike,
    moving_b: ArrayLike,
    errors: Errors = "raise",
) -> GuidanceFourBar:
    """Three-position motion generation with chosen moving pivots.

    The coupler frame in pose ``i`` has its origin at ``P_i = xy[i]`` and its x axis at
    ``θ_i``.  A moving pivot ``m`` (coupler frame) is at ``M_i = P_i + R(θ_i) m`` in pose
    ``i``; the fixed pivot is the centre of the circle through ``M_1, M_2, M_3`` — the
    intersection of the perpendicular bisectors of ``M_1M_2`` and ``M_2M_3`` (Norton,
    *Design of Machinery*, ch. 3, "three-position synthesis"; Erdman & Sandor,
    *Mechanism Design*, vol. 1).  Solved in closed form: with ``u = M_2 − M_1``, ``v = M_3 − M_1``,
    ``D = 2 u × v``::

        centre = M_1 + ((v_y |u|² − u_y |v|²)/D, (u_x |v|² − v_x |u|²)/D).

    Parameters
    ----------
    xy : array, shape (..., 3, 2), length — the coupler reference point in the three poses.
    theta : array, shape (..., 3), rad — the coupler angle in the three poses.
    moving_a, moving_b : array, shape (..., 2), length, keyword — the crank-side and
        rocker-side moving pivots in the coupler frame.
    errors : {"raise", "mask"}, keyword, default "raise".

    Returns
    -------
    GuidanceFourBar

    Raises
    ------
    SolveError
        If the three positions of a moving pivot are collinear (its fixed pivot would be at
        infinity) or two of them coincide (the pivot is a rotation pole of two poses), or
        the moving pivots or the resulting fixed pivots coincide.

    >>> fb = three_position_fixed_pivots([[0, 0], [1, 0.2], [2, 0]], [0, 0.3, 0.5],
    ...                                  moving_a=[-0.5, 0], moving_b=[0.5, 0])
    >>> np.round(fb.ground_a, 4), np.round(fb.ground_b, 4)
    (array([ 0.1749, -3.1783]), array([ 1.7152, -1.8682]))
    >>> np.round(np.hypot(*(fb.moving_a - fb.ground_a).T), 6)  # all three on one circle
    array([3.249216, 3.249216, 3.249216])
    """
    _check_errors(errors)
    xy, theta, ma, mb = _poses(xy, theta, moving_a, moving_b)
    fail = _Failures(xy.shape[:-2])
    _finite_poses(fail, (xy, 2), (theta, 1), (ma, 1), (mb, 1))
    gap = np.hypot(*np.moveaxis(mb - ma, -1, 0))
    size = np.max(np.hypot(xy[..., 0], xy[..., 1]), axis=-1) + np.hypot(*np.moveaxis(ma, -1, 0))
    fail.add(
        ~(gap > COINCIDENT_RTOL * size),
        "the two moving pivots coincide (zero coupler length)",
        "choose two distinct moving pivots",
    )
    hint = "choose another moving pivot (away from the rotation poles of the poses)"
    with np.errstate(invalid="ignore", divide="ignore"):
        ground_a = _circumcentre(
            xy + _rotate(theta, ma[..., None, :]), fail, "moving pivot A", hint
        )
        ground_b = _circumcentre(
            xy + _rotate(theta, mb[..., None, :]), fail, "moving pivot B", hint
        )
    return _guidance(xy, theta, ground_a, ground_b, ma, mb, fail, errors)


def three_position_moving_pivots(
    xy: ArrayLike,
    theta: ArrayLike,
    *,
    ground_a: ArrayLike,
    ground_b: ArrayLike,
    errors: Errors = "raise",
) -> GuidanceFourBar:
    """Three-position motion generation with chosen fixed pivots (inversion).

    Seen from the coupler, a fixed pivot ``G`` occupies ``g_i = R(−θ_i)(G − P_i)`` in
    pose ``i``; the moving pivot ``m`` (coupler frame) is equidistant from the three
    ``g_i`` because ``|P_i + R(θ_i) m − G| = |m − g_i|``, so ``m`` is their circumcentre
    (kinematic inversion: Norton, *Design of Machinery*, ch. 3, "three-position synthesis
    with specified fixed pivots"; Erdman & Sandor, *Mechanism Design*, vol. 1).

    Parameters
    ----------
    xy : array, shape (..., 3, 2), length; theta : array, shape (..., 3), rad — the poses.
    ground_a, ground_b : array, shape (..., 2), length, keyword — the fixed pivots (world).
    errors : {"raise", "mask"}, keyword, default "raise".

    Returns
    -------
    GuidanceFourBar

    Raises
    ------
    SolveError
        If the three inverted positions of a fixed pivot are collinear or two coincide, or
        the fixed pivots or the resulting moving pivots coincide.

    >>> fb = three_position_moving_pivots([[0, 0], [1, 0.2], [2, 0]], [0, 0.3, 0.5],
    ...                                   ground_a=[0, -2], ground_b=[3, -2])
    >>> np.round(fb.coupler_a, 4), np.round(fb.coupler_b, 4)
    (array([-0.5118,  0.5077]), array([ 1.3224, -0.3179]))
    >>> np.round(np.hypot(*(fb.moving_b - fb.ground_b).T), 6)  # all three on one circle
    array([2.375704, 2.375704, 2.375704])
    """
    _check_errors(errors)
    xy, theta, ga, gb = _poses(xy, theta, ground_a, ground_b)
    fail = _Failures(xy.shape[:-2])
    _finite_poses(fail, (xy, 2), (theta, 1), (ga, 1), (gb, 1))
    hint = "choose another fixed pivot (away from the rotation poles of the poses)"
    with np.errstate(invalid="ignore", divide="ignore"):
        ca = _circumcentre(
            _rotate(-theta, ga[..., None, :] - xy),
            fail,
            "fixed pivot A seen from the coupler",
            hint,
        )
        cb = _circumcentre(
            _rotate(-theta, gb[..., None, :] - xy),
            fail,
            "fixed pivot B seen from the coupler",
            hint,
        )
    gap = np.hypot(*np.moveaxis(cb - ca, -1, 0))
    size = np.max(np.hypot(xy[..., 0], xy[..., 1]), axis=-1) + np.hypot(*np.moveaxis(ga, -1, 0))
    fail.add(
        ~(gap > COINCIDENT_RTOL * size),
        "the two moving pivots found coincide (zero coupler length)",
        "choose other fixed pivots",
    )
    return _guidance(xy, theta, ga, gb, ca, cb, fail, errors)


# --------------------------------------------------------------------------------------
# slider-crank with a given stroke and time ratio
# --------------------------------------------------------------------------------------


@dataclass(frozen=True, eq=False)
class SliderCrank:
    """An offset slider-crank with a given stroke and time ratio.

    Geometry: crank pivot at the origin, slider pin on the guide line ``y = −e`` (``e ≥ 0``
    below the crank pivot), slider at ``x > 0``.  Turning counter-clockwise, the crank
    takes ``π + θ`` for the outward stroke (near → far, slow) and ``π − θ`` for the return.

    Attributes
    ----------
    crank, rod, offset : array, shape (...), length — ``r``, ``l``, ``e``.
    stroke, time_ratio, excess_angle : array, shape (...) — ``H`` (length), ``K``, θ (rad).
    crank_angle_far, crank_angle_near : array, shape (...), rad — crank angle at the outer
        dead centre (crank and rod in line, ``x = √((l + r)² − e²)``) and at the inner one
        (folded, ``x = √((l − r)² − e²)``).
    slider_far, slider_near : array, shape (...), length — the slider ``x`` at the two.
    ok : bool array, shape (...); reason : object array of str, shape (...).
    """

    crank: Array
    rod: Array
    offset: Array
    stroke: Array
    time_ratio: Array
    excess_angle: Array
    crank_angle_far: Array
    crank_angle_near: Array
    slider_far: Array
    slider_near: Array
    ok: NDArray[np.bool_]
    reason: NDArray[np.object_]


def slider_crank_from_stroke(
    stroke: ArrayLike,
    time_ratio: ArrayLike,
    *,
    offset: ArrayLike | None = None,
    crank: ArrayLike | None = None,
    rod: ArrayLike | None = None,
    errors: Errors = "raise",
) -> SliderCrank:
    """Offset slider-crank with stroke ``H`` and time ratio ``K`` (one free parameter).

    The dead-centre slider positions ``C1, C2`` (``|C1C2| = H``) are seen from the crank
    pivot ``O`` under the excess angle θ, so ``O`` lies on the circle through ``C1, C2``
    with inscribed angle θ, at distance ``e`` from the guide; then ``l − r = |OC_near|``,
    ``l + r = |OC_far|`` (Artobolevsky; the quick-return construction of Norton, *Design
    of Machinery*, ch. 3, with the rocker pivot at infinity).  The cosine rule and the
    area of the triangle ``O C1 C2`` give, with ``t = tan(θ/2)``::

        H² = 4 r² + 2 H e t,        l² = H²/4 + H e / (2 t),

    so exactly one of ``offset``, ``crank`` or ``rod`` fixes the mechanism.  A real one
    exists for ``1 ≤ K < 3`` (θ < 90°: ``θ = arcsin(e/(l − r)) − arcsin(e/(l + r))``
    stays below 90°) with, for ``K > 1``::

        0 < e ≤ H cot θ,      H t/2 ≤ r < H/2,      H/2 < l ≤ H/(2t),

    the upper end of ``e`` (lower end of ``r``) putting the inner dead centre at the foot
    of the perpendicular from ``O`` (the rod square to the guide there).  For ``K = 1`` the
    slider-crank is central: ``e = 0``, ``r = H/2`` and the free parameter is the rod
    ``l > H/2`` (pass ``rod``).

    Parameters
    ----------
    stroke : array, shape (...), length — ``H > 0``.
    time_ratio : array, shape (...) — ``K ≥ 1``.
    offset, crank, rod : array, shape (...), length, keyword — exactly one of them.
    errors : {"raise", "mask"}, keyword, default "raise".

    Returns
    -------
    SliderCrank

    Raises
    ------
    SolveError
        If ``K < 1``, ``K ≥ 3``, ``H ≤ 0``, or the free parameter is outside its range
        (the message gives the range).
    ValueError
        If not exactly one of ``offset``, ``crank``, ``rod`` is given.

    ``H = 0.1``, ``K = 1.4`` (θ = 30°, ``t = tan 15°``), ``e = 0.05``:
    ``r = ½ √(0.01 − 0.01 t) = 0.042780``, ``l = √(0.0025 + 0.0025/t) = 0.108766``:

    >>> sc = slider_crank_from_stroke(0.1, 1.4, offset=0.05)
    >>> [round(float(v), 6) for v in (sc.crank, sc.rod, sc.offset)]
    [0.04278, 0.108766, 0.05]
    >>> round(float(sc.slider_far - sc.slider_near), 12)
    0.1
    """
    _check_errors(errors)
    given = {k: v for k, v in (("offset", offset), ("crank", crank), ("rod", rod)) if v is not None}
    if len(given) != 1:
        raise ValueError(
            "give exactly one free parameter: offset=, crank= or rod= (got "
            f"{', '.join(given) or 'none'})"
        )
    ((which, value),) = given.items()
    h = np.asarray(stroke, dtype=float)
    k = np.asarray(time_ratio, dtype=float)
    p = np.asarray(value, dtype=float)
    shape = np.broadcast_shapes(h.shape, k.shape, p.shape)
    h, k, p = (np.broadcast_to(x, shape) for x in (h, k, p))

    fail = _Failures(shape)
    fail.add(~(np.isfinite(h) & np.isfinite(k) & np.isfinite(p)), "the data are not finite")
    fail.add(~(h > 0), "the stroke must be positive", "pass stroke > 0")
    fail.add(
        ~(k >= 1),
        "the time ratio K must be at least 1",
        "pass 1/K: K < 1 is the same mechanism with the crank turning the other way",
    )
    fail.add(
        ~(k < 3),
        "no slider-crank has K ≥ 3: its excess angle arcsin(e/(l − r)) − arcsin(e/(l + r)) "
        "stays below 90°",
        "lower K, or use a six-bar quick-return (e.g. a slotted-link drive)",
    )
    theta = excess_angle(k)
    with np.errstate(divide="ignore", invalid="ignore"):
        t = np.tan(theta / 2)
        central = k == 1
        e_max = h / np.tan(theta)  # H cot θ
        fail.add(
            central & (which != "rod"),
            "for K = 1 the slider-crank is central (e = 0, r = H/2) and the rod length is "
            "the free parameter",
            "pass rod= (any rod longer than H/2)",
        )
        slack = 1 + RANGE_RTOL
        if which == "offset":
            e = p
            fail.add(
                ~((e > 0) & (e <= e_max * slack)),
                "the offset is outside (0, H cot θ]",
                lambda i: f"choose the offset in (0, {e_max[i]:.6g}]",
            )
            e = np.minimum(e, e_max)
        elif which == "crank":
            lo, hi = h * t / 2, h / 2
            fail.add(
                ~((p >= lo / slack) & (p < hi)),
                "the crank is outside [H tan(θ/2)/2, H/2)",
                lambda i: f"choose the crank in [{lo[i]:.6g}, {hi[i]:.6g})",
            )
            e = np.clip((h**2 - 4 * p**2) / (2 * h * t), 0.0, e_max)
        else:
            lo, hi = h / 2, np.where(central, np.inf, h / (2 * t))
            fail.add(
                ~((p > lo) & (p <= hi * slack)),
                "the rod is outside (H/2, H/(2 tan(θ/2))]",
                lambda i: f"choose the rod in ({lo[i]:.6g}, {hi[i]:.6g}]",
            )
            e = np.where(central, 0.0, np.clip((p**2 - h**2 / 4) * 2 * t / h, 0.0, e_max))
        r = p if which == "crank" else np.where(central, h / 2, np.sqrt(h**2 - 2 * h * e * t) / 2)
        if which == "rod":
            ell = p
        else:
            ell = np.sqrt(h**2 / 4 + h * e / (2 * t))
    fail.settle(errors)

    ok = fail.ok
    with np.errstate(invalid="ignore"):
        s_far = np.sqrt((ell + r) ** 2 - e**2)
        s_near = np.sqrt(np.maximum((ell - r) ** 2 - e**2, 0.0))
    return SliderCrank(
        crank=_masked(ok, r),
        rod=_masked(ok, ell),
        offset=_masked(ok, e),
        stroke=_masked(ok, h),
        time_ratio=_masked(ok, k),
        excess_angle=_masked(ok, theta),
        crank_angle_far=_masked(ok, np.arctan2(-e, s_far)),
        crank_angle_near=_masked(ok, np.arctan2(e, -s_near)),
        slider_far=_masked(ok, s_far),
        slider_near=_masked(ok, s_near),
        ok=ok,
        reason=fail.reason,
    )


# --------------------------------------------------------------------------------------
# crank-rocker with a given swing and time ratio
# --------------------------------------------------------------------------------------


@dataclass(frozen=True, eq=False)
class CrankRocker:
    """A Grashof crank-rocker with a given rocker swing and time ratio.

    Angles follow the four-bar convention of the module (crank pivot at the origin, rocker
    pivot at ``(d, 0)``, angles from the frame line).

    Attributes
    ----------
    a, b, c, d : array, shape (...), length — crank, coupler, rocker, frame.
    swing, time_ratio, excess_angle : array, shape (...) — ψ (rad), ``K``, θ (rad).
    crank_angle_extended, rocker_angle_extended : array, shape (...), rad — at the
        extreme where crank and coupler are in line, extended (``|O2B| = b + a``).
    crank_angle_folded, rocker_angle_folded : array, shape (...), rad — at the extreme
        where they overlap, folded (``|O2B| = b − a``).
    ok : bool array, shape (...); reason : object array of str, shape (...).
    """

    a: Array
    b: Array
    c: Array
    d: Array
    swing: Array
    time_ratio: Array
    excess_angle: Array
    crank_angle_extended: Array
    crank_angle_folded: Array
    rocker_angle_extended: Array
    rocker_angle_folded: Array
    ok: NDArray[np.bool_]
    reason: NDArray[np.object_]


SlowSwing = Literal["against_crank", "with_crank"]


def crank_rocker_frame_range(
    swing: ArrayLike,
    time_ratio: ArrayLike,
    *,
    rocker: ArrayLike = 1.0,
    slow_swing: SlowSwing = "against_crank",
) -> tuple[Array, Array]:
    """Open interval of frame lengths ``d`` that give a crank-rocker (see
    :func:`crank_rocker_from_swing`): ``c < d < c |sin(θ ± ψ)| / sin θ``.

    Returns ``(lo, hi)``, arrays of shape (...), length; empty (``hi ≤ lo``) when no
    crank-rocker of that kind exists; ``hi = inf`` for ``K = 1``.
    """
    sigma = _slow_swing_sign(slow_swing)
    psi = np.asarray(swing, dtype=float)
    c = np.asarray(rocker, dtype=float)
    theta = excess_angle(time_ratio)
    with np.errstate(divide="ignore", invalid="ignore"):
        hi = c * np.abs(np.sin(theta + sigma * psi)) / np.sin(theta)
    lo, hi = np.broadcast_arrays(c, hi)
    return np.array(lo), np.array(hi)


def _slow_swing_sign(slow_swing: str) -> float:
    if slow_swing == "against_crank":
        return 1.0
    if slow_swing == "with_crank":
        return -1.0
    raise ValueError(f"slow_swing must be 'against_crank' or 'with_crank', got {slow_swing!r}")


def crank_rocker_from_swing(
    swing: ArrayLike,
    time_ratio: ArrayLike,
    *,
    frame: ArrayLike,
    rocker: ArrayLike = 1.0,
    slow_swing: SlowSwing = "against_crank",
    errors: Errors = "raise",
) -> CrankRocker:
    """Crank-rocker with rocker swing ψ and time ratio ``K`` (one free parameter: ``d``).

    The classical construction (Artobolevsky; Norton, *Design of Machinery*, ch. 3,
    "quick-return four-bar"): draw the rocker ``O4B`` of length ``c`` in its two extreme
    positions ``B1, B2``, ψ apart.  At the extremes crank and coupler are in line, so the
    crank pivot ``O2`` sees the chord ``B1B2`` (length ``2c sin(ψ/2)``) under the excess
    angle θ: ``O2`` lies on a circle through ``B1, B2`` with inscribed angle θ, and
    ``b + a = |O2B_ext|``, ``b − a = |O2B_fold|``.  Of the two such circles (centres on
    either side of the chord), the one beyond the chord, seen from ``O4``, gives a rocker
    whose slow swing turns against the crank (``slow_swing="against_crank"``); the one on
    the side of ``O4`` a slow swing with the crank (``"with_crank"``).  ``O2`` must not
    lie on the arc cut off by the lines ``O4B1`` and ``O4B2`` (there the two extremes
    fall on different circuits): the frame length — the distance ``|O2O4|``, monotonic
    along the admissible arc — is then restricted to::

        c < d < c |sin(θ + σψ)| / sin θ,     σ = +1 (against) or −1 (with),

    non-empty iff ``ψ + 2θ < π`` (against) or ``ψ > 2θ`` (with).  ``O2`` is placed on the
    circle at distance ``d`` from ``O4`` by the radical line of the two circles (stable
    down to ``θ = 0``, where the circle becomes the line ``B1B2``), then ``a, b`` follow
    from the distances to ``B1, B2``.  The mirror image of the result is the other
    solution with the same lengths.

    Parameters
    ----------
    swing : array, shape (...), rad — rocker swing ψ, ``0 < ψ < π``.
    time_ratio : array, shape (...) — ``K ≥ 1``.
    frame : array, shape (...), length, keyword — the free parameter ``d``; see
        :func:`crank_rocker_frame_range`.
    rocker : array, shape (...), length, keyword, default 1.0 — rocker ``c`` (the scale).
    slow_swing : {"against_crank", "with_crank"}, keyword, default "against_crank" — the
        sense of the rocker's slow swing relative to the crank's rotation.
    errors : {"raise", "mask"}, keyword, default "raise".

    Returns
    -------
    CrankRocker — with the crank turning counter-clockwise it turns by ``π + θ`` from the
    extended to the folded extreme (``"against_crank"``; the reverse for ``"with_crank"``).

    Raises
    ------
    SolveError
        If ψ is not in (0, π), ``K < 1``, a length is not positive, or ``d`` is outside the
        range (the message gives it, or says that none exists).

    >>> cr = crank_rocker_from_swing(np.radians(50.0), 1.3, frame=2.0)
    >>> [round(float(v), 4) for v in (cr.a, cr.b, cr.c, cr.d)]
    [0.3294, 1.3424, 1.0, 2.0]
    >>> round(float(np.degrees(cr.rocker_angle_extended - cr.rocker_angle_folded)), 9)
    50.0
    """
    _check_errors(errors)
    sigma = _slow_swing_sign(slow_swing)
    psi = np.asarray(swing, dtype=float)
    k = np.asarray(time_ratio, dtype=float)
    d = np.asarray(frame, dtype=float)
    c = np.asarray(rocker, dtype=float)
    shape = np.broadcast_shapes(psi.shape, k.shape, d.shape, c.shape)
    psi, k, d, c = (np.broadcast_to(x, shape) for x in (psi, k, d, c))

    fail = _Failures(shape)
    finite = np.isfinite(psi) & np.isfinite(k) & np.isfinite(d) & np.isfinite(c)
    fail.add(~finite, "the data are not finite")
    fail.add(~((psi > 0) & (psi < np.pi)), "the rocker swing must lie in (0, π)")
    fail.add(
        ~(k >= 1),
        "the time ratio K must be at least 1",
        "pass 1/K with the other slow_swing: K < 1 is the same mechanism run backwards",
    )
    fail.add(~((c > 0) & (d > 0)), "the rocker and frame lengths must be positive")
    theta = excess_angle(k)
    lo, hi = crank_rocker_frame_range(psi, k, rocker=c, slow_swing=slow_swing)
    other = "with_crank" if sigma > 0 else "against_crank"
    condition = "ψ + 2θ < π" if sigma > 0 else "ψ > 2θ"

    def range_hint(i: tuple[int, ...]) -> str:
        if hi[i] <= lo[i]:
            return (
                f"no frame length works: slow_swing={slow_swing!r} needs {condition} "
                f"(ψ = {math.degrees(psi[i]):.6g}°, θ = {math.degrees(theta[i]):.6g}°); "
                f"try slow_swing={other!r} or other ψ, K"
            )
        return f"choose the frame length in ({lo[i]:.6g}, {hi[i]:.6g})"

    fail.add(
        ~((d > lo) & (d < hi)),
        "no crank-rocker with this frame length: the crank pivot would leave the "
        "admissible arc of the construction circle",
        range_hint,
    )
    fail.settle(errors)

    ok = fail.ok
    # construction frame: O4 at the origin, B1 = (−w, h), B2 = (w, h)
    w, h = c * np.sin(psi / 2), c * np.cos(psi / 2)
    st, ct = np.sin(theta), np.cos(theta)
    with np.errstate(invalid="ignore", divide="ignore"):
        y = ((d**2 + h**2 - w**2) * st + 2 * sigma * h * w * ct) / (2 * h * st + 2 * sigma * w * ct)
        x = np.sqrt(np.maximum(d**2 - y**2, 0.0))
    o2 = np.stack([x, y], axis=-1)
    b1 = np.stack([-w, h], axis=-1)  # extended extreme (farther from O2, which has x > 0)
    b2 = np.stack([w, h], axis=-1)  # folded extreme
    l_ext = np.hypot(*np.moveaxis(b1 - o2, -1, 0))
    l_fold = np.hypot(*np.moveaxis(b2 - o2, -1, 0))
    # output frame: O2 at the origin, x axis along O2 → O4
    u = -o2 / np.where(ok, d, 1.0)[..., None]
    return CrankRocker(
        a=_masked(ok, (l_ext - l_fold) / 2),
        b=_masked(ok, (l_ext + l_fold) / 2),
        c=_masked(ok, c),
        d=_masked(ok, d),
        swing=_masked(ok, psi),
        time_ratio=_masked(ok, k),
        excess_angle=_masked(ok, theta),
        crank_angle_extended=_masked(ok, _angle_in(u, b1 - o2)),
        crank_angle_folded=_masked(ok, _angle_in(u, o2 - b2)),
        rocker_angle_extended=_masked(ok, _angle_in(u, b1)),
        rocker_angle_folded=_masked(ok, _angle_in(u, b2)),
        ok=ok,
        reason=fail.reason,
    )
