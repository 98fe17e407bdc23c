"""Springs and dampers compiled to forces and moments over positions (SI).

A spring or a damper between two points is a pair of opposite forces along the line from
its first end ``A`` to its second ``B`` (unit vector ``u``): ``+T·u`` on ``A`` and
``−T·u`` on ``B`` for a tension ``T`` (positive: it pulls the ends together).  Their
power is ``−T·l̇``, ``l`` the distance ``|B − A|``, whatever the bodies do.  A spring's
tension is a function of ``l``; a damper's of ``l̇`` (from the state placement: the
motion's true velocities); a damper in a joint is a pair of opposite moments ``∓T`` on
its second and first body, ``T`` a function of the relative angular speed
``ω₂ − ω₁``.

Points come from the ``points`` placement (where the loads act and how they are reduced:
the motion itself, or the analogs of an input), rates from the ``state`` placement (the
motion in time).  Ends on the ground (body 0) carry no load of the model's bodies and are
left out.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from mechloop.dynamics.mechanism import Mechanism, _fixed_in, _size
from mechloop.dynamics.points import Placement
from mechloop.errors import Problem
from mechloop.model.schema import Model
from mechloop.model.units import UnitProblem, unit_factor

Array = NDArray[np.float64]
Complex = NDArray[np.complex128]


@dataclass(frozen=True)
class RateLaw:
    """A damper's tension (N, or N·m in a joint) as an odd function of the relative speed
    (m/s or rad/s): ``coefficient·v`` or a table over ``|v|`` (linear between its points,
    the end slopes beyond), with the sign of ``v``."""

    coefficient: float | None
    speeds: Array | None = None
    tensions: Array | None = None

    def __call__(self, v: Array) -> Array:
        v = np.asarray(v, dtype=float)
        if self.coefficient is not None:
            return self.coefficient * v
        return np.sign(v) * extrapolate(np.abs(v), self.speeds, self.tensions)


def extrapolate(x: Array, xs: Array, ys: Array) -> Array:
    """Piecewise linear through ``(xs, ys)`` (xs increasing), its end slopes beyond."""
    y = np.interp(x, xs, ys)
    lo = ys[0] + (x - xs[0]) * (ys[1] - ys[0]) / (xs[1] - xs[0])
    hi = ys[-1] + (x - xs[-1]) * (ys[-1] - ys[-2]) / (xs[-1] - xs[-2])
    return np.where(x < xs[0], lo, np.where(x > xs[-1], hi, y))


@dataclass(frozen=True)
class ElementLoad:
    """One force (``point`` given, complex ``force``) or moment (``point`` None, real
    ``force``) of a spring or damper on ``body``, shape (P,).  For a damper ``law`` is
    its tension law, ``speed`` the relative speed on the *points* placement (the analog
    of the relative speed when that placement holds analogs) and ``unit`` the load per
    unit tension (``∓u`` or ``∓1``), so that the load is ``law(speed_true)·unit``."""

    name: str
    body: int
    point: object | None
    force: Complex | Array
    law: RateLaw | None = None
    speed: Array | None = None
    unit: Complex | Array | None = None


def element_loads(model: Model, mechanism: Mechanism, points: Placement, state: Placement,
                  *, static: bool, problems: list[Problem], check_ends: bool = True
                  ) -> list[ElementLoad]:
    """Every spring's and damper's loads on the moving bodies (SI), in the order of the
    model file; problems (a body that is not one, a point that does not exist or is not
    fixed in its body, a damper in a model without time) are appended to ``problems``.
    ``check_ends=False`` skips the last check (the positions of a population of designs,
    whose points move from design to design)."""
    out: list[ElementLoad] = []
    scale = _size(model, points) if check_ends and (model.springs or model.dampers) else 0.0
    units = model.units
    try:
        f_force, f_length = (unit_factor(units.force, "force"),
                             unit_factor(units.length, "length"))
        f_moment = unit_factor(units.moment, "moment")
    except UnitProblem:  # reported where the units are read
        return out
    known = {0, *mechanism.bodies}
    for kind, items in (("springs", model.springs), ("dampers", model.dampers)):
        for i, item in enumerate(items):
            path = (kind, i)
            bad = [b for b in item.bodies if b not in known]
            if bad or item.bodies[0] == item.bodies[1]:
                problems.append(Problem((*path, "bodies"), f"bodies {list(item.bodies)} "
                                        "are not two different bodies of the mechanism",
                                        f"use two of {sorted(known)} (0: the ground)"))
                continue
            name = item.name or f"{kind[0].upper()}{i + 1}"
            if kind == "dampers" and static:
                problems.append(Problem(path, "a damper needs the model's time (its "
                                        "force follows the speed)", "add time: {rpm: ...}"))
                continue
            if kind == "dampers" and item.ends is None:
                out += _joint_damper(name, item, mechanism, points, state, f_moment)
                continue
            try:
                a, b = (points.point(end) for end in item.ends)
            except KeyError as exc:
                problems.append(Problem((*path, "ends"), f"vector {exc.args[0]} does not "
                                        "exist", f"use one of {sorted(model.vectors)}"))
                continue
            loose = [j for j, (end, body) in enumerate(zip((a, b), item.bodies, strict=True))
                     if check_ends and not _fixed_in(end, body, mechanism.bodies, points,
                                                     scale)]
            if loose:
                j = loose[0]
                problems.append(Problem((*path, "ends", j), f"this point is not fixed in "
                                        f"body {item.bodies[j]}: it moves relative to it",
                                        "give a point on a vector of that body (or the "
                                        "body that carries the point)"))
                continue
            with np.errstate(invalid="ignore", divide="ignore"):
                d = b.z - a.z
                length = np.abs(d)
                u = d / length
            if kind == "springs":
                tension = _spring_tension(item, length, f_force, f_length)
                law = speed = None
            else:
                sa, sb = (state.point(end) for end in item.ends)
                law = _damper_law(item.coefficient, item.table, f_force / f_length,
                                  f_length, f_force)
                speed = (np.conj(u) * (b.v - a.v)).real
                true_speed = (np.conj(u) * (sb.v - sa.v)).real
                tension = law(true_speed)
            for body, sign, end in ((item.bodies[0], 1.0, a), (item.bodies[1], -1.0, b)):
                if body != 0:
                    out.append(ElementLoad(name, body, end, sign * tension * u, law, speed,
                                           None if law is None else sign * u))
    return out


def _spring_tension(spring, length: Array, f_force: float, f_length: float) -> Array:
    if spring.table is None:
        k = spring.stiffness * f_force / f_length
        return k * (length - spring.free_length * f_length) + spring.preload * f_force
    table = np.asarray(spring.table, dtype=float)
    return extrapolate(length, table[:, 0] * f_length, table[:, 1] * f_force)


def _damper_law(coefficient: float | None, table, f_coefficient: float, f_speed: float,
                f_tension: float) -> RateLaw:
    if coefficient is not None:
        return RateLaw(coefficient * f_coefficient)
    t = np.asarray(table, dtype=float)
    return RateLaw(None, t[:, 0] * f_speed, t[:, 1] * f_tension)


def _omega(mechanism: Mechanism, placement: Placement, body: int) -> Array:
    if body == 0:
        return np.zeros(placement.results.broken.size)
    return placement.results.rate(f"a{mechanism.bodies[body].angle_vector}")


def _joint_damper(name: str, damper, mechanism: Mechanism, points: Placement,
                  state: Placement, f_moment: float) -> list[ElementLoad]:
    """The moments of a damper in the joint of ``damper.bodies`` (per rad/s)."""
    law = _damper_law(damper.coefficient, damper.table, f_moment, 1.0, f_moment)
    first, second = damper.bodies
    speed = _omega(mechanism, points, second) - _omega(mechanism, points, first)
    tension = law(_omega(mechanism, state, second) - _omega(mechanism, state, first))
    n = speed.size
    return [ElementLoad(name, body, None, sign * tension, law, speed, np.full(n, sign))
            for body, sign in ((first, 1.0), (second, -1.0)) if body != 0]


