"""Reduced (equivalent) characteristics and the balancing load by virtual power.

With ``v'`` and ``ω'`` the first analogs (velocities per unit rate of an argument) and
``v''``, ``ω''`` the second ones, for a one-input machine reduced to its input ``q``:

* ``J_red = Σ (m |v'_S|² + J_S ω'²)`` (kg·m², or kg for a sliding input) and
  ``dJ_red/dq = 2 Σ (m v'_S·v''_S + J_S ω' ω'')``;
* ``M_red = Σ F·v'_P + Σ M ω'`` — the reduced moment (force) of the external loads and
  gravity;

and for any number of inputs the balancing load of input ``k`` follows from the power
balance with the true accelerations ``a_S``, ``ε``, and the partial analogs of input k:
``Q_k = Σ (m a_S·v'_S + J_S ε ω') − Σ F·v'_P − Σ M ω'`` — independent of the reactions.
For one input this equals ``J_red q̈ + ½ dJ_red/dq q̇² − M_red``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from mechloop.dynamics.loads import Loads
from mechloop.dynamics.mechanism import Mechanism
from mechloop.dynamics.points import Placement

Array = NDArray[np.float64]


def _dot(z, w) -> Array:
    return (np.conj(z) * w).real


@dataclass(frozen=True)
class Reduced:
    """Reduced characteristics for one input, shape (P,): ``inertia`` (kg·m² or kg),
    ``d_inertia`` (per rad or per m of the input), ``load`` (N·m or N)."""

    inertia: Array
    d_inertia: Array
    load: Array


def reduced(mechanism: Mechanism, analogs: Placement, loads_at: Loads) -> Reduced:
    """Reduced inertia, its derivative and the reduced load, from a placement whose
    results are analogs with respect to the input (``solve(model, analogs_of=k)``).
    ``loads_at`` are the loads with their points taken from the same placement."""
    res = analogs.results
    n = res.broken.size
    inertia, d_inertia, load = np.zeros(n), np.zeros(n), np.zeros(n)
    for mass in mechanism.masses:
        s = analogs.point(mass.center)
        omega = res.rate(f"a{mechanism.bodies[mass.body].angle_vector}")
        eps = res.accel(f"a{mechanism.bodies[mass.body].angle_vector}")
        inertia += mass.mass * np.abs(s.v) ** 2 + mass.inertia * omega**2
        d_inertia += 2.0 * (mass.mass * _dot(s.v, s.a) + mass.inertia * omega * eps)
    for force in loads_at.forces:
        load += _dot(force.force, force.point.v)
    for couple in loads_at.moments:
        load += couple.moment * res.rate(f"a{mechanism.bodies[couple.body].angle_vector}")
    return Reduced(inertia, d_inertia, load)


def balancing_by_virtual_power(mechanism: Mechanism, motion: Placement, analogs: Placement,
                               loads_at: Loads, *, static: bool = False) -> Array:
    """The balancing load of the input whose analogs ``analogs`` holds (N·m or N), from
    the true accelerations in ``motion`` and the loads (points from ``analogs``)."""
    res, ana = motion.results, analogs.results
    n = res.broken.size
    total = np.zeros(n)
    if not static:
        for mass in mechanism.masses:
            name = f"a{mechanism.bodies[mass.body].angle_vector}"
            s_true = motion.point(mass.center)
            s_ana = analogs.point(mass.center)
            total += mass.mass * _dot(s_true.a, s_ana.v)
            total += mass.inertia * res.accel(name) * ana.rate(name)
    for force in loads_at.forces:
        total -= _dot(force.force, force.point.v)
    for couple in loads_at.moments:
        total -= couple.moment * ana.rate(f"a{mechanism.bodies[couple.body].angle_vector}")
    return total
