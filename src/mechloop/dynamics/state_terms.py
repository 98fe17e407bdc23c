"""The reduced moment of the loads that depend on the speed, for the motion in time.

A one-input machine turning at ``ω`` (rad/s) at angle ``q`` moves every point at its
analog velocity ``v'(q)`` times ``ω``.  A load that depends on the rates is re-evaluated at
that state and reduced with the analogs (:class:`~mechloop.dynamics.loads.Dependence`):

* a damper's load ``law(v)·unit``, ``v = s'(q)·ω`` its relative speed (``s'`` the analog
  of the relative speed), reduces to ``law(s'(q)·ω)·λ(q)`` with the lever
  ``λ = unit·v'_P`` (a moment: ``unit·ω'_body``) — for a linear damper
  ``−c·s'(q)²·ω``;
* a load with ``when`` reduces to ``G(q)`` (the reduced moment of the load as if it always
  acted) where ``sign·x'(q)·ω > 0``, ``x'`` the analog of the deciding parameter's rate,
  and to zero elsewhere;
* a load given as an expression of rates or time reduces to ``scale·f(state)·λ(q)``,
  the expression evaluated with the parameters at ``q``, their rates ``x'(q)·ω`` and the
  simulation's time ``t``.

Springs depend on the positions only: they are in ``M_q(q)`` with gravity.

Between the model's positions ``λ``, ``s'``, ``G`` and ``x'`` are read as cubic splines
(periodic when the machine is), one spline for all of them.  Units SI.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray
from scipy.interpolate import CubicSpline

from mechloop.dynamics.elements import RateLaw
from mechloop.dynamics.loads import Loads
from mechloop.dynamics.mechanism import Mechanism
from mechloop.dynamics.points import Placement
from mechloop.model.expression import Expression

Array = NDArray[np.float64]


def _dot(z, w) -> Array:
    return (np.conj(z) * w).real


@dataclass(frozen=True)
class _Term:
    law: RateLaw | None  # a damper (None: a gated load or an expression)
    sign: float  # a gated load's sign
    lever: int  # rows of the stacked samples
    rate: int
    expression: Expression | None = None  # an expression of the rates or time
    scale: float = 1.0
    channels: tuple[tuple[str, int], ...] = ()  # name -> row (a rate's row: its analog)


class StateTerms:
    """``M_s(q, ω)``, N·m: the reduced moment of the rate-dependent loads.

    Parameters
    ----------
    q : array, shape (P,), rad — the input at the model's positions (increasing).
    loads_at : the model's loads built on the analogs of the input
        (``build_loads(..., analogs_placement, state=motion)``).
    mechanism, analogs : the mechanism and the analogs' placement.
    periodic : bool — the machine repeats every cycle.
    keep : index, optional — the model's positions that ``q`` are (a stretch between
        chain breaks, :mod:`mechloop.dynamics.chain_span`); default all.

    ``static`` (shape (P,)) is what these loads contribute to the reduced load at the
    model's own motion (to take out of ``M_q``).
    """

    def __init__(self, q: Array, loads_at: Loads, mechanism: Mechanism,
                 analogs: Placement, *, periodic: bool, keep=slice(None)):
        res = analogs.results
        rows: list[Array] = []
        terms: list[_Term] = []
        static = np.zeros(analogs.results.broken.size)

        def body_rate(body: int) -> Array:
            return res.rate(f"a{mechanism.bodies[body].angle_vector}")

        def add(lever: Array, rate: Array, law: RateLaw | None, sign: float) -> None:
            rows.extend((lever, rate))
            terms.append(_Term(law, sign, len(rows) - 2, len(rows) - 1))

        def add_expression(lever: Array, dep) -> None:
            rows.append(lever)
            at = len(rows) - 1
            channels = []
            for name in sorted(dep.expression.names - {"t"}):
                rows.append(res.rate(name[1:]) if name.startswith("d") else res.value(name))
                channels.append((name, len(rows) - 1))
            terms.append(_Term(None, 0.0, at, at, dep.expression, dep.scale,
                               tuple(channels)))

        for force in loads_at.forces:
            dep = force.depends
            if dep is None:
                continue
            static += _dot(force.force, force.point.v)
            if dep.expression is not None:
                add_expression(_dot(dep.unit, force.point.v), dep)
            elif dep.law is not None:
                add(_dot(dep.unit, force.point.v), dep.speed, dep.law, 0.0)
            else:
                add(_dot(dep.ungated, force.point.v), dep.rate, None, dep.sign)
        for couple in loads_at.moments:
            dep = couple.depends
            if dep is None:
                continue
            w = body_rate(couple.body)
            static += couple.moment * w
            if dep.expression is not None:
                add_expression(dep.unit * w, dep)
            elif dep.law is not None:
                add(dep.unit * w, dep.speed, dep.law, 0.0)
            else:
                add(dep.ungated * w, dep.rate, None, dep.sign)
        self.static = static[keep]
        rows = [row[keep] for row in rows]
        self.terms = tuple(terms)
        self.start, self.period = float(q[0]), float(q[-1] - q[0])
        self.periodic = periodic
        self._spline = None
        if rows:
            y = np.stack(rows, axis=1)
            closed = periodic and np.allclose(y[0], y[-1], rtol=1e-9,
                                              atol=1e-12 * np.abs(y).max(initial=1.0))
            if closed:
                y = np.vstack([y[:-1], y[:1]])
            self._spline = CubicSpline(q, y, bc_type="periodic" if closed else "not-a-knot")

    def __bool__(self) -> bool:
        return bool(self.terms)

    def moment(self, q: Array, omega: Array, time: Array | float = 0.0) -> Array:
        """``M_s`` (N·m) at angles ``q`` inside the model's range (rad), speeds ``omega``
        (rad/s) and times ``time`` (s), arrays of one shape."""
        q = np.asarray(q, dtype=float)
        omega = np.asarray(omega, dtype=float)
        out = np.zeros(np.broadcast(q, omega).shape)
        if self._spline is None:
            return out
        y = self._spline(q)
        for t in self.terms:
            lever, rate = y[..., t.lever], y[..., t.rate]
            if t.expression is not None:
                names = {n: y[..., row] * omega if n.startswith("d") else y[..., row]
                         for n, row in t.channels}
                if "t" in t.expression.names:
                    names["t"] = np.asarray(time, dtype=float)
                out = out + t.scale * t.expression(names) * lever
            elif t.law is not None:
                out = out + t.law(rate * omega) * lever
            else:
                out = out + np.where(t.sign * rate * omega > 0, lever, 0.0)
        return out
