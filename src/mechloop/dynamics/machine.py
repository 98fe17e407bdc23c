"""Machine motion: steady motion of a one-degree-of-freedom machine and flywheel sizing.

The machine is reduced to its input link, coordinate ``q``: a reduced moment of inertia
``J(q) > 0`` and the reduced moment of all loads ``M(q)`` (driving positive, resisting
negative).  Over one cycle of ``q`` the energy equation gives the speed,

    ½ J(q) ω(q)² = E0 + A(q),        A(q) = ∫_{q0}^{q} M dq,

and the motion is steady (the state at the end of the cycle equals the state at its start)
only when the net work ``A(q_end)`` is zero.  The constant ``E0`` (kinetic energy at
``q0``) is chosen so that the mean speed ``(ω_max + ω_min) / 2`` equals the requested one;
the coefficient of speed fluctuation is ``δ = (ω_max − ω_min) / ω_mean``.  Extremes are
taken over the given positions, so the grid should be fine enough to resolve them.

Shapes: ``q`` is ``(P,)``; every other sampled quantity is ``(..., P)`` with positions
last, and leading axes (independent cases) broadcast.  Units are SI: ``q`` rad, ``J``
kg·m², ``M`` N·m, ``ω`` rad/s, ``ε`` rad/s², energy J, time s.  For a sliding input read
m, kg, N, m/s and m/s².

Quadrature: samples are read as a cubic spline in ``q`` (``scipy.interpolate
.CubicSpline``) and integrated or differentiated exactly.  A case whose last sample equals
its first (to ``PERIODIC_RTOL`` of its largest value) gets a periodic spline, else a
not-a-knot one; both are fourth order and exact for constants and cubics.  A cumulative
trapezoid would be only second order and make the steady-state test depend on the grid.

>>> import numpy as np
>>> q = np.linspace(0.0, 2 * np.pi, 361)
>>> motion = machine_motion(q, np.full_like(q, 2.0), 10.0 * np.sin(q), omega_mean=10.0)
>>> round(motion.delta, 9)  # 2·M0 / (J·ω_mean²)
0.1
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.interpolate import CubicSpline
from scipy.optimize import brentq

from mechloop.errors import SolveError

Array = NDArray[np.float64]

#: Largest ``|y(q_end) − y(q0)| / max|y|`` for which samples are read as periodic.
PERIODIC_RTOL = 1e-9
#: Largest net work over the cycle, relative to ``max|A|``, that still counts as steady.
STEADY_RTOL = 1e-6
#: The fixed point over the speed of loads that depend on it (:func:`settle_speed`) has
#: converged when ``max|ω_{k+1}(q) − ω_k(q)|`` falls to this times the mean speed.
SETTLE_RTOL = 1e-11
#: The most iterations :func:`settle_speed` takes before it gives up.
SETTLE_ITERATIONS = 200


class MachineError(SolveError):
    """A machine motion that cannot be computed, and why (``cause``): ``"cycle"`` (the
    chain breaks or the force analysis is singular somewhere in the cycle),
    ``"advance"`` (the input does not advance), ``"stops"`` (the machine stops),
    ``"inertia"`` (no reduced inertia somewhere), ``"unsteady"`` (the loads leave net
    work over the cycle), ``"settle"`` (loads that depend on the speed: the steady cycle
    was not found, :func:`settle_speed`).  What to change in a model for each cause:
    :mod:`mechloop.dynamics.analysis`."""

    def __init__(self, message: str, hint: str = "", cause: str = ""):
        super().__init__(message, hint)
        self.cause = cause

    def __reduce__(self):
        return (type(self), (self.message, self.hint, self.cause))


@dataclass(frozen=True, eq=False)
class MachineMotion:
    """Steady motion of the machine over one cycle.

    Attributes
    ----------
    omega : array, shape (..., P), rad/s — speed of the input link.
    epsilon : array, shape (..., P), rad/s² — its acceleration ``(M − ½ω² dJ/dq) / J``.
    kinetic_energy : array, shape (..., P), J — ``½ J ω² = E0 + A``.
    time : array, shape (..., P), s — ``t(q) = ∫ dq/ω`` from ``q0``; ``time[..., -1]`` is
        the period of the cycle.
    omega_max, omega_min : float or array, shape (...), rad/s — extremes over the cycle.
    delta : float or array, shape (...) — ``(omega_max − omega_min) / omega_mean``.
    runs : bool or array of bool, shape (...) — where the motion is steady and the speed
        stays positive; every other field is NaN where it is False (only with
        ``stops="nan"``: :func:`machine_motion` raises otherwise).
    """

    omega: Array
    epsilon: Array
    kinetic_energy: Array
    time: Array
    omega_max: Array | float
    omega_min: Array | float
    delta: Array | float
    runs: NDArray[np.bool_] | bool = True


def work(q: ArrayLike, m: ArrayLike) -> Array:
    """Cumulative work ``A(q) = ∫_{q0}^{q} m dq``.

    Parameters
    ----------
    q : array, shape (P,), rad — strictly increasing.
    m : array, shape (..., P), N·m — moment at the positions ``q``.

    Returns
    -------
    A : array, shape (..., P), J — zero at ``q[0]``; integral of the cubic spline of ``m``
        (periodic where ``m`` returns to its first value, see the module docstring).
    """
    q = _positions(q)
    return _spline_values(q, _samples("m", m, q), -1)


def steady_driving_moment(q: ArrayLike, m_resist: ArrayLike) -> Array | float:
    """The constant moment that makes the net work of ``m_resist`` over the cycle zero.

    ``M_d = −A(q_end) / (q_end − q0)`` with ``A = work(q, m_resist)``, N·m; shape (...).
    For an engine, pass the driving moment table to get the constant resisting moment.
    """
    q = _positions(q)
    return _out(-work(q, m_resist)[..., -1] / (q[-1] - q[0]))


def machine_motion(
    q: ArrayLike,
    j_red: ArrayLike,
    m_red: ArrayLike,
    *,
    omega_mean: ArrayLike,
    dj_red: ArrayLike | None = None,
    stops: str = "raise",
) -> MachineMotion:
    """Steady motion from the reduced characteristics at a given mean speed.

    Parameters
    ----------
    q : array, shape (P,), rad — one cycle of the input coordinate, strictly increasing.
    j_red : array, shape (..., P), kg·m² — reduced moment of inertia, positive.
    m_red : array, shape (..., P), N·m — reduced moment of all loads; its net work over the
        cycle must be zero.
    omega_mean : float or array, shape (...), rad/s — ``(ω_max + ω_min) / 2``, positive.
    dj_red : array, shape (..., P), kg·m², optional — ``dJ/dq``; by default the derivative
        of the cubic spline of ``j_red`` (periodic when ``j_red`` is).
    stops : {"raise", "nan"}, default "raise" — what a case that is not steady or stops
        gives: the :class:`SolveError` below, or NaN in its fields and False in ``runs``
        (a stack of independent cases, e.g. candidate designs, where some fail).

    ``E0`` is found by bisection on all cases at once: the mean speed grows monotonically
    with ``E0`` from ``E0 = −min A`` (the machine just stops) upwards.

    Raises
    ------
    SolveError
        If the net work over the cycle is not zero (the motion is not steady), or if the
        speed cannot stay positive at the requested mean (the machine stops); with
        ``stops="nan"`` only for invalid arguments.
    """
    if stops not in ("raise", "nan"):
        raise ValueError(f"stops must be 'raise' or 'nan', got {stops!r}")
    q, j, m, w_mean = _reduced(q, j_red, m_red, omega_mean)
    a = work(q, m)
    if stops == "raise":
        _check_steady(q, a)
    kinetic, runs = _kinetic_energy(a, j, w_mean)
    if stops == "raise":
        _check_running(q, a, j, w_mean, runs)
    else:
        runs = runs & ~_unsteady(a)
        kinetic = np.where(runs[..., None], kinetic, 1.0)  # NaN below, after the spline
    omega = np.sqrt(2.0 * kinetic / j)
    dj = _spline_values(q, j, 1) if dj_red is None else _samples("dj_red", dj_red, q)
    epsilon = (m - 0.5 * omega**2 * dj) / j
    time = _spline_values(q, 1.0 / omega, -1)
    if not runs.all():
        kinetic, omega, epsilon, time = (np.where(runs[..., None], x, np.nan)
                                         for x in (kinetic, omega, epsilon, time))
    w_max, w_min = omega.max(axis=-1), omega.min(axis=-1)
    return MachineMotion(
        omega=omega,
        epsilon=epsilon,
        kinetic_energy=kinetic,
        time=time,
        omega_max=_out(w_max),
        omega_min=_out(w_min),
        delta=_out((w_max - w_min) / w_mean),
        runs=bool(runs) if runs.ndim == 0 else runs,
    )


def flywheel_inertia(
    q: ArrayLike,
    j_red: ArrayLike,
    m_red: ArrayLike,
    *,
    omega_mean: ArrayLike,
    delta: ArrayLike,
    dj_red: ArrayLike | None = None,
) -> Array | float:
    """The constant inertia ``J_f`` (kg·m²) added to ``j_red`` that gives exactly ``delta``.

    Arguments as in :func:`machine_motion`; ``delta`` (float or array, shape (...)) is the
    target coefficient of speed fluctuation, ``0 < delta < 2``.  ``δ(J_f)`` decreases
    monotonically; ``J_f`` is its root by ``brentq``, case by case.  Returns 0.0 where the
    target is met without a flywheel.  A machine that would stop without a flywheel counts
    as ``δ = 2`` (the limit of a running machine), so it gets sized too.  ``dj_red`` does
    not change ``δ``; it is accepted so that the same arguments fit both functions.

    Returns a float for ``(P,)`` inputs, else an array of shape (...).
    """
    q, j, m, w_mean = _reduced(q, j_red, m_red, omega_mean)
    a = work(q, m)
    _check_steady(q, a)
    target = _fluctuation_target(delta, w_mean.shape)
    j_f = np.zeros(w_mean.shape)
    for case in np.ndindex(w_mean.shape):
        j_f[case] = _flywheel_case(a[case], j[case], w_mean[case], target[case])
    return _out(j_f)


def flywheel_inertia_approx(
    q: ArrayLike,
    j_red: ArrayLike,
    m_red: ArrayLike,
    *,
    omega_mean: ArrayLike,
    delta: ArrayLike,
    dj_red: ArrayLike | None = None,
) -> Array | float:
    """Flywheel inertia (kg·m²) by the classical approximate (Merzalov) method.

    The links split into group I of constant reduced inertia ``J_I = J_c + J_f`` and group
    II, the variable rest ``j_red − J_c``, whose kinetic energy is taken at the mean speed.
    The energy of group I is then ``T_I(q) = const + A(q) − ½ j_red(q) ω_mean²``, and

        J_f = (max T_I − min T_I) / (δ ω_mean²) − J_c,       J_c = min_q j_red,

    clipped at 0.0.  For a constant ``j_red`` this is exact (it equals
    :func:`flywheel_inertia`); otherwise taking group II at the mean speed errs by up to
    about half the swing of ``j_red``, small beside a flywheel much larger than that.
    Arguments and return as in :func:`flywheel_inertia`.
    """
    q, j, m, w_mean = _reduced(q, j_red, m_red, omega_mean)
    a = work(q, m)
    _check_steady(q, a)
    target = _fluctuation_target(delta, w_mean.shape)
    group_one = a - 0.5 * j * w_mean[..., None] ** 2
    j_f = np.ptp(group_one, axis=-1) / (target * w_mean**2) - j.min(axis=-1)
    return _out(np.maximum(j_f, 0.0))


def settle_speed(cycle_at, omega_mean: float, q: Array, *, rtol: float = SETTLE_RTOL,
                 iterations: int | None = None):
    """The steady cycle of a machine whose loads depend on the speed: the fixed point of
    ``ω_{k+1}(q) = ω(cycle_at(ω_k, t_k))`` from the constant ``omega_mean`` (rad/s).

    ``cycle_at(omega, time)`` (``omega`` rad/s and ``time`` s over the positions ``q``,
    shapes (P,)) evaluates the loads at that motion, balances the cycle and returns
    ``(result, motion)``: anything, and the :class:`MachineMotion` that runs.  Returns
    ``(result, motion, iterations)`` once ``max|ω_{k+1} − ω_k| ≤ rtol·omega_mean``.

    Raises :class:`MachineError` (cause ``"settle"``) when that does not happen within
    ``iterations`` (default :data:`SETTLE_ITERATIONS`; the loads change too much with the
    speed for the steady cycle at this mean speed to be found by substitution).
    """
    iterations = SETTLE_ITERATIONS if iterations is None else iterations
    omega = np.full(q.shape, float(omega_mean))
    time = (q - q[0]) / float(omega_mean)
    change = np.inf
    for count in range(1, iterations + 1):
        result, motion = cycle_at(omega, time)
        change = float(np.max(np.abs(motion.omega - omega))) / float(omega_mean)
        omega, time = motion.omega, motion.time
        if change <= rtol:
            return result, motion, count
    raise MachineError(
        f"the steady cycle with the loads that depend on the speed did not settle: after "
        f"{iterations} iterations the speed over the cycle still changed by {change:.3g} "
        f"of the mean speed (wanted {rtol:.3g})",
        "the dampers or one-way loads change too much with the speed over the cycle: "
        "raise the mean speed, add inertia (a flywheel: delta smaller), or simulate the "
        "machine in time instead", cause="settle")


def _flywheel_case(a: Array, j: Array, w_mean: float, target: float) -> float:
    """``J_f`` of one case, shape (P,): root of ``δ(j + J_f) = target``."""

    def excess(j_f: float) -> float:
        return float(_fluctuation(a, j + j_f, np.asarray(w_mean))) - target

    if excess(0.0) <= 0.0:
        return 0.0
    # δ ≈ ΔE / (J_f ω²): start at that size with ΔE bounded above, grow until δ < target.
    high = (np.ptp(a) + 0.5 * w_mean**2 * np.ptp(j)) / (target * w_mean**2)
    for _ in range(200):
        if excess(high) < 0.0:
            return float(brentq(excess, 0.0, high, xtol=1e-14 * high))
        high *= 2.0
    raise SolveError(  # pragma: no cover - δ falls like 1/J_f, so the loop ends
        f"no flywheel reaches delta = {target:.6g}", "check the reduced characteristics"
    )


def _fluctuation(a: Array, j: Array, w_mean: Array) -> Array:
    """δ, shape (...); 2.0 where the machine stops."""
    kinetic, runs = _kinetic_energy(a, j, w_mean)
    omega = np.sqrt(2.0 * np.maximum(kinetic, 0.0) / j)
    return np.where(runs, (omega.max(axis=-1) - omega.min(axis=-1)) / w_mean, 2.0)


def _kinetic_energy(a: Array, j: Array, w_mean: Array) -> tuple[Array, NDArray[np.bool_]]:
    """``E0 + A``, shape (..., P), with ``E0`` such that ``(ω_max + ω_min)/2 = w_mean``, and
    the mask of cases, shape (...), where such an ``E0`` exists (the machine runs).

    Bisection on ``E0`` for all cases at once.  At ``E0 = −min A`` the slowest speed is
    zero: if the mean speed there already reaches ``w_mean`` the machine stops.  At
    ``E0 = −min A + max J·w_mean²`` the slowest speed is at least ``√2·w_mean``.
    """
    low = np.asarray(-a.min(axis=-1))
    runs = _mean_speed(low, a, j) < w_mean
    high = low + j.max(axis=-1) * w_mean**2
    for _ in range(200):
        mid = 0.5 * (low + high)
        if np.all((mid == low) | (mid == high)):
            break
        too_slow = _mean_speed(mid, a, j) < w_mean
        low, high = np.where(too_slow, mid, low), np.where(too_slow, high, mid)
    kinetic = 0.5 * (low + high)[..., None] + a
    return kinetic, runs & (kinetic.min(axis=-1) > 0.0)


def _mean_speed(e0: Array, a: Array, j: Array) -> Array:
    omega = np.sqrt(2.0 * np.maximum(e0[..., None] + a, 0.0) / j)
    return 0.5 * (omega.max(axis=-1) + omega.min(axis=-1))


def _unsteady(a: Array) -> NDArray[np.bool_]:
    """The cases, shape (...), whose net work over the cycle is not zero."""
    return np.abs(a[..., -1]) > STEADY_RTOL * np.abs(a).max(axis=-1)


def _check_steady(q: Array, a: Array) -> None:
    net = a[..., -1]
    bad = _unsteady(a)
    if bad.any():
        case = _first(bad)
        raise MachineError(
            f"the motion is not steady: the loads leave a net work of {float(net[case]):.6g} J"
            f" over one cycle{_where(case, bad)}, so the speed does not repeat",
            "add the constant driving moment steady_driving_moment(q, m_red) = "
            f"{float(-net[case] / (q[-1] - q[0])):.6g} N·m to m_red; it balances the net work",
            cause="unsteady",
        )


def _check_running(q: Array, a: Array, j: Array, w_mean: Array, runs: Array) -> None:
    stops = ~runs
    if stops.any():
        case = _first(stops)
        need = float(_mean_speed(-a.min(axis=-1), a, j)[case])
        raise MachineError(
            f"the machine stops: at omega_mean = {float(w_mean[case]):.6g} rad/s the kinetic"
            f" energy falls to zero near q = {float(q[np.argmin(a[case])]):.6g}"
            f"{_where(case, stops)}; steady running needs omega_mean > {need:.6g} rad/s",
            "raise omega_mean or add a flywheel (flywheel_inertia gives its size for a delta)",
            cause="stops",
        )


def _first(mask: NDArray[np.bool_]) -> tuple[int, ...]:
    return tuple(int(i) for i in np.argwhere(mask)[0])


def _where(case: tuple[int, ...], mask: NDArray[np.bool_]) -> str:
    if not case:
        return ""
    index = case[0] if len(case) == 1 else case
    return f" (case {index}; {int(mask.sum())} of {mask.size} cases)"


def _reduced(
    q: ArrayLike, j_red: ArrayLike, m_red: ArrayLike, omega_mean: ArrayLike
) -> tuple[Array, Array, Array, Array]:
    """Validated ``q`` and ``j, m, omega_mean`` broadcast to shapes (..., P) and (...)."""
    q = _positions(q)
    j = _samples("j_red", j_red, q)
    if not np.all(j > 0.0):
        raise MachineError("j_red must be positive at every position", "check the masses",
                           cause="inertia")
    m = _samples("m_red", m_red, q)
    w_mean = np.asarray(omega_mean, dtype=float)
    if not np.all(np.isfinite(w_mean) & (w_mean > 0.0)):
        raise SolveError(f"omega_mean must be positive, got {omega_mean!r}", "pass rad/s > 0")
    lead = np.broadcast_shapes(j.shape[:-1], m.shape[:-1], w_mean.shape)
    return (
        q,
        np.broadcast_to(j, (*lead, q.size)),
        np.broadcast_to(m, (*lead, q.size)),
        np.broadcast_to(w_mean, lead),
    )


def _fluctuation_target(delta: ArrayLike, lead: tuple[int, ...]) -> Array:
    target = np.asarray(delta, dtype=float)
    if not np.all((target > 0.0) & (target < 2.0)):
        raise SolveError(
            f"delta must lie in (0, 2), got {delta!r}", "typical values are 0.01 to 0.1"
        )
    return np.broadcast_to(target, lead)


def _positions(q: ArrayLike) -> Array:
    q = np.asarray(q, dtype=float)
    if q.ndim != 1 or q.size < 4:
        raise SolveError(
            f"q must be one cycle of at least 4 positions, shape (P,); got shape {q.shape}",
            "pass the input coordinate as a 1-D array",
        )
    if not (np.all(np.isfinite(q)) and np.all(np.diff(q) > 0.0)):
        raise SolveError("q must be finite and strictly increasing", "sort q, drop repeats")
    return q


def _samples(name: str, y: ArrayLike, q: Array) -> Array:
    y = np.asarray(y, dtype=float)
    if y.ndim == 0 or y.shape[-1] != q.size:
        raise SolveError(
            f"{name} must have shape (..., {q.size}) like q, got {y.shape}",
            "put the positions on the last axis",
        )
    if not np.all(np.isfinite(y)):
        raise SolveError(f"{name} has non-finite values", f"check {name}")
    return y


def _spline_values(q: Array, y: Array, nu: int) -> Array:
    """Derivative ``nu`` (1) or integral from ``q[0]`` (``nu = -1``) at ``q`` of the cubic
    spline of ``y``, shape (..., P): periodic for cases that return to their first value."""
    periodic = np.abs(y[..., -1] - y[..., 0]) <= PERIODIC_RTOL * np.abs(y).max(axis=-1)
    closed = np.concatenate([y[..., :-1], y[..., :1]], axis=-1)
    values = _evaluate(CubicSpline(q, closed, axis=-1, bc_type="periodic"), q, nu)
    if periodic.all():
        return values
    open_values = _evaluate(CubicSpline(q, y, axis=-1), q, nu)
    return np.where(np.expand_dims(periodic, -1), values, open_values)


def _evaluate(spline: CubicSpline, q: Array, nu: int) -> Array:
    if nu >= 0:
        return spline(q, nu)
    values = spline.antiderivative(-nu)(q)
    return values - values[..., :1]


def _out(x: Array) -> Array | float:
    """A float for a single case, the array of shape (...) otherwise."""
    x = np.asarray(x)
    return float(x) if x.ndim == 0 else x
