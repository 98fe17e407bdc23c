"""A one-input machine reduced to its input ``q`` as functions of ``q``: ``J(q)``,
``J'(q)``, the reduced moment of its loads ``M_q(q)`` and their work, read from samples over
one cycle — what :mod:`mechloop.dynamics.simulate` integrates.

Between the samples the values are the cubic spline :mod:`mechloop.dynamics.machine` uses:
periodic when the samples return to their first value (to ``PERIODIC_RTOL``), else
not-a-knot.  ``J'`` is the derivative of the spline of ``J`` itself, so ``½·J(q)·ω²`` changes
exactly by the work done.  A machine whose ``J`` returns to its first value is periodic: the
functions repeat every cycle ``L = q[-1] − q[0]`` (the loads' work grows by its work per
cycle each cycle).  Units SI: rad, kg·m², N·m, J.
"""

from __future__ import annotations

import math
from bisect import bisect_right
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray
from scipy.interpolate import CubicSpline

from mechloop.dynamics.machine import PERIODIC_RTOL
from mechloop.errors import SolveError

Array = NDArray[np.float64]



@dataclass(frozen=True)
class Interpolation:
    """How well the splines read ``J`` between the positions.

    ``inertia_error``: estimated largest error of ``J`` between positions, kg·m² (the miss
    of a spline through every other position, divided by 16); ``slope_error``: largest
    ``|J_spline'(q_i) − dJ/dq_i|`` at the positions against the analogs' derivative,
    kg·m²/rad (NaN when the analogs' derivative is not given).
    """

    inertia_error: float
    slope_error: float


class ReducedMachine:
    """``J(q)``, ``J'(q)``, ``M_q(q)`` and its work ``A(q)`` from samples over one cycle.

    Parameters
    ----------
    q : array, shape (P,), rad — the input over one cycle, strictly increasing.
    inertia : array, shape (P,), kg·m² — ``J`` at ``q``, positive.
    load : array, shape (P,), N·m — reduced moment of the loads at ``q``.
    d_inertia : array, shape (P,), kg·m²/rad, optional — the analogs' ``dJ/dq``, only to
        check the spline's slope (:class:`Interpolation`).
    periodic : bool, optional — False: the samples are a range, not a cycle, even if
        ``J`` returns to its first value (an input that does not turn whole turns); by
        default a machine is periodic when ``J`` returns.
    state : :class:`~mechloop.dynamics.state_terms.StateTerms`, optional — the reduced
        moment ``M_s(q, ω)`` of the loads that depend on the speed (dampers, loads with
        ``when``), beside ``M_q(q)`` (which must leave them out).
    breaks : (lower, upper), optional — where the chain breaks beyond the first and the
        last sample (:class:`~mechloop.dynamics.chain_span.ChainEnd`, None where the
        model's range simply ends): the samples are then the stretch of positions between
        two breaks, not a cycle (``periodic`` must not be True).
    """

    def __init__(self, q: ArrayLike, inertia: ArrayLike, load: ArrayLike,
                 d_inertia: ArrayLike | None = None, *, periodic: bool | None = None,
                 state=None, breaks: tuple = (None, None)):
        q = np.asarray(q, dtype=float)
        j = np.asarray(inertia, dtype=float)
        m = np.asarray(load, dtype=float)
        if q.ndim != 1 or q.size < 4 or j.shape != q.shape or m.shape != q.shape:
            raise SolveError(f"q, J and M must be one cycle of at least 4 positions of the "
                             f"same shape (P,); got {q.shape}, {j.shape}, {m.shape}",
                             "pass arrays over the positions")
        if not (np.all(np.isfinite(q)) and np.all(np.diff(q) > 0)):
            raise SolveError("the input must advance at every position of the cycle",
                             "make the input's argument increase from position 0 to N")
        if not (np.all(np.isfinite(j)) and np.all(j > 0) and np.all(np.isfinite(m))):
            raise SolveError("J must be positive and J, M finite at every position",
                             "give the moving bodies masses; remove chain breaks")
        self.q, self.inertia, self.load = q, j, m
        self.state = state if state else None
        self.start, self.period = float(q[0]), float(q[-1] - q[0])
        self.breaks = tuple(breaks)
        self.periodic = _returns(j) and periodic is not False and not any(self.breaks)
        self._j = _spline(q, j, self.periodic)
        self._dj = self._j.derivative()
        self._m = _spline(q, m, self.periodic and _returns(m))
        self._a = self._m.antiderivative()
        self._m_periodic = self.periodic and _returns(m)
        self._knots = q.tolist()
        self._pieces_j = self._j.c.T.tolist()
        self._pieces_m = self._m.c.T.tolist()
        self.cycle_work = float(self._a(q[-1]) - self._a(q[0]))
        d = None if d_inertia is None else np.asarray(d_inertia, dtype=float)
        self.d_inertia = d
        self.interpolation = Interpolation(_inertia_error(q, j, self.periodic),
                                           float(np.max(np.abs(self._dj(q) - d)))
                                           if d is not None else math.nan)

    def with_inertia(self, extra: float) -> ReducedMachine:
        """The same machine with a constant inertia added (a flywheel, a rotor), kg·m²."""
        return ReducedMachine(self.q, self.inertia + extra, self.load, self.d_inertia,
                              periodic=self.periodic, state=self.state, breaks=self.breaks)

    def wrap(self, q: ArrayLike) -> tuple[Array, Array]:
        """``(turns, q_in)``: ``q = q_in + turns·L`` with ``q_in`` in the model's range
        (for a periodic machine; else ``turns = 0`` and ``q`` itself)."""
        q = np.asarray(q, dtype=float)
        if not self.periodic:
            return np.zeros_like(q), q
        turns = np.floor((q - self.start) / self.period)
        return turns, q - turns * self.period

    def j(self, q: ArrayLike) -> Array:
        """``J(q)``, kg·m²."""
        return self._j(self.wrap(q)[1])

    def dj(self, q: ArrayLike) -> Array:
        """``J'(q)``, kg·m²/rad: the derivative of the spline :meth:`j`."""
        return self._dj(self.wrap(q)[1])

    def m(self, q: ArrayLike, *, lap: float | None = None) -> Array:
        """``M_q(q)``, N·m.  With ``lap`` (the start angle of the cycle ``q`` is in, rad)
        the cycle's spline is followed past its end without a jump — what the integrator
        needs inside one cycle when the loads' table does not return to its first value."""
        if lap is None or not self.periodic:
            return self._m(self.wrap(q)[1])
        return self._m(np.asarray(q, dtype=float) - (lap - self.start))

    def terms(self, q: float, lap: float) -> tuple[float, float, float]:
        """``(J, J', M_q)`` at one angle ``q`` (rad) of the cycle that starts at ``lap``, as
        :meth:`j`, :meth:`dj` and ``m(q, lap=lap)`` give them, but in plain floats (the
        splines' own cubic pieces by Horner's rule): the integrator's right-hand side
        calls this some ten thousand times a second of simulated machine."""
        x = q - (lap - self.start) if self.periodic else q
        inside = self.start + (x - self.start) % self.period if self.periodic else x
        c3, c2, c1, c0 = self._pieces_j[self._piece(inside)]
        h = inside - self._knots[self._piece(inside)]
        j = ((c3 * h + c2) * h + c1) * h + c0
        dj = (3.0 * c3 * h + 2.0 * c2) * h + c1
        xm = inside if self._m_periodic else x
        k = self._piece(xm)
        c3, c2, c1, c0 = self._pieces_m[k]
        h = xm - self._knots[k]
        return j, dj, ((c3 * h + c2) * h + c1) * h + c0

    def state_moment(self, q: ArrayLike, omega: ArrayLike, t: ArrayLike = 0.0) -> Array:
        """``M_s(q, ω, t)``, N·m: the reduced moment of the loads that depend on the speed
        or time at angles ``q`` (rad, any number of cycles), speeds ``omega`` (rad/s) and
        times ``t`` (s); zero without such loads."""
        q = np.asarray(q, dtype=float)
        if self.state is None:
            return np.zeros(np.broadcast(q, np.asarray(omega)).shape)
        return self.state.moment(self.wrap(q)[1], omega, t)

    def _piece(self, x: float) -> int:
        """The spline piece that holds ``x`` (the end pieces beyond the knots)."""
        return min(max(bisect_right(self._knots, x) - 1, 0), len(self._knots) - 2)

    def work(self, q: ArrayLike) -> Array:
        """``A(q) = ∫_{q[0]}^{q} M_q dq``, J (the exact integral of the spline, over any
        number of cycles)."""
        turns, inside = self.wrap(q)
        return turns * self.cycle_work + self._a(inside) - self._a(self.start)


def _returns(y: Array) -> bool:
    return bool(abs(y[-1] - y[0]) <= PERIODIC_RTOL * max(float(np.abs(y).max()), 1e-300))


def _spline(q: Array, y: Array, periodic: bool) -> CubicSpline:
    if periodic:
        return CubicSpline(q, np.append(y[:-1], y[0]), bc_type="periodic")
    return CubicSpline(q, y)


def _inertia_error(q: Array, j: Array, periodic: bool) -> float:
    """A sixteenth of the largest miss, at the odd positions, of the spline through the
    even ones (fourth order: halving the step divides the error by 16)."""
    even = slice(0, None, 2)
    if q.size < 9 or (periodic and (q.size - 1) % 2):
        return math.nan
    coarse = _spline(q[even], j[even], periodic)
    return float(np.max(np.abs(coarse(q[1::2]) - j[1::2]))) / 16.0
