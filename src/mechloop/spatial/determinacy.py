"""What the rank of a spatial model's force system says (:mod:`mechloop.spatial.reactions`).

* **Statically indeterminate** (rank below the number of unknowns): the null vectors of
  the system at a generic position name the joints whose reactions can balance each
  other whatever the loads; a greedy search finds changes of joint type (revolute →
  spherical or cylindrical, prismatic → cylindrical: fewer components) that keep the
  rank and remove the excess, a joint between two moving bodies before one with the
  ground.
* **Idle motions** (rank below the number of equations): each left null vector is a
  motion of the bodies that no joint or drive resists (``(v_O, ω)`` per body once the
  rows' scaling is undone); its equation is dropped when the loads and inertia balance
  in it, and otherwise the problem names the body, the axis it turns about (or the
  direction it slides along), the joints on that axis and the unbalanced moment of its
  inertia and of its loads.

All arrays are the scaled system of :func:`~mechloop.spatial.reactions.solve_reactions`:
``(6B, K)`` at one position, or ``(P, 6B, K)``.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from mechloop.errors import ModelError, Problem
from mechloop.spatial.joints import Joint3

Array = NDArray[np.float64]

#: A singular value below this share of the largest is zero (decides the rank).
RANK_RTOL = 1e-9
#: The equations dropped as identically satisfied must hold to this share of the scale.
RESIDUAL_RTOL = 1e-8


def _rank(a: Array) -> int:
    s = np.linalg.svd(a, compute_uv=False)
    return int((s > RANK_RTOL * s[0]).sum()) if s.size and s[0] > 0 else 0


_RELAX = (("revolute", "spherical", ("moment", None)),
          ("revolute", "cylindrical", ("force", "axial")),
          ("prismatic", "cylindrical", ("moment", "axial")))


def relaxations(a: Array, columns: list, joints: dict[str, Joint3], rank: int,
                 involved: list[str]) -> list[tuple[str, str, str]]:
    """Changes of joint type (fewer components) that make the system at one position
    determinate, found greedily: each keeps the rank and lowers the excess most (a joint
    between two moving bodies before one with the ground)."""
    keep = np.ones(len(columns), bool)
    changes: list[tuple[str, str, str]] = []
    changed: set[str] = set()
    while keep.sum() > rank:
        best = None
        for name in involved:
            if name in changed:
                continue
            for old, new, (part, role) in _RELAX:
                if joints[name].kind != old:
                    continue
                drop = np.array([c.owner == name and c.part == part
                                 and (role is None or c.role == role) for c in columns])
                trial = keep & ~drop
                if _rank(a[:, trial]) < rank:
                    continue
                key = (int(trial.sum()) - rank, 0 in joints[name].bodies)  # moving first
                if best is None or key < best[0]:
                    best = (key, name, old, new, trial)
        if best is None:
            break
        _, name, old, new, keep = best
        changes.append((name, old, new))
        changed.add(name)
    return changes if keep.sum() == rank else []


def indeterminate(a: Array, columns: list, joints: dict[str, Joint3],
                   rank: int) -> Problem:
    """The problem of a statically indeterminate system ``a`` (one position, scaled)."""
    _, _, vt = np.linalg.svd(a)
    null = vt[rank:]
    weight = np.abs(null).max(axis=0)
    involved = list(dict.fromkeys(c.owner for c, w in zip(columns, weight, strict=True)
                                  if w > 1e-6 and isinstance(c.owner, str)))
    changes = relaxations(a, columns, joints, rank, involved)
    excess = len(columns) - rank
    message = (f"the force analysis is statically indeterminate: {excess} reaction "
               f"component(s) more than the equations of the bodies decide (joints "
               f"{', '.join(involved)} can hold reactions that balance each other "
               "whatever the loads)")
    if changes:
        types = ", ".join(f"{name} {old} → {new}" for name, old, new in changes)
        hint = f"make it determinate with these joint types: {types}"
        path = ("joints", changes[0][0], "type")
    else:
        hint = (f"free some of the components of joints {', '.join(involved)} (a "
                "spherical or cylindrical joint in place of a revolute one)")
        path = ("joints",)
    return Problem(path, message, hint)


def _describe_idle(t: Array, rows: dict[int, int], refs: dict[int, Array],
                   joints: list[Joint3], points: dict[str, Array], p: int
                   ) -> tuple[int, bool, str, str, float]:
    """An idle motion ``t`` (``(6B,)``, every body's ``(v_O, ω)`` at position ``p``): the
    body that moves most, whether it turns (else it slides), the direction of its axis,
    the joints on that axis, and the scale that makes its ω (or v) unit."""
    size = {b: float(np.linalg.norm(t[6 * i:6 * i + 6])) for b, i in rows.items()}
    body = max(size, key=size.get)
    i = 6 * rows[body]
    v, w = t[i:i + 3], t[i + 3:i + 6]
    turn = float(np.linalg.norm(w))
    if turn <= 1e-9 * max(size[body], 1e-300):
        speed = float(np.linalg.norm(v))
        return body, False, "{:.3g}, {:.3g}, {:.3g}".format(*(v / speed)), "", 1.0 / speed
    axis = w / turn
    foot = refs[body][:, p] + np.cross(w, v) / turn**2  # a point of the turning axis
    on = [j.name for j in joints if body in j.bodies and np.linalg.norm(
        np.cross(points[j.name][:, p] - foot, axis)) <= 1e-6 * (1.0 + np.abs(foot).max())]
    return body, True, "{:.3g}, {:.3g}, {:.3g}".format(*axis), ", ".join(on), 1.0 / turn


def idle_motions(sa: Array, sb: Array, loads: Array, residual: Array,
                 solved: NDArray[np.bool_], rank: int, rows, refs, joints, points,
                 generic: int, size: float) -> tuple[str, ...]:
    """Descriptions of the idle motions (the left null space of the scaled system ``sa``
    at position ``generic``); a problem when the loads and inertia do not balance in
    them (``residual`` above :data:`RESIDUAL_RTOL` at a position ``solved``), with the
    share of the loads (``loads``: their part of ``−sb``) and of the inertia."""
    unscale = np.ones(sa.shape[1])
    unscale.reshape(-1, 6)[:, 3:] = 1.0 / size  # a left null vector → (v_O, ω) per body

    def null(p: int) -> Array:
        return np.linalg.svd(sa[p])[0][:, rank:]

    out = []
    for y in null(generic).T:
        body, turn, axis, on, _ = _describe_idle(unscale * y, rows, refs, joints, points,
                                                 generic)
        out.append(f"body {body}: {'turn about' if turn else 'slide along'} ({axis}) at "
                   f"position {generic}" + (f" (the line of joints {on})" if on else ""))
    bad = solved & (residual > RESIDUAL_RTOL)
    if bad.any():
        positions = np.flatnonzero(bad)
        p = int(positions[np.argmax(residual[bad])])
        u = null(p)
        y = u @ (u.T @ sb[p])  # the part of the equations nothing balances at p
        y /= np.linalg.norm(y)
        body, turn, axis, on, unit = _describe_idle(unscale * y, rows, refs, joints,
                                                    points, p)
        sign = 1.0 if y @ sb[p] >= 0 else -1.0
        by_loads = -sign * float(y @ loads[p]) * unit
        by_inertia = sign * float(y @ sb[p]) * unit - by_loads
        total = abs(by_loads) + abs(by_inertia)
        by_loads, by_inertia = (0.0 if abs(x) <= 1e-9 * total else x
                                for x in (by_loads, by_inertia))
        count = positions.size
        if turn and on:
            message = (f"body {body} can turn about the axis ({axis}) at position {p} "
                       f"through joints {on} with no joint holding it, but its inertia and "
                       "loads do not balance in that motion: a moment of "
                       f"{by_inertia:.3g} N·m from its inertia and {by_loads:.3g} N·m from "
                       f"the loads (at {count} position(s))")
        elif turn:
            message = (f"body {body} can turn about the axis ({axis}) at position {p} with "
                       "no joint holding it, but its inertia and loads do not balance in "
                       f"that motion: a moment of {by_inertia:.3g} N·m from its inertia and "
                       f"{by_loads:.3g} N·m from the loads (at {count} position(s))")
        else:
            message = (f"body {body} can slide along ({axis}) at position {p} with no joint "
                       "holding it, but its inertia and loads do not balance in that "
                       f"motion: a force of {by_inertia:.3g} N from its inertia and "
                       f"{by_loads:.3g} N from the loads (at {count} position(s))")
        raise ModelError([Problem(
            ("bodies", body), message,
            f"make body {body}'s inertia tensor symmetric about that axis with no load "
            "turning it about the axis (inertia: rod, or [J_axis, J, J]), or hold the "
            "motion with a joint (revolute instead of spherical)")])
    return tuple(out)
